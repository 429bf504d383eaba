// Foot-bot distance scanner, rot_z_only sensor and default actuator.
//
// A platform 0.123199866 m above the robot origin carries four range sensors: short range
// at θ and θ + π, long range at θ + π/2 and θ − π/2 (θ = platform rotation, robot frame).
// Rays start on the body surface; readings are in cm from the ray start, −1 when the hit
// is within the minimum distance (long range: 12 cm), −2 without a hit. Position mode
// gives one ray per sensor; speed mode sweeps the span rotated since the previous sense
// with 6 rays per sensor. Readings are kept sorted by angle, duplicates overwritten — the
// std::map<CRadians, Real> of ARGoS. `noise_range` is ignored, as in ARGoS.
#include <cmath>

#include "devices/devices.h"

namespace essaim {

namespace {
constexpr double kShortLength = 0.26;  // m, ray length from the body surface
constexpr double kLongLength = 1.42;
constexpr double kShortMin = 0.0;  // m: at or below reads -1
constexpr double kLongMin = 0.12;
constexpr int kSweepRays = 6;  // rays per sensor per tick in speed mode

/// Inserts (angle, distance) into a sorted array of `*count` readings; an equal angle
/// overwrites (map semantics). Shifts while it scans (a sweep mostly appends); writes at most
/// readings[*count], within the array since a tick inserts no more than it holds.
void Insert(ScanReading* readings, int* count, double angle, double distance) {
  int i = *count;
  for (; i > 0 && readings[i - 1].angle > angle; --i) readings[i] = readings[i - 1];
  if (i > 0 && readings[i - 1].angle == angle) {  // rare (a stopped sweep): undo the shift
    readings[i - 1].distance = distance;
    for (int j = i; j < *count; ++j) readings[j] = readings[j + 1];
    return;
  }
  readings[i] = {angle, distance};
  ++*count;
}

/// The reading of one ray in direction (c, s), robot heading included.
double Cast(const PhysicsWorld& physics, const RayCandidates& near_shapes, const Pose2& p, double c, double s,
            double length, double min) {
  const Vec2 from(p.x + footbot::kRadius * c, p.y + footbot::kRadius * s);
  const Vec2 to(from.x() + length * c, from.y() + length * s);
  const RayHit hit = physics.CastRay(near_shapes, from, to);
  if (!hit.Hit()) return -2;
  return hit.distance > min ? hit.distance * 100 : -1;
}

/// ARGoS's signed normalisation of an angle (CRadians::SignedNormalize): whole turns off
/// until it lies in [-π, π], both ends kept. Applied after every step of the sums below, as
/// ARGoS does, so that a ray ARGoS reports at -π is reported at -π here, not at +π.
double SignedNormalize(double a) {
  while (a > kPi) a -= kTwoPi;
  while (a < -kPi) a += kTwoPi;
  return a;
}

/// The four sensors' angles on the platform at rotation `theta`, summed as ARGoS sums them:
/// θ, then a quarter turn added three times (k = 0..3: θ, θ + π/2, θ + π, θ − π/2).
void PositionAngles(double theta, double angle[4]) {
  angle[0] = SignedNormalize(theta);
  for (int k = 1; k < 4; ++k) angle[k] = SignedNormalize(angle[k - 1] + kPi / 2);
}

/// Sensor k's first ray of a sweep from platform rotation `start`, summed as ARGoS does.
double SweepStartAngle(double start, int k) {
  if (k == 0) return SignedNormalize(start);
  if (k == 1) return SignedNormalize(start + kPi / 2);
  if (k == 2) return SignedNormalize(start + kPi);
  return SignedNormalize(start + kPi / 2 + kPi);
}

void Insert(Readings& rd, int k, double angle, double d) {
  if (k % 2 == 0)
    Insert(rd.scanner_short, &rd.scanner_short_count, angle, d);
  else
    Insert(rd.scanner_long, &rd.scanner_long_count, angle, d);
}

/// The four sensors at platform angle `theta`.
void CastAll(const PhysicsWorld& physics, const Pose2& p, RobotState& robot, double theta) {
  double angles[4];
  PositionAngles(theta, angles);
  for (int k = 0; k < 4; ++k) {
    const double angle = angles[k];
    const double a = p.yaw + angle;
    const bool shortRange = (k % 2) == 0;
    const double d = Cast(physics, robot.scanner_candidates, p, std::cos(a), std::sin(a),
                          shortRange ? kShortLength : kLongLength, shortRange ? kShortMin : kLongMin);
    Insert(robot.rd, k, angle, d);
  }
}

/// Speed mode: each sensor's kSweepRays rays from `start`, `span` apart. The short sensors'
/// rays are tested against the shapes within their reach, each long sensor's against those
/// near the sector it sweeps (when at most a quarter turn): most of the 1.5 m disc lies
/// outside both. Readings inserted in CastAll's order.
void Sweep(const PhysicsWorld& physics, const Pose2& p, RobotState& robot, double start, double span) {
  const Vec2 centre(p.x, p.y);
  physics.GatherRayCandidates(centre, footbot::kRadius + kShortLength, footbot::kScannerElevation, robot.index,
                              &robot.scanner_candidates);
  double angle[kSweepRays][4], reading[kSweepRays][4];
  for (int k = 0; k < 4; ++k) {
    const bool shortRange = (k % 2) == 0;
    double c[kSweepRays], s[kSweepRays];
    for (int i = 0; i < kSweepRays; ++i) {
      // Each ray one span on from the previous one (ARGoS adds the span, then normalises).
      angle[i][k] = i == 0 ? SweepStartAngle(start, k) : SignedNormalize(angle[i - 1][k] + span);
      const double a = p.yaw + angle[i][k];
      c[i] = std::cos(a);
      s[i] = std::sin(a);
    }
    const RayCandidates* shapes = &robot.scanner_candidates;
    if (!shortRange) {
      const double radius = footbot::kRadius + kLongLength;
      if ((kSweepRays - 1) * span <= kPi / 2)
        physics.GatherWedgeCandidates(centre, radius, {c[0], s[0]}, {c[kSweepRays - 1], s[kSweepRays - 1]},
                                      footbot::kScannerElevation, robot.index, &robot.scanner_wedge);
      else
        physics.GatherRayCandidates(centre, radius, footbot::kScannerElevation, robot.index, &robot.scanner_wedge);
      shapes = &robot.scanner_wedge;
    }
    for (int i = 0; i < kSweepRays; ++i)
      reading[i][k] = Cast(physics, *shapes, p, c[i], s[i], shortRange ? kShortLength : kLongLength,
                           shortRange ? kShortMin : kLongMin);
  }
  for (int i = 0; i < kSweepRays; ++i)
    for (int k = 0; k < 4; ++k) Insert(robot.rd, k, angle[i][k], reading[i][k]);
}
}  // namespace

void ActScanner(RobotState& robot) {
  ScannerState& s = robot.scanner;
  switch (robot.cmd.scanner_mode) {
    case ScannerMode::Position:
      s.mode = ScannerMode::Position;
      s.rotation = WrapUnsigned(robot.cmd.scanner_angle);
      break;
    case ScannerMode::Speed:
      s.mode = ScannerMode::Speed;
      s.speed = robot.cmd.scanner_speed;
      break;
    case ScannerMode::Off:
      s.mode = ScannerMode::Off;
      break;
  }
}

void UpdateScanner(RobotState& robot, double dt) {
  ScannerState& s = robot.scanner;
  if (s.mode == ScannerMode::Speed) s.rotation = WrapUnsigned(s.rotation + s.speed * dt);
}

void SenseScanner(RobotState& robot, const PhysicsWorld& physics) {
  ScannerState& s = robot.scanner;
  Readings& rd = robot.rd;
  rd.scanner_short_count = 0;
  rd.scanner_long_count = 0;
  const Pose2 p = physics.RobotPose(robot.index);
  if (s.mode == ScannerMode::Position) {
    physics.GatherRayCandidates({p.x, p.y}, footbot::kRadius + kLongLength, footbot::kScannerElevation, robot.index,
                                &robot.scanner_candidates);
    CastAll(physics, p, robot, s.rotation);
  } else if (s.mode == ScannerMode::Speed) {
    // The span is always swept counter-clockwise (ARGoS quirk: negative rpm mis-handled).
    const double span = WrapUnsigned(s.rotation - s.previous_rotation) / kSweepRays;
    Sweep(physics, p, robot, s.previous_rotation, span);
  }
  s.previous_rotation = s.rotation;
}

}  // namespace essaim
