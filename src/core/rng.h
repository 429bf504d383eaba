// Random numbers with ARGoS's distributions, on MT19937 streams.
// The standard fixes mt19937's output sequence; the std:: distributions are not fixed
// across standard libraries, so every transform here is our own (determinism contract).
#pragma once
#include <cstdint>
#include <memory>
#include <random>

namespace essaim {

/// What a stream is used for; part of its seed so streams never alias.
enum class StreamKind : uint32_t {
  Simulator = 1,      // <distribute> placement
  Controller = 2,     // robot.random
  SensorNoise = 3,    // noise of one robot's sensors
  ActuatorNoise = 4,  // noise of one robot's actuators
  LuaMath = 5,        // seed of Lua's own math.random
  LoopFunctions = 6,  // experiment.random
  Medium = 7,         // media decisions not owned by one robot
};

/// Seed of stream (kind, index) of an experiment: a SplitMix64 mix, so a robot's streams
/// depend only on the experiment seed and its index, never on thread count or order.
uint64_t DeriveSeed(uint64_t experiment_seed, StreamKind kind, uint64_t index);

/// An MT19937 stream whose 5 KB state is made at its first draw: most robots never draw
/// from most of their streams (noise-free sensors, no robot.random), and at 100 000 robots
/// three eager states were a quarter of the memory. Seeded then exactly as Seed says, so
/// the numbers drawn are those of an eager stream.
class Rng {
 public:
  Rng() = default;  // mt19937's default seed (5489)
  explicit Rng(uint64_t seed) { Seed(seed); }
  Rng(const Rng& other) { *this = other; }
  Rng& operator=(const Rng& other);
  Rng(Rng&&) noexcept = default;
  Rng& operator=(Rng&&) noexcept = default;
  void Seed(uint64_t seed) {
    seed_ = seed;
    seeded_ = true;
    plain_ = false;
    mt_.reset();
  }
  /// Seeded as ARGoS's CRandom::CRNG(seed) and std::mt19937(seed) are (Matsumoto and
  /// Nishimura's init_genrand): the numbers an ARGoS generator of that seed draws.
  void SeedPlain(uint32_t seed) {
    Seed(seed);
    plain_ = true;
  }

  uint32_t NextU32() { return static_cast<uint32_t>(Engine()()); }
  /// u / (2^32 - 1): both 0 and 1 reachable, as ARGoS.
  double Uniform01() { return NextU32() / 4294967295.0; }
  double Uniform(double min, double max) { return Uniform01() * (max - min) + min; }
  /// ARGoS uniform_int(min, max): trunc(n * (floor(max) - floor(min)) + floor(min)).
  int64_t UniformInt(double min, double max);
  /// Polar Box-Muller, first variate only (ARGoS).
  double Gaussian(double std_dev, double mean = 0.0);
  double Exponential(double mean);
  int64_t Poisson(double mean);
  bool Bernoulli(double p = 0.5);

 private:
  std::mt19937& Engine() {
    if (!mt_) Start();
    return *mt_;
  }
  /// Makes the state and seeds it: from seed_ when Seed was called, else mt19937's default.
  void Start();

  uint64_t seed_ = 0;
  bool seeded_ = false;
  bool plain_ = false;  // SeedPlain: init_genrand(seed), not the two-word seed sequence
  std::unique_ptr<std::mt19937> mt_;
};

}  // namespace essaim
