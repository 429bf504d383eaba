// ARGoS's random numbers (argos3/core/utility/math/rng.h): ARGoS's Mersenne Twister and
// distributions, so a CRNG of seed S draws what ARGoS's does. CRandom::CreateRNG("argos")
// seeds each generator with the next draw of the category "argos", itself seeded with the
// experiment's random_seed, as ARGoS does (docs/compatibility.md).
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/math/angles.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/vector2.h>

#include <string>

namespace argos {

class CRandom {
 public:
  class CRNG {
   public:
    /// A generator seeded as ARGoS seeds one: it draws exactly ARGoS's numbers for `un_seed`.
    explicit CRNG(UInt32 un_seed);
    CRNG(const CRNG& c_rng);
    CRNG& operator=(const CRNG&) = delete;
    ~CRNG();
    /// Back to the first draw of its seed.
    void Reset();
    void SetSeed(UInt32 un_seed);
    UInt64 GetSeed() const;
    bool Bernoulli(Real f_true = 0.5);
    CRadians Uniform(const CRange<CRadians>& c_range);
    Real Uniform(const CRange<Real>& c_range);
    /// In [min, max).
    SInt32 Uniform(const CRange<SInt32>& c_range);
    UInt32 Uniform(const CRange<UInt32>& c_range);
    UInt32 Uniform32bit();
    Real Exponential(Real f_mean);
    Real Gaussian(Real f_std_dev, Real f_mean = 0);
    UInt32 Poisson(Real f_mean);
    Real Rayleigh(Real f_sigma);
    Real Lognormal(Real f_sigma, Real f_mu);
    /// The generator's type (a GSL name in ARGoS until 3.0.0-beta42): essaim's is a Mersenne Twister.
    std::string GetType() const { return "mt19937"; }
    struct SStream;  // essaim's: the stream and how it was seeded

   private:
    friend class CRandom;
    explicit CRNG(SStream* ps_stream) : m_psStream(ps_stream) {}
    SStream* m_psStream;
  };

  /// A new generator of `str_category`, seeded as ARGoS does: with the next draw of the
  /// category's own seeder. "argos" exists in every experiment, seeded with its random_seed;
  /// others are made by CreateCategory. Made in a robot's ControlStep (robots step on several
  /// threads), it takes the next draw of that robot's own seeder for the category instead,
  /// so the numbers do not depend on the threads. The experiment owns what this returns.
  static CRNG* CreateRNG(const std::string& str_category);
  /// ARGoS's until 3.0.0-beta42, which let a GSL generator type be chosen; essaim has the
  /// Mersenne Twister, ARGoS's default, alone.
  static CRNG* CreateRNG(const std::string& str_category, const std::string& str_type) {
    if (str_type != "mt19937")
      THROW_ARGOSEXCEPTION("CRandom::CreateRNG: no generator type \"" << str_type
                                                                      << "\" (essaim has \"mt19937\" only)");
    return CreateRNG(str_category);
  }
  /// Makes category `str_category` seeded with `un_seed`; false when it exists already
  /// (in an experiment "argos" does). Categories belong to the running experiment (outside
  /// any, to the process).
  static bool CreateCategory(const std::string& str_category, UInt32 un_seed);
  static bool ExistsCategory(const std::string& str_category);
  static void RemoveCategory(const std::string& str_category);
  static UInt32 GetSeedOf(const std::string& str_category);
  static void SetSeedOf(const std::string& str_category, UInt32 un_seed);
};

}  // namespace argos
