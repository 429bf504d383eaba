// Range-and-bearing actuator and sensor. The medium (devices/rab_routing.cpp) decides
// who hears whom after physics; here the receiver turns each routed packet into range and
// bearings in its own frame, with drop and noise from its own sensor_rng.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

void ActRab(RobotState& robot) {
  // One-tick latency: the payload set in step() at t is broadcast from t+1.
  std::copy(robot.cmd.rab_data.begin(), robot.cmd.rab_data.end(), robot.rab_data.begin());
}

void SenseRab(const SenseContext& ctx, const DeviceConfig& cfg, RobotState& robot) {
  Readings& rd = robot.rd;
  rd.rab.clear();
  const Media& media = ctx.media;
  const int self = robot.index;
  if (media.rab_medium.empty() || media.rab_medium[self] < 0) return;
  const double drop = cfg.params.packet_drop_prob;
  const double noise = cfg.params.noise_std_dev;
  const Vec3& pr = media.rab_pos[self];
  const double c = std::cos(media.rab_yaw[self]), s = std::sin(media.rab_yaw[self]);
  for (int sender : media.rab_inbox[self]) {
    if (drop > 0 && robot.sensor_rng.Bernoulli(drop)) continue;
    Vec3 v = media.rab_pos[sender] - pr;
    if (noise > 0) {
      // Length ~ N(0, sd), inclination U[0, pi], azimuth U[0, 2pi] (not uniform on the sphere).
      const double len = robot.sensor_rng.Gaussian(noise);
      const double inc = robot.sensor_rng.Uniform(0, kPi);
      const double az = robot.sensor_rng.Uniform(0, kTwoPi);
      v += Vec3(len * std::sin(inc) * std::cos(az), len * std::sin(inc) * std::sin(az), len * std::cos(inc));
    }
    // Into the receiver's frame (planar robot: rotate by -yaw).
    const double lx = c * v.x() + s * v.y();
    const double ly = -s * v.x() + c * v.y();
    const double len = v.norm();
    RabPacket p;
    p.range = len * 100.0;
    p.horizontal_bearing = std::atan2(ly, lx);
    p.vertical_bearing = len > 0 && v.z() != 0 ? kPi / 2 - std::acos(std::clamp(v.z() / len, -1.0, 1.0)) : 0.0;
    p.sender = sender;
    const std::vector<uint8_t>& payload = ctx.robots[sender].rab_data;
    p.data = payload.data();
    p.size = static_cast<int>(payload.size());
    rd.rab.push_back(p);
  }
}

}  // namespace essaim
