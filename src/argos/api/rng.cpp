// CRandom over essaim's random streams (core/rng.h): the n-th generator a session makes
// draws stream (LoopFunctions, n) of the experiment's seed, skipping stream 1 (the Lua
// loop functions' math.random), so the first is experiment.random's.
#include "core/rng.h"

#include <argos3/core/utility/math/rng.h>

#include "argos/api/session_state.h"

namespace argos {

struct CRandom::CRNG::SStream {
  explicit SStream(UInt64 un_seed) : Seed(un_seed), Stream(un_seed) {}
  UInt64 Seed;
  essaim::Rng Stream;
};

CRandom::CRNG::CRNG(UInt64 un_seed) : m_psStream(new SStream(un_seed)) {}
CRandom::CRNG::~CRNG() { delete m_psStream; }
UInt64 CRandom::CRNG::GetSeed() const { return m_psStream->Seed; }
bool CRandom::CRNG::Bernoulli(Real f_true) { return m_psStream->Stream.Bernoulli(f_true); }

CRadians CRandom::CRNG::Uniform(const CRange<CRadians>& c_range) {
  return CRadians(m_psStream->Stream.Uniform(c_range.GetMin().GetValue(), c_range.GetMax().GetValue()));
}

Real CRandom::CRNG::Uniform(const CRange<Real>& c_range) {
  return m_psStream->Stream.Uniform(c_range.GetMin(), c_range.GetMax());
}

namespace {
// An integer in [min, max): the draw can reach max (u = 1), which is kept out.
template <typename T>
T UniformInteger(essaim::Rng& stream, const CRange<T>& c_range) {
  if (c_range.GetMax() <= c_range.GetMin()) return c_range.GetMin();
  const int64_t drawn = stream.UniformInt(static_cast<double>(c_range.GetMin()), static_cast<double>(c_range.GetMax()));
  return static_cast<T>(drawn < static_cast<int64_t>(c_range.GetMax()) ? drawn : c_range.GetMax() - 1);
}
}  // namespace

SInt32 CRandom::CRNG::Uniform(const CRange<SInt32>& c_range) { return UniformInteger(m_psStream->Stream, c_range); }
UInt32 CRandom::CRNG::Uniform(const CRange<UInt32>& c_range) { return UniformInteger(m_psStream->Stream, c_range); }
Real CRandom::CRNG::Exponential(Real f_mean) { return m_psStream->Stream.Exponential(f_mean); }
Real CRandom::CRNG::Gaussian(Real f_std_dev, Real f_mean) { return m_psStream->Stream.Gaussian(f_std_dev, f_mean); }
UInt32 CRandom::CRNG::Poisson(Real f_mean) { return static_cast<UInt32>(m_psStream->Stream.Poisson(f_mean)); }

bool CRandom::ExistsCategory(const std::string& str_category) { return str_category == "argos"; }

CRandom::CRNG* CRandom::CreateRNG(const std::string& str_category) {
  essaim::ArgosSession::State& session = essaim::RequireSession("CRandom::CreateRNG");
  if (!ExistsCategory(str_category))
    THROW_ARGOSEXCEPTION("CRandom::CreateRNG: no category \"" << str_category << "\" (essaim has \"argos\" only)");
  const size_t made = session.rngs.size();
  const UInt64 index = made == 0 ? 0 : made + 1;
  session.rngs.emplace_back(
      new CRNG(essaim::DeriveSeed(session.world->Seed(), essaim::StreamKind::LoopFunctions, index)));
  return session.rngs.back().get();
}

}  // namespace argos
