// C++ loop functions (docs/loop-functions.md, "C++ loop functions"): a library built
// against essaim's ARGoS API, loaded and driven at the points of the tick where the Lua
// loop functions' hooks run. The ARGoS classes stay inside this room: the rest of essaim
// sees this class only.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_host.h"
#include "core/color.h"
#include "model/model.h"

namespace essaim {

class CppLoopFunctions {
 public:
  CppLoopFunctions();
  ~CppLoopFunctions();  // the loop functions deleted (Destroy() is a hook: Call("destroy"))
  CppLoopFunctions(const CppLoopFunctions&) = delete;
  CppLoopFunctions& operator=(const CppLoopFunctions&) = delete;

  /// Makes the loop functions of the label in `host`'s session (loaded: its libraries hold the
  /// label). `host` must outlive it. False with `error`: bad input (exit 2).
  bool Load(const Model& model, ArgosHost* host, std::string* error);
  bool Loaded() const { return host_ != nullptr; }

  /// "init", "pre_step", "post_step", "reset", "destroy", "post_experiment".
  bool Call(const char* hook, std::string* error);
  bool IsExperimentFinished(bool* finished, std::string* error);
  /// Whether the last hook's error came from reading the .argos element (GetNodeAttribute,
  /// GetNode): bad input, whose message names the file and line.
  bool LastErrorIsConfiguration() const;
  bool FloorColor(double x, double y, Color* out, std::string* error);
  /// Whether the floor entity's SetChanged() was called since the last call.
  bool TakeFloorChanged();
  /// LOG/LOGERR lines, "<O or E><text>\n" each.
  std::string& LogBuffer();

 private:
  const Model* model_ = nullptr;
  ArgosHost* host_ = nullptr;
};

}  // namespace essaim
