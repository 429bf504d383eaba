#include "model/device_params.h"

#include "core/strings.h"
#include "model/model.h"

namespace essaim {

namespace {
struct Parser {
  DeviceConfig* cfg;
  ErrorList* errors;
  void Fail(const std::string& name, const std::string& what) {
    errors->Add(cfg->loc.file, cfg->loc.line, cfg->loc.element,
                "attribute '" + name + "': '" + cfg->attrs[name] + "' " + what);
  }
  // Every read goes through here. A name missing from the device table's row would be
  // reported as an unknown attribute in the user's file: fail loudly instead (the row is
  // the schema, the loader's AttributeLedger relies on it: xml_controllers.cpp).
  bool Present(const std::string& name) const {
    bool in_row = false;
    for (const DeviceAttr& a : GetDeviceRow(cfg->type).attrs) in_row |= name == a.name;
    if (!in_row)
      errors->Add(cfg->loc.file, cfg->loc.line, cfg->loc.element,
                  "internal error: attribute '" + name + "' is read but missing from the device table");
    return cfg->attrs.count(name) > 0;
  }
  double Number(const std::string& name, double def, double min = -1e300, double max = 1e300) {
    if (!Present(name)) return def;
    auto v = ParseDouble(cfg->attrs[name]);
    if (!v) {
      Fail(name, "is not a number");
      return def;
    }
    if (*v < min || *v > max) {
      Fail(name, "is out of range [" + FormatDouble(min) + ", " + FormatDouble(max) + "]");
      return def;
    }
    return *v;
  }
  NoiseRange Range(const std::string& name) {
    NoiseRange r;
    if (!Present(name)) return r;
    auto v = ParseRange(cfg->attrs[name]);
    if (!v) {
      Fail(name, "must be a range min:max with min <= max");
      return r;
    }
    r.lo = v->first, r.hi = v->second;
    return r;
  }
};
}  // namespace

void ParseDeviceParams(DeviceConfig* cfg, ErrorList* errors) {
  Parser p{cfg, errors};
  DeviceParams& d = cfg->params;
  switch (cfg->type) {
    case DeviceType::WheelsActuator: {
      const char* side[2] = {"_left", "_right"};
      for (const char* base : {"bias_avg", "bias_stddev", "factor_avg", "factor_stddev"})
        for (const char* suffix : {"", "_left", "_right"}) d.wheel_noise |= p.Present(std::string(base) + suffix);
      for (int w = 0; w < 2; ++w) {
        auto pick = [&](const std::string& base, double def) {
          double generic = p.Number(base, def);
          return p.Number(base + side[w], generic);
        };
        d.bias_avg[w] = pick("bias_avg", 0);
        d.bias_stddev[w] = pick("bias_stddev", 0);
        d.factor_avg[w] = pick("factor_avg", 1);
        d.factor_stddev[w] = pick("factor_stddev", 0);
      }
      break;
    }
    case DeviceType::WheelsSensor:
      d.vel_noise = p.Range("vel_noise_range");
      d.dist_noise = p.Range("dist_noise_range");
      break;
    case DeviceType::PositioningSensor:
      d.pos_noise = p.Range("pos_noise_range");
      d.angle_noise = p.Range("angle_noise_range");
      d.axis_noise = p.Range("axis_noise_range");
      break;
    case DeviceType::BatterySensor:
      d.charge_noise = p.Range("noise_range");
      break;
    case DeviceType::ProximitySensor:
    case DeviceType::LightSensor:
    case DeviceType::BaseGroundSensor:
    case DeviceType::MotorGroundSensor:
      d.noise_level = p.Number("noise_level", 0, 0);
      break;
    case DeviceType::RabSensor:
      d.noise_std_dev = p.Number("noise_std_dev", 0, 0);
      d.packet_drop_prob = p.Number("packet_drop_prob", 0, 0, 1);
      break;
    case DeviceType::CameraSensor:
      d.noise_std_dev = p.Number("noise_std_dev", 0, 0);
      break;
    case DeviceType::ScannerSensor:
      p.Range("noise_range");  // validated, then ignored as ARGoS does
      break;
    default:
      break;
  }
}

}  // namespace essaim
