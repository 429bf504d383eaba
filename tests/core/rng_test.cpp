// robot.random's distributions: ranges and moments of every call.
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace essaim {
namespace {

struct Moments {
  double mean = 0, var = 0, min = 1e300, max = -1e300;
};
template <class F>
Moments Sample(F f, int n = 200000) {
  std::vector<double> xs(n);
  Moments m;
  for (double& x : xs) {
    x = f();
    m.mean += x;
    m.min = std::min(m.min, x);
    m.max = std::max(m.max, x);
  }
  m.mean /= n;
  for (double x : xs) m.var += (x - m.mean) * (x - m.mean);
  m.var /= n - 1;
  return m;
}

TEST(Rng, Uniform01RangeAndMoments) {
  Rng r(42);
  Moments m = Sample([&] { return r.Uniform01(); });
  EXPECT_GE(m.min, 0.0);
  EXPECT_LE(m.max, 1.0);
  EXPECT_NEAR(m.mean, 0.5, 0.005);
  EXPECT_NEAR(m.var, 1.0 / 12, 0.002);
}

TEST(Rng, UniformMinMax) {
  Rng r(1);
  Moments m = Sample([&] { return r.Uniform(-3, 5); });
  EXPECT_GE(m.min, -3.0);
  EXPECT_LE(m.max, 5.0);
  EXPECT_NEAR(m.mean, 1.0, 0.03);
  EXPECT_NEAR(m.var, 64.0 / 12, 0.1);
}

TEST(Rng, UniformIntIsHalfOpenForNonNegativeRanges) {
  Rng r(7);
  std::vector<int> counts(6, 0);
  for (int i = 0; i < 60000; ++i) {
    int64_t v = r.UniformInt(2, 6);  // {2,3,4,5} (6 only with prob 2^-32)
    ASSERT_GE(v, 2);
    ASSERT_LE(v, 5);
    ++counts[v];
  }
  for (int v = 2; v <= 5; ++v) EXPECT_NEAR(counts[v], 15000, 500);
}

TEST(Rng, UniformIntNegativeRangeKeepsArgosBias) {
  // uniform_int(-3, 3): trunc toward zero doubles the weight of 0 (spec quirk 10).
  Rng r(9);
  std::vector<int> counts(7, 0);
  for (int i = 0; i < 60000; ++i) {
    int64_t v = r.UniformInt(-3, 3);
    ASSERT_GE(v, -3);
    ASSERT_LE(v, 2);
    ++counts[v + 3];
  }
  EXPECT_NEAR(counts[3], 2 * counts[5], 600);  // 0 vs 2
}

TEST(Rng, GaussianStdDevFirstThenMean) {
  Rng r(3);
  Moments m = Sample([&] { return r.Gaussian(2.0, 10.0); });
  EXPECT_NEAR(m.mean, 10.0, 0.02);
  EXPECT_NEAR(std::sqrt(m.var), 2.0, 0.02);
}

TEST(Rng, ExponentialMean) {
  Rng r(4);
  Moments m = Sample([&] { return r.Exponential(3.0); });
  EXPECT_GE(m.min, 0.0);
  EXPECT_NEAR(m.mean, 3.0, 0.04);
  EXPECT_NEAR(m.var, 9.0, 0.3);
}

TEST(Rng, PoissonMeanAndVariance) {
  Rng r(5);
  Moments m = Sample([&] { return static_cast<double>(r.Poisson(4.0)); });
  EXPECT_GE(m.min, 0.0);
  EXPECT_NEAR(m.mean, 4.0, 0.03);
  EXPECT_NEAR(m.var, 4.0, 0.1);
}

TEST(Rng, BernoulliFrequency) {
  Rng r(6);
  Moments m = Sample([&] { return r.Bernoulli(0.3) ? 1.0 : 0.0; });
  EXPECT_NEAR(m.mean, 0.3, 0.005);
  Moments half = Sample([&] { return r.Bernoulli() ? 1.0 : 0.0; });
  EXPECT_NEAR(half.mean, 0.5, 0.005);
}

// The state is made at the first draw: the numbers are an eagerly seeded mt19937's, a
// reseed restarts the stream, and a copy continues from where the original stood.
TEST(Rng, LazyStateDrawsWhatAnEagerMt19937Draws) {
  const uint64_t seed = 0x0123456789abcdefull;
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};
  std::mt19937 eager(seq);
  Rng lazy(seed), unseeded;
  std::mt19937 default_seeded;  // 5489
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(lazy.NextU32(), eager());
    EXPECT_EQ(unseeded.NextU32(), default_seeded());
  }
  Rng copy = lazy;
  const Rng fresh_copy = Rng(seed);
  Rng from_fresh = fresh_copy;
  EXPECT_EQ(from_fresh.NextU32(), Rng(seed).NextU32());  // a copy before any draw starts at the start
  for (int i = 0; i < 5; ++i) EXPECT_EQ(copy.NextU32(), lazy.NextU32());
  lazy.Seed(seed);
  EXPECT_EQ(lazy.NextU32(), Rng(seed).NextU32());
}

TEST(Rng, SameSeedSameStreamAndStreamsDiffer) {
  Rng a(DeriveSeed(1, StreamKind::Controller, 0)), b(DeriveSeed(1, StreamKind::Controller, 0));
  Rng c(DeriveSeed(1, StreamKind::Controller, 1)), d(DeriveSeed(1, StreamKind::SensorNoise, 0));
  bool cd_differ = false;
  for (int i = 0; i < 100; ++i) {
    uint32_t x = a.NextU32();
    EXPECT_EQ(x, b.NextU32());
    cd_differ |= c.NextU32() != d.NextU32();
  }
  EXPECT_TRUE(cd_differ);
  EXPECT_NE(DeriveSeed(1, StreamKind::Controller, 0), DeriveSeed(2, StreamKind::Controller, 0));
}

// Rng::Seed computes seed_seq's algorithm itself (faster): the whole state must be the one
// std::seed_seq{lo, hi} gives, or every recording would change. 1300 draws pass through two
// twists of the 624-word state, so every state word is compared.
TEST(Rng, SeedIsStdSeedSeqWordForWord) {
  const uint64_t seeds[] = {0,
                            1,
                            312,
                            0xFFFFFFFFull,
                            0x100000000ull,
                            0x8000000000000000ull,
                            ~0ull,
                            DeriveSeed(312, StreamKind::Controller, 99999),
                            DeriveSeed(7, StreamKind::SensorNoise, 0)};
  for (uint64_t seed : seeds) {
    std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};
    std::mt19937 reference(seq);
    Rng rng(seed);
    for (int i = 0; i < 1300; ++i) ASSERT_EQ(rng.NextU32(), reference()) << "seed " << seed << " draw " << i;
  }
}

// Seeding is deferred to the first draw: a stream seeded twice draws from the last seed,
// and a copy made before any draw draws the same numbers as the original.
TEST(Rng, TheLastSeedBeforeTheFirstDrawCounts) {
  Rng a(1);
  a.Seed(2);
  Rng copy = a;
  Rng b(2);
  for (int i = 0; i < 10; ++i) {
    const uint32_t x = b.NextU32();
    EXPECT_EQ(a.NextU32(), x);
    EXPECT_EQ(copy.NextU32(), x);
  }
  a.Seed(1);  // reseeding after draws starts the stream of 1 afresh
  Rng c(1);
  EXPECT_EQ(a.NextU32(), c.NextU32());
}

}  // namespace
}  // namespace essaim
