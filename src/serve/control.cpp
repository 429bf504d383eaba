#include "serve/control.h"

#include "core/strings.h"
#include "core/value_json.h"

namespace essaim {

namespace {
bool Ticks(const Value& doc, ControlCommand* out, std::string* error) {
  const Value* t = doc.Find("ticks");
  if (!t) return true;
  if (t->kind != Value::Kind::Integer || t->integer < 1 || t->integer > 1000000000LL) {
    *error = "\"ticks\" must be an integer from 1 to 1000000000";
    return false;
  }
  out->ticks = static_cast<uint64_t>(t->integer);
  return true;
}

double NumberOr(const Value* v, double otherwise) {
  if (v && v->kind == Value::Kind::Integer) return static_cast<double>(v->integer);
  if (v && v->kind == Value::Kind::Unsigned) return static_cast<double>(v->big_unsigned);
  if (v && v->kind == Value::Kind::Number) return v->number;
  return otherwise;
}

bool Speed(const Value& doc, ControlCommand* out, std::string* error) {
  double x = NumberOr(doc.Find("value"), -1);
  if (!(x == 0 || (x >= 0.01 && x <= 10000))) {
    *error = "\"value\" must be a number: 0 (as fast as it goes) or 0.01 to 10000 (times real time)";
    return false;
  }
  out->speed = x;
  return true;
}

bool Reset(const Value& doc, ControlCommand* out, std::string* error) {
  if (const Value* s = doc.Find("seed")) {
    if (s->kind != Value::Kind::Integer || s->integer < 0) {
      *error = "\"seed\" must be an integer >= 0";
      return false;
    }
    out->seed = static_cast<uint64_t>(s->integer);
  }
  if (const Value* n = doc.Find("new_seed")) {
    if (n->kind != Value::Kind::Bool) {
      *error = "\"new_seed\" must be true or false";
      return false;
    }
    out->new_seed = n->boolean;
  }
  return true;
}
}  // namespace

bool ParseControl(const std::string& body, ControlCommand* out, std::string* error) {
  Value doc;
  if (!ParseJsonValue(body, &doc, error)) return false;
  const Value* cmd_value = doc.Find("cmd");
  if (!cmd_value || cmd_value->kind != Value::Kind::String) {
    *error = "the body must be a JSON object with \"cmd\": play, pause, step, run, speed or reset";
    return false;
  }
  const std::string cmd = cmd_value->text;
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
