// Actuator and sensor noise: moments over many draws against the
// configured distributions, and stream ownership — a robot's noise comes from its own
// streams only, so other robots, threads and robot.random never shift it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr int kDraws = 20000;
constexpr int kRobots = 4000;  // one bias draw each; seeding an MT19937 is the slow part

struct Moments {
  double mean = 0, sd = 0, min = 1e300, max = -1e300;
};

Moments Of(const std::vector<double>& v) {
  Moments m;
  for (double x : v) {
    m.mean += x;
    m.min = std::min(m.min, x);
    m.max = std::max(m.max, x);
  }
  m.mean /= v.size();
  for (double x : v) m.sd += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(m.sd / (v.size() - 1));
  return m;
}

/// Gaussian(sd, mean) sample moments within 5 standard errors.
void ExpectGaussian(const std::vector<double>& v, double mean, double sd) {
  Moments m = Of(v);
  double n = static_cast<double>(v.size());
  EXPECT_NEAR(m.mean, mean, 5 * sd / std::sqrt(n));
  EXPECT_NEAR(m.sd, sd, 5 * sd / std::sqrt(2 * n));
}

/// Uniform(lo, hi): moments within 5 standard errors, and every draw inside the range.
void ExpectUniform(const std::vector<double>& v, double lo, double hi) {
  Moments m = Of(v);
  double n = static_cast<double>(v.size());
  double sd = (hi - lo) / std::sqrt(12.0);
  EXPECT_NEAR(m.mean, (lo + hi) / 2, 5 * sd / std::sqrt(n));
  EXPECT_NEAR(m.sd, sd, 5 * sd / std::sqrt(5 * n / 4));  // uniform: var(s²) is smaller than Gaussian's
  EXPECT_GE(m.min, lo - 1e-12);
  EXPECT_LE(m.max, hi + 1e-12);
  EXPECT_LT(m.min, lo + (hi - lo) * 0.01) << "covers the range";
  EXPECT_GT(m.max, hi - (hi - lo) * 0.01);
}

DeviceConfig Config(DeviceType type, AttrMap attrs) {
  DeviceConfig cfg;
  cfg.type = type;
  cfg.attrs = std::move(attrs);
  ErrorList errors;
  ParseDeviceParams(&cfg, &errors);
  EXPECT_TRUE(errors.Empty()) << errors.Format();
  return cfg;
}

/// A one-robot Model and its physics, the robot at `pose`, for calling device functions.
struct Bench {
  Model model;
  std::unique_ptr<PhysicsWorld> physics;
  explicit Bench(const Pose2& pose = {}) {
    model.robots.resize(1);
    model.robots[0].pose = pose;
    physics = std::make_unique<PhysicsWorld>(model);
  }
};

TEST(Noise, WheelBiasIsDrawnOncePerRobotFromItsGaussian) {
  DeviceConfig cfg =
      Config(DeviceType::WheelsActuator, {{"bias_avg", "0.01"}, {"bias_stddev", "0.002"}, {"bias_avg_right", "-0.03"}});
  ASSERT_TRUE(cfg.params.wheel_noise);
  std::vector<double> left, right;
  for (int i = 0; i < kRobots; ++i) {
    RobotState r;
    r.actuator_rng.Seed(DeriveSeed(7, StreamKind::ActuatorNoise, i));
    InitWheelNoise(cfg, r);
    left.push_back(r.wheel_bias_left);
    right.push_back(r.wheel_bias_right);
  }
  ExpectGaussian(left, 0.01, 0.002);
  ExpectGaussian(right, -0.03, 0.002);  // the _right suffix overrides the generic mean only
}

TEST(Noise, WheelFactorIsDrawnPerCommandAndMultipliesSpeedPlusBias) {
  Bench b;
  DeviceConfig cfg = Config(DeviceType::WheelsActuator,
                            {{"factor_avg", "0.9"}, {"factor_stddev", "0.1"}, {"factor_stddev_left", "0.05"}});
  RobotState r;
  r.actuator_rng.Seed(11);
  InitWheelNoise(cfg, r);
  EXPECT_EQ(r.wheel_bias_left, 0) << "absent bias attributes mean no bias (an ARGoS quirk)";
  std::vector<double> left, right;
  for (int i = 0; i < kDraws; ++i) {
    r.cmd.wheel_left = 0.10;  // set_velocity(10, 20)
    r.cmd.wheel_right = 0.20;
    r.cmd.wheels_new = true;
    ActWheels(&cfg, r, *b.physics);
    left.push_back(r.wheel_left);
    right.push_back(r.wheel_right);
  }
  ExpectGaussian(left, 0.9 * 0.10, 0.05 * 0.10);
  ExpectGaussian(right, 0.9 * 0.20, 0.1 * 0.20);
  // A stop command is applied exactly and draws nothing.
  Rng before = r.actuator_rng;
  r.cmd.wheel_left = r.cmd.wheel_right = 0;
  r.cmd.wheels_new = true;
  ActWheels(&cfg, r, *b.physics);
  EXPECT_EQ(r.wheel_left, 0);
  EXPECT_EQ(r.wheel_right, 0);
  EXPECT_EQ(r.actuator_rng.NextU32(), before.NextU32());
  // No new command: the applied speeds stay, no draw.
  r.cmd.wheel_left = r.cmd.wheel_right = 0.1;
  r.cmd.wheels_new = true;
  ActWheels(&cfg, r, *b.physics);
  double held = r.wheel_left;
  before = r.actuator_rng;
  ActWheels(&cfg, r, *b.physics);
  EXPECT_EQ(r.wheel_left, held);
  EXPECT_EQ(r.actuator_rng.NextU32(), before.NextU32());
}

TEST(Noise, WheelFactorWithoutSpreadIsExact) {
  Bench b;
  DeviceConfig cfg = Config(DeviceType::WheelsActuator, {{"bias_avg", "0.01"}, {"factor_avg", "2"}});
  RobotState r;
  InitWheelNoise(cfg, r);  // bias_stddev 0: the bias is exactly its mean
  EXPECT_DOUBLE_EQ(r.wheel_bias_left, 0.01);
  r.cmd.wheel_left = 0.05;
  r.cmd.wheel_right = -0.05;
  r.cmd.wheels_new = true;
  ActWheels(&cfg, r, *b.physics);
  EXPECT_DOUBLE_EQ(r.wheel_left, 2 * (0.05 + 0.01));
  EXPECT_DOUBLE_EQ(r.wheel_right, 2 * (-0.05 + 0.01));
}

TEST(Noise, WheelSensorVelocityAndDistanceRanges) {
  DeviceConfig cfg = Config(DeviceType::WheelsSensor, {{"vel_noise_range", "-1:3"}, {"dist_noise_range", "0:0.5"}});
  RobotState r;
  r.sensor_rng.Seed(3);
  r.wheel_left = 0.10;  // applied 10 cm/s
  r.wheel_right = -0.05;
  std::vector<double> vl, vr, dl;
  for (int i = 0; i < kDraws; ++i) {
    SenseWheels(cfg, r, 0.1);
    vl.push_back(r.rd.velocity_left - 10);
    vr.push_back(r.rd.velocity_right + 5);
    dl.push_back(r.rd.distance_left - 1);  // 10 cm/s · 0.1 s
  }
  ExpectUniform(vl, -1, 3);
  ExpectUniform(vr, -1, 3);
  ExpectUniform(dl, 0, 0.5);
}

TEST(Noise, PositioningPositionAngleAndAxisRanges) {
  Bench b({1, 2, 0.5});
  DeviceConfig pos = Config(DeviceType::PositioningSensor, {{"pos_noise_range", "-0.01:0.01"}});
  DeviceConfig ang = Config(DeviceType::PositioningSensor, {{"angle_noise_range", "0:0.2"}});
  DeviceConfig axis = Config(DeviceType::PositioningSensor, {{"axis_noise_range", "-0.1:0.1"}});
  RobotState r;
  r.sensor_rng.Seed(5);
  std::vector<double> x, y, z, angle, ax;
  for (int i = 0; i < kDraws; ++i) {
    SensePositioning(pos, r, *b.physics);
    x.push_back(r.rd.position.x() - 1);
    y.push_back(r.rd.position.y() - 2);
    z.push_back(r.rd.position.z());
    EXPECT_DOUBLE_EQ(r.rd.quat_z, std::sin(0.25));  // orientation untouched
    SensePositioning(ang, r, *b.physics);
    angle.push_back(2 * std::atan2(r.rd.quat_z, r.rd.quat_w) - 0.5);  // axis stays +Z
    SensePositioning(axis, r, *b.physics);
    ax.push_back(r.rd.quat_x / std::sin(0.25));  // axis x = 0 + u, scaled by sin(angle/2)
  }
  ExpectUniform(x, -0.01, 0.01);
  ExpectUniform(y, -0.01, 0.01);
  ExpectUniform(z, -0.01, 0.01);
  ExpectUniform(angle, 0, 0.2);  // raw radians, as ARGoS parses it
  ExpectUniform(ax, -0.1, 0.1);
}

TEST(Noise, BatteryChargeRangeIsClampedToOne) {
  BatteryDef def;
  def.model = DischargeModel::Time;
  DeviceConfig cfg = Config(DeviceType::BatterySensor, {{"noise_range", "-0.1:0.1"}});
  RobotState r;
  r.sensor_rng.Seed(9);
  InitBattery(def, r, {});
  r.battery.charge = 0.5;
  std::vector<double> v;
  for (int i = 0; i < kDraws; ++i) {
    SenseBattery(cfg, def, r, 0.1);
    v.push_back(r.rd.battery_charge - 0.5);
  }
  ExpectUniform(v, -0.1, 0.1);
  r.battery.charge = 0.95;
  int at_one = 0;
  for (int i = 0; i < kDraws; ++i) {
    SenseBattery(cfg, def, r, 0.1);
    EXPECT_LE(r.rd.battery_charge, 1.0);
    at_one += r.rd.battery_charge == 1.0;
  }
  EXPECT_NEAR(at_one / double(kDraws), 0.25, 0.02) << "draws above 1 clamp to 1";
}

// ---- stream ownership, through whole worlds

const char* kQuiet =
    "<lua_controller id=\"quiet\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors><positioning implementation=\"default\" pos_noise_range=\"-0.01:0.01\"/></sensors>"
    "<params script=\"drive.lua\"/></lua_controller>";
// Draws far more: wheel factor noise, wheel-sensor noise, battery noise, more positioning.
const char* kNoisy =
    "<lua_controller id=\"noisy\"><actuators><differential_steering implementation=\"default\" "
    "bias_stddev=\"0.01\" factor_stddev=\"0.2\"/></actuators>"
    "<sensors><battery implementation=\"default\" noise_range=\"-0.1:0.1\"/>"
    "<differential_steering implementation=\"default\" vel_noise_range=\"-1:1\" dist_noise_range=\"-1:1\"/>"
    "<positioning implementation=\"default\" pos_noise_range=\"-0.05:0.05\" angle_noise_range=\"-0.1:0.1\"/></sensors>"
    "<params script=\"drive.lua\"/></lua_controller>";
const char* kDrive =
    "function init() robot.wheels.set_velocity(5, 6) end\n"
    "function step() log(string.format('%.17g', robot.random.uniform())) end\n";

struct Trace {
  std::vector<double> x0, x1;   // noisy position x of robot 0 and 1 (0 m-centred)
  std::vector<double> random0;  // robot 0's robot.random draws
  std::vector<Pose2> pose0;
};

Trace RunPair(const std::string& second_ctrl, bool with_second, int threads = 1) {
  TempDir d;
  d.Write("drive.lua", kDrive);
  std::string arena = FootBot("r0", 0, 0, 0, "quiet");
  if (with_second) arena += FootBot("r1", 0, 1, 0, second_ctrl);
  Trace t;
  std::vector<double> logged;  // robot.random draws, robot order within a tick
  SimOptions sim;
  sim.threads = threads;
  sim.log_sink = [&](char, const std::string& line, const LogOrigin&) {
    logged.push_back(std::strtod(line.c_str(), nullptr));
  };
  Scene s = Load(d, Experiment(arena, std::string(kQuiet) + kNoisy, 100, 42), {}, sim);
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return t;
  for (int k = 0; k < 100; ++k) {
    Step(*s.world);
    Pose2 p = s.world->physics.RobotPose(0);
    t.pose0.push_back(p);
    t.x0.push_back(s.world->robots[0].rd.position.x() - p.x);
    if (with_second) t.x1.push_back(s.world->robots[1].rd.position.x() - s.world->physics.RobotPose(1).x);
  }
  const size_t per_tick = with_second ? 2 : 1;  // robot 0 logs first in each tick
  for (size_t i = 0; i < logged.size(); i += per_tick) t.random0.push_back(logged[i]);
  return t;
}

TEST(Noise, EachRobotDrawsFromItsOwnStreams) {
  Trace alone = RunPair("", false);
  Trace twin = RunPair("quiet", true);
  Trace noisy = RunPair("noisy", true);
  Trace threaded = RunPair("noisy", true, 2);
  ASSERT_EQ(alone.x0.size(), 100u);
  ASSERT_EQ(alone.random0.size(), 100u);
  // Robot 0's noise and robot.random are the same whoever its neighbour is, however
  // much the neighbour draws, on one thread or two.
  for (const Trace* t : {&twin, &noisy, &threaded}) {
    ASSERT_EQ(t->x0.size(), alone.x0.size());
    ASSERT_EQ(t->random0.size(), alone.random0.size());
    for (size_t k = 0; k < alone.x0.size(); ++k) {
      ASSERT_EQ(t->x0[k], alone.x0[k]) << "tick " << k + 1;
      ASSERT_EQ(t->random0[k], alone.random0[k]) << "tick " << k + 1;
    }
  }
  // Two robots with the same controller and seed draw different, uncorrelated noise.
  double sxy = 0, sxx = 0, syy = 0;
  int equal = 0;
  for (size_t k = 0; k < twin.x0.size(); ++k) {
    equal += twin.x0[k] == twin.x1[k];
    sxy += twin.x0[k] * twin.x1[k];
    sxx += twin.x0[k] * twin.x0[k];
    syy += twin.x1[k] * twin.x1[k];
  }
  EXPECT_EQ(equal, 0);
  EXPECT_LT(std::fabs(sxy / std::sqrt(sxx * syy)), 0.3);  // |r| < 3/sqrt(100)
  ExpectUniform(twin.x0, -0.01, 0.01);
}

TEST(Noise, SensorNoiseLeavesRobotRandomAlone) {
  // The quiet controller (noisy positioning) and a noise-free copy: same robot.random.
  TempDir d;
  d.Write("drive.lua", kDrive);
  std::string clean = kQuiet;
  clean.replace(clean.find(" pos_noise_range=\"-0.01:0.01\""), 29, "");
  clean.replace(clean.find("\"quiet\""), 7, "\"clean\"");
  auto run = [&](const std::string& ctrl) {
    std::vector<double> out;
    SimOptions sim;
    sim.log_sink = [&](char, const std::string& line, const LogOrigin&) {
      out.push_back(std::strtod(line.c_str(), nullptr));
    };
    Scene s = Load(d, Experiment(FootBot("r0", 0, 0, 0, ctrl), std::string(kQuiet) + clean, 30, 42), {}, sim);
    EXPECT_TRUE(s.ok()) << s.error;
    if (s.ok()) RunTicks(*s.world, 30);
    return out;
  };
  std::vector<double> a = run("quiet"), b = run("clean");
  ASSERT_EQ(a.size(), 30u);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace essaim
