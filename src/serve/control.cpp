#include "serve/control.h"

#include "core/json.h"
#include "core/strings.h"

namespace essaim {

namespace {
bool Ticks(const Json& doc, ControlCommand* out, std::string* error) {
  if (!doc.contains("ticks")) return true;
  const Json& t = doc["ticks"];
  if (!t.is_number_integer() || t.get<long long>() < 1 || t.get<long long>() > 1000000000LL) {
    *error = "\"ticks\" must be an integer from 1 to 1000000000";
    return false;
  }
  out->ticks = t.get<uint64_t>();
  return true;
}

bool Speed(const Json& doc, ControlCommand* out, std::string* error) {
  const Json* v = doc.contains("value") ? &doc["value"] : nullptr;
  double x = v && v->is_number() ? v->get<double>() : -1;
  if (!(x == 0 || (x >= 0.01 && x <= 10000))) {
    *error = "\"value\" must be a number: 0 (as fast as it goes) or 0.01 to 10000 (times real time)";
    return false;
  }
  out->speed = x;
  return true;
}

bool Reset(const Json& doc, ControlCommand* out, std::string* error) {
  if (doc.contains("seed")) {
    const Json& s = doc["seed"];
    if (!s.is_number_integer() || s.get<long long>() < 0) {
      *error = "\"seed\" must be an integer >= 0";
      return false;
    }
    out->seed = s.get<uint64_t>();
  }
  if (doc.contains("new_seed")) {
    if (!doc["new_seed"].is_boolean()) {
      *error = "\"new_seed\" must be true or false";
      return false;
    }
    out->new_seed = doc["new_seed"].get<bool>();
  }
  return true;
}
}  // namespace

bool ParseControl(const std::string& body, ControlCommand* out, std::string* error) {
  Json doc;
  if (!ParseJson(body, &doc, error)) return false;
  if (!doc.is_object() || !doc.contains("cmd") || !doc["cmd"].is_string()) {
    *error = "the body must be a JSON object with \"cmd\": play, pause, step, run, speed or reset";
    return false;
  }
  const std::string cmd = doc["cmd"].get<std::string>();
  *out = ControlCommand{};
  if (cmd == "play")
    out->kind = ControlKind::Play;
  else if (cmd == "pause")
    out->kind = ControlKind::Pause;
  else if (cmd == "step" || cmd == "run")
    out->kind = ControlKind::Step;
  else if (cmd == "speed")
    out->kind = ControlKind::Speed;
  else if (cmd == "reset")
    out->kind = ControlKind::Reset;
  else {
    *error = "unknown cmd '" + cmd + "' (play, pause, step, run, speed or reset)";
    return false;
  }
  if (out->kind == ControlKind::Step) return Ticks(doc, out, error);
  if (out->kind == ControlKind::Speed) return Speed(doc, out, error);
  if (out->kind == ControlKind::Reset) return Reset(doc, out, error);
  return true;
}

std::optional<long long> ParseIndex(const std::string& text) {
  std::optional<long long> v = ParseInt(text);
  if (!v || *v < 0) return std::nullopt;
  return v;
}

}  // namespace essaim
