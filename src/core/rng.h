// Random numbers with ARGoS's distributions (spec §8.4), on MT19937 streams.
// The standard fixes mt19937's output sequence; the std:: distributions are not fixed
// across standard libraries, so every transform here is our own (determinism contract).
#pragma once
#include <cstdint>
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

class Rng {
 public:
  Rng() : mt_(5489u) {}
  explicit Rng(uint64_t seed) { Seed(seed); }
  /// The stream of `seed`. Its 624-word state is made at the first draw: a robot has three
  /// streams and most experiments draw from one or none (set-up at 100 000 robots).
  void Seed(uint64_t seed) {
    seed_ = seed;
    unseeded_ = true;
  }

  uint32_t NextU32() {
    if (unseeded_) SeedNow();
    return static_cast<uint32_t>(mt_());
  }
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
  void SeedNow();

  std::mt19937 mt_;
  uint64_t seed_ = 0;
  bool unseeded_ = false;  // Seed() called, state not made yet
};

}  // namespace essaim
