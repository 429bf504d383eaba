// The devices layer's row of each device: what it does when the World is built, in the act
// stage and in the sense stage. Indexed by DeviceType like model/device_table.h's rows and
// checked against them at compile time (device_functions.cpp): a sensor has a sense
// function, an actuator an act function and the half of the act stage it runs in.
#pragma once
#include "devices/devices.h"

namespace essaim {

/// What preparing a robot's devices reads (World creation, one thread).
struct InitContext {
  const Model& model;
  const PhysicsWorld& physics;
};

/// What the act stage hands every actuator.
struct ActContext {
  const Model& model;
  PhysicsWorld& physics;
  double dt = 0.1;  // s, one tick
};

/// Which half of the act stage an actuator runs in (devices.h: ActRobotOwnState, ActRobotJoints).
enum class ActPhase {
  None,      // a sensor
  OwnState,  // writes only the robot's own state and wheel servo: any thread
  Joints,    // makes or moves joints in the shared physics world: one thread, robot order
};

using InitFn = void (*)(const InitContext&, const DeviceConfig&, const RobotDef&, RobotState&);
using ActFn = void (*)(const ActContext&, const DeviceConfig&, const RobotDef&, RobotState&);
using SenseFn = void (*)(const SenseContext&, const DeviceConfig&, const RobotDef&, RobotState&);

struct DeviceFunctions {
  DeviceType type;
  InitFn init;         // buffers, drawn biases, readings visible in init(); nullptr: none
  ActPhase act_phase;  // actuators only
  ActFn act;           // actuators: apply the commands the controller set last tick
  SenseFn sense;       // sensors: fill the robot's Readings
};

const DeviceFunctions& FunctionsOf(DeviceType type);

}  // namespace essaim
