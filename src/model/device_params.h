// Device attributes parsed once at load into typed fields, so the step never parses text
// and a bad value is a load error with file and line.
#pragma once
#include "core/error_list.h"

namespace essaim {

struct DeviceConfig;

struct NoiseRange {
  double lo = 0, hi = 0;
  bool On() const { return lo != hi; }
};

struct DeviceParams {
  // differential_steering actuator: index 0 left, 1 right
  bool wheel_noise = false;
  double bias_avg[2] = {0, 0}, bias_stddev[2] = {0, 0};
  double factor_avg[2] = {1, 1}, factor_stddev[2] = {0, 0};
  // differential_steering sensor
  NoiseRange vel_noise, dist_noise;
  // positioning
  NoiseRange pos_noise, angle_noise, axis_noise;
  // battery sensor
  NoiseRange charge_noise;
  // proximity, light, ground sensors
  double noise_level = 0;
  // range_and_bearing sensor, camera
  double noise_std_dev = 0;
  double packet_drop_prob = 0;
};

/// Fills cfg->params from cfg->attrs; reports bad values into `errors`.
void ParseDeviceParams(DeviceConfig* cfg, ErrorList* errors);

}  // namespace essaim
