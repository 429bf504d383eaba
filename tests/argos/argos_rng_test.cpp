// ARGoS's random numbers: a CRNG seeded with S draws what ARGoS 3 (421bd763, Release,
// double) drew for S, and a category seeds its generators as ARGoS's does. The values are
// ../shared/argos-controllers.md's section N, measured in ARGoS.
#include <argos3/core/utility/math/rng.h>
#include <gtest/gtest.h>

#include <vector>

using argos::CRandom;
using argos::CRange;
using argos::Real;
using argos::UInt32;

namespace {
std::vector<Real> Reals(UInt32 seed, int n) {
  CRandom::CRNG rng(seed);
  std::vector<Real> out;
  for (int i = 0; i < n; ++i) out.push_back(rng.Uniform(CRange<Real>(0, 1)));
  return out;
}
std::vector<UInt32> Ints(UInt32 seed, int n) {
  CRandom::CRNG rng(seed);
  std::vector<UInt32> out;
  for (int i = 0; i < n; ++i) out.push_back(rng.Uniform(CRange<UInt32>(0, 100)));
  return out;
}
std::vector<Real> Gaussians(UInt32 seed, int n) {
  CRandom::CRNG rng(seed);
  std::vector<Real> out;
  for (int i = 0; i < n; ++i) out.push_back(rng.Gaussian(1, 0));
  return out;
}
std::vector<bool> Coins(UInt32 seed, int n) {
  CRandom::CRNG rng(seed);
  std::vector<bool> out;
  for (int i = 0; i < n; ++i) out.push_back(rng.Bernoulli(0.5));
  return out;
}
}  // namespace

TEST(ArgosRng, ASeededGeneratorDrawsArgossNumbers) {
  EXPECT_EQ(Reals(1, 3), (std::vector<Real>{0.41702199853421701, 0.99718480836534518, 0.72032448945574568}));
  EXPECT_EQ(Ints(1, 5), (std::vector<UInt32>{41, 99, 72, 93, 0}));
  EXPECT_EQ(Gaussians(1, 3), (std::vector<Real>{0.15606557998386178, -0.56803984157659371, -0.80628862809731305}));
  EXPECT_EQ(Coins(1, 8), (std::vector<bool>{1, 0, 0, 0, 1, 1, 1, 0}));
  EXPECT_EQ(Reals(12345, 3), (std::vector<Real>{0.92961608686708286, 0.89015471327355011, 0.31637556043369125}));
  EXPECT_EQ(Ints(12345, 5), (std::vector<UInt32>{92, 89, 31, 13, 18}));
  EXPECT_EQ(Gaussians(12345, 3), (std::vector<Real>{-0.39074051512556168, -0.4786476211743641, 2.4901223090216602}));
  EXPECT_EQ(Coins(12345, 8), (std::vector<bool>{0, 0, 1, 1, 1, 1, 1, 0}));
}

TEST(ArgosRng, ResetSetSeedAndCopyReplayTheSeed) {
  CRandom::CRNG rng(1);
  const Real first = rng.Uniform(CRange<Real>(0, 1));
  CRandom::CRNG copy(rng);
  EXPECT_EQ(copy.Uniform(CRange<Real>(0, 1)), rng.Uniform(CRange<Real>(0, 1)));
  rng.Reset();
  EXPECT_EQ(rng.Uniform(CRange<Real>(0, 1)), first);
  rng.SetSeed(12345);
  EXPECT_EQ(rng.Uniform(CRange<Real>(0, 1)), 0.92961608686708286);
  EXPECT_EQ(rng.GetSeed(), 12345u);
}

// A category's n-th generator is seeded with the n-th draw of the category's own seeder.
TEST(ArgosRng, ACategorySeedsItsGeneratorsAsArgosDoes) {
  ASSERT_TRUE(CRandom::CreateCategory("section_n", 7));
  EXPECT_FALSE(CRandom::CreateCategory("section_n", 8));  // exists: unchanged, as ARGoS
  EXPECT_TRUE(CRandom::ExistsCategory("section_n"));
  EXPECT_EQ(CRandom::GetSeedOf("section_n"), 7u);
  CRandom::CRNG* first = CRandom::CreateRNG("section_n");
  CRandom::CRNG* second = CRandom::CreateRNG("section_n");
  EXPECT_EQ(first->GetSeed(), 327741615u);
  EXPECT_EQ(second->GetSeed(), 976413892u);
  EXPECT_EQ(first->Uniform(CRange<Real>(0, 1)), 0.055749468285532081);
  EXPECT_EQ(second->Uniform(CRange<Real>(0, 1)), 0.98873681714496031);
  CRandom::RemoveCategory("section_n");
  EXPECT_FALSE(CRandom::ExistsCategory("section_n"));
  EXPECT_THROW(CRandom::CreateRNG("section_n"), argos::CARGoSException);
}

// "argos" is a category as any other: an experiment makes it with its seed; outside one it
// is made as the others are, and seeds its generators as ARGoS's does.
TEST(ArgosRng, TheArgosCategorySeedsAsArgossDoes) {
  EXPECT_FALSE(CRandom::ExistsCategory("argos"));  // outside an experiment
  ASSERT_TRUE(CRandom::CreateCategory("argos", 7));
  EXPECT_EQ(CRandom::CreateRNG("argos")->GetSeed(), 327741615u);
  EXPECT_EQ(CRandom::CreateRNG("argos")->GetSeed(), 976413892u);
  CRandom::RemoveCategory("argos");
}
