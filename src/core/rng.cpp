#include "core/rng.h"

#include <cmath>

namespace essaim {

namespace {
uint64_t SplitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// ARGoS's Floor: returns n-1 for negative integral inputs (an ARGoS quirk).
double ArgosFloor(double x) {
  if (x >= 0) return std::floor(x);
  return static_cast<double>(static_cast<int64_t>(x) - 1);
}
}  // namespace

uint64_t DeriveSeed(uint64_t experiment_seed, StreamKind kind, uint64_t index) {
  uint64_t s = experiment_seed;
  SplitMix64(s);
  s ^= static_cast<uint64_t>(kind) * 0xD1B54A32D192ED03ull;
  SplitMix64(s);
  s ^= index * 0x8CB92BA72F3D8DD7ull;
  return SplitMix64(s);
}

void Rng::Start() {
  mt_ = std::make_unique<std::mt19937>();
  if (!seeded_) return;
  std::seed_seq seq{static_cast<uint32_t>(seed_), static_cast<uint32_t>(seed_ >> 32)};
  mt_->seed(seq);
}

Rng& Rng::operator=(const Rng& other) {
  seed_ = other.seed_;
  seeded_ = other.seeded_;
  mt_ = other.mt_ ? std::make_unique<std::mt19937>(*other.mt_) : nullptr;
  return *this;
}

int64_t Rng::UniformInt(double min, double max) {
  double a = ArgosFloor(min), b = ArgosFloor(max);
  return static_cast<int64_t>(Uniform01() * (b - a) + a);
}

double Rng::Gaussian(double std_dev, double mean) {
  double x, y, s;
  do {
    x = Uniform(-1.0, 1.0);
    y = Uniform(-1.0, 1.0);
    s = x * x + y * y;
  } while (s >= 1.0 || s == 0.0);
  return mean + std_dev * x * std::sqrt(-2.0 * std::log(s) / s);
}

double Rng::Exponential(double mean) { return -std::log(Uniform01()) * mean; }

int64_t Rng::Poisson(double mean) {
  // Devroye's sequential inversion on one uniform draw.
  double u = Uniform01();
  int64_t x = 0;
  double p = std::exp(-mean), s = p;
  while (u > s) {
    ++x;
    p *= mean / static_cast<double>(x);
    s += p;
    if (p == 0.0) break;
  }
  return x;
}

bool Rng::Bernoulli(double p) { return NextU32() < p * 4294967295.0; }

}  // namespace essaim
