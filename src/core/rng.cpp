#include "core/rng.h"

#include <cmath>
#include <cstddef>

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

namespace {
// mt19937 seeded from std::seed_seq{lo, hi}: the standard fixes seed_seq's generate()
// ([rand.util.seedseq]), so this is the same state word for word, written for exactly two
// input words into 624 outputs: indices wrap by one subtraction instead of libstdc++'s four
// divisions per element, and nothing goes to the heap. Seeding was ~12 µs, 3 per robot.
constexpr size_t kWords = 624;                     // mt19937's state: n
constexpr size_t kT = 11, kP = (kWords - kT) / 2;  // t for n >= 623, p = (n - t) / 2
constexpr size_t kQ = kP + kT;                     // q = p + t
inline size_t Wrap(size_t i) { return i >= kWords ? i - kWords : i; }
inline uint32_t Mix(uint32_t x) { return x ^ (x >> 27); }

struct TwoWordSeedSeq {
  using result_type = uint32_t;  // what the engine's seed(q) checks a seed sequence by
  uint32_t v[2];
  // What mt19937::seed(q) calls: fills [begin, end) (624 words) as seed_seq::generate does.
  template <typename It>
  void generate(It begin, It end) const {
    // mt19937 asks for exactly its n = 624 words (end - begin).
    (void)end;
    uint32_t a[kWords];
    for (uint32_t& w : a) w = 0x8b8b8b8bu;
    // m = max(s + 1, n) = n steps of the first kind (s = 2 input words).
    for (size_t k = 0; k < kWords; ++k) {
      const size_t kp = Wrap(k + kP), kq = Wrap(k + kQ), km = k == 0 ? kWords - 1 : k - 1;
      const uint32_t r1 = 1664525u * Mix(a[k] ^ a[kp] ^ a[km]);
      const uint32_t r2 = r1 + (k == 0 ? 2u : static_cast<uint32_t>(k) + (k <= 2 ? v[k - 1] : 0u));
      a[kp] += r1;
      a[kq] += r2;
      a[k] = r2;
    }
    // Then n steps of the second kind, k from m = n: k mod n runs 0..n-1 again.
    for (size_t k = 0; k < kWords; ++k) {
      const size_t kp = Wrap(k + kP), kq = Wrap(k + kQ), km = k == 0 ? kWords - 1 : k - 1;
      const uint32_t r3 = 1566083941u * Mix(a[k] + a[kp] + a[km]);
      const uint32_t r4 = r3 - static_cast<uint32_t>(k);
      a[kp] ^= r3;
      a[kq] ^= r4;
      a[k] = r4;
    }
    for (size_t i = 0; i < kWords; ++i) begin[i] = a[i];
  }
};
}  // namespace

void Rng::Start() {
  mt_ = std::make_unique<std::mt19937>();
  if (!seeded_) return;
  if (plain_) return mt_->seed(static_cast<uint32_t>(seed_));
  TwoWordSeedSeq seq{{static_cast<uint32_t>(seed_), static_cast<uint32_t>(seed_ >> 32)}};
  mt_->seed(seq);
}

Rng& Rng::operator=(const Rng& other) {
  seed_ = other.seed_;
  seeded_ = other.seeded_;
  plain_ = other.plain_;
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
