// ARGoS's random numbers (argos3/core/utility/math/rng.h). CRandom::CreateRNG("argos")
// gives a generator drawn from the experiment's random_seed: the first one made draws the
// stream the Lua loop functions' experiment.random draws, so a C++ port of Lua loop
// functions draws the same numbers (docs/loop-functions.md).
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
    ~CRNG();
    CRNG(const CRNG&) = delete;
    CRNG& operator=(const CRNG&) = delete;
    bool Bernoulli(Real f_true = 0.5);
    CRadians Uniform(const CRange<CRadians>& c_range);
    Real Uniform(const CRange<Real>& c_range);
    /// In [min, max).
    SInt32 Uniform(const CRange<SInt32>& c_range);
    UInt32 Uniform(const CRange<UInt32>& c_range);
    Real Exponential(Real f_mean);
    Real Gaussian(Real f_std_dev, Real f_mean = 0);
    UInt32 Poisson(Real f_mean);
    UInt64 GetSeed() const;
    /// The generator's type (a GSL name in ARGoS until 3.0.0-beta42): essaim's is a Mersenne Twister.
    std::string GetType() const { return "mt19937"; }

   private:
    friend class CRandom;
    explicit CRNG(UInt64 un_seed);
    struct SStream;
    SStream* m_psStream;
  };

  /// A new generator of `str_category` ("argos": seeded from the experiment's seed). The
  /// experiment owns it: it is freed when the run ends.
  static CRNG* CreateRNG(const std::string& str_category);
  /// ARGoS's until 3.0.0-beta42, which let a GSL generator type be chosen; essaim has the
  /// Mersenne Twister, ARGoS's default, alone.
  static CRNG* CreateRNG(const std::string& str_category, const std::string& str_type) {
    if (str_type != "mt19937")
      THROW_ARGOSEXCEPTION("CRandom::CreateRNG: no generator type \"" << str_type
                                                                      << "\" (essaim has \"mt19937\" only)");
    return CreateRNG(str_category);
  }
  static bool ExistsCategory(const std::string& str_category);
};

}  // namespace argos
