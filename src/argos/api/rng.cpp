// CRandom over essaim's random streams (core/rng.h), whose generator and distributions are
// ARGoS's: a CRNG made with a seed is seeded as ARGoS's (init_genrand), so it draws ARGoS's
// numbers. Every category seeds its generators as ARGoS's CCategory does: each takes the next
// draw of the category's seeder. "argos" is made with the session, seeded with the
// experiment's seed, so loop functions and controllers made in ARGoS's order (serially, robots
// in order) draw ARGoS's numbers. A generator made during a robot's ControlStep, which runs
// beside other robots' on other threads, takes the next draw of that robot's own seeder for
// the category instead, seeded from the category's seed and the robot's index: the same
// numbers at any thread count.
#include "core/rng.h"

#include <argos3/core/utility/math/rng.h>

#include <cmath>
#include <limits>

#include "argos/api/session_state.h"

namespace argos {

struct CRandom::CRNG::SStream {
  UInt64 Seed = 0;
  essaim::Rng Stream;
  void Start() { Stream.SeedPlain(static_cast<UInt32>(Seed)); }  // as ARGoS's CRNG(seed)
};

namespace {
CRandom::CRNG::SStream* PlainStream(UInt32 un_seed) {
  auto* stream = new CRandom::CRNG::SStream;
  stream->Seed = un_seed;
  stream->Start();
  return stream;
}
}  // namespace

CRandom::CRNG::CRNG(UInt32 un_seed) : m_psStream(PlainStream(un_seed)) {}
CRandom::CRNG::CRNG(const CRNG& c_rng) : m_psStream(new SStream(*c_rng.m_psStream)) {}
CRandom::CRNG::~CRNG() { delete m_psStream; }
void CRandom::CRNG::Reset() { m_psStream->Start(); }
void CRandom::CRNG::SetSeed(UInt32 un_seed) {
  m_psStream->Seed = un_seed;
  m_psStream->Start();
}
UInt64 CRandom::CRNG::GetSeed() const { return m_psStream->Seed; }
bool CRandom::CRNG::Bernoulli(Real f_true) { return m_psStream->Stream.Bernoulli(f_true); }
UInt32 CRandom::CRNG::Uniform32bit() { return m_psStream->Stream.NextU32(); }

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

// ARGoS's: a uniform draw in (0, 1), both ends excluded, then sigma * sqrt(-2 ln u).
Real CRandom::CRNG::Rayleigh(Real f_sigma) {
  Real fValue;
  do {
    fValue = Uniform(CRange<Real>(0, 1));
  } while (fValue <= 0 || fValue >= 1);
  return f_sigma * std::sqrt(-2 * std::log(fValue));
}

Real CRandom::CRNG::Lognormal(Real f_sigma, Real f_mu) { return std::exp(f_mu + f_sigma * Gaussian(1, 0)); }

}  // namespace argos

namespace essaim {
namespace {
// The running experiment's categories; outside any, the process's.
std::map<std::string, ArgosRngCategory>& Categories() {
  static std::map<std::string, ArgosRngCategory> process;
  ArgosSession::State* session = CurrentSession();
  return session ? session->rng_categories : process;
}

ArgosRngCategory& Category(const std::string& name) {
  auto it = Categories().find(name);
  if (it == Categories().end()) THROW_ARGOSEXCEPTION("CRandom:: can't find category \"" << name << "\".");
  return it->second;
}

// Changing the categories while robots step on several threads would race with their reads.
void RequireSerial(const char* what) {
  const ArgosControllerCall* call = CurrentControllerCall();
  if (call && call->parallel) THROW_ARGOSEXCEPTION(what << ": not from ControlStep (robots step on several threads)");
}

// The seed of robot `robot`'s own seeder for a category of seed `category_seed`.
argos::UInt32 RobotSeederSeed(argos::UInt32 category_seed, uint32_t robot) {
  return static_cast<argos::UInt32>(DeriveSeed(category_seed, StreamKind::Controller, robot));
}

argos::UInt32 NextSeed(argos::CRandom::CRNG& seeder) {
  return seeder.Uniform(argos::CRange<argos::UInt32>(1, std::numeric_limits<argos::UInt32>::max()));
}

}  // namespace
}  // namespace essaim

namespace argos {

CRandom::CRNG* CRandom::CreateRNG(const std::string& str_category) {
  essaim::ArgosRngCategory& category = essaim::Category(str_category);
  const essaim::ArgosControllerCall* call = essaim::CurrentControllerCall();
  if (!call || !call->parallel) {
    category.rngs.emplace_back(new CRNG(essaim::NextSeed(category.seeder)));
    return category.rngs.back().get();
  }
  essaim::ArgosControllerSlot& slot = *call->slot;  // this robot's alone: no other thread touches it
  auto seeder = slot.step_seeders.find(str_category);
  if (seeder == slot.step_seeders.end())
    seeder = slot.step_seeders.emplace(str_category, essaim::RobotSeederSeed(category.seed, slot.robot)).first;
  slot.step_rngs.emplace_back(new CRNG(essaim::NextSeed(seeder->second)));
  return slot.step_rngs.back().get();
}

bool CRandom::CreateCategory(const std::string& str_category, UInt32 un_seed) {
  essaim::RequireSerial("CRandom::CreateCategory");
  if (ExistsCategory(str_category)) return false;
  essaim::Categories().emplace(str_category, un_seed);
  return true;
}

bool CRandom::ExistsCategory(const std::string& str_category) { return essaim::Categories().count(str_category) > 0; }

void CRandom::RemoveCategory(const std::string& str_category) {
  essaim::RequireSerial("CRandom::RemoveCategory");
  essaim::Category(str_category);
  essaim::Categories().erase(str_category);
}

UInt32 CRandom::GetSeedOf(const std::string& str_category) { return essaim::Category(str_category).seed; }

void CRandom::SetSeedOf(const std::string& str_category, UInt32 un_seed) {
  essaim::RequireSerial("CRandom::SetSeedOf");
  essaim::ArgosRngCategory& category = essaim::Category(str_category);
  category.seed = un_seed;
  category.seeder.SetSeed(un_seed);
}

}  // namespace argos
