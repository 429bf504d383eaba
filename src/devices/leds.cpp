// LEDs actuator: the 13 colours set by the controller become the robot's
// applied LEDs in Act, which the LED field (devices/led_field.cpp) indexes for cameras.
#include <algorithm>

#include "devices/devices.h"

namespace essaim {

void ActLeds(RobotState& robot) { std::copy(robot.cmd.leds, robot.cmd.leds + footbot::kLedCount, robot.leds); }

}  // namespace essaim
