// Where `essaim run` prints the scripts' log lines. On a terminal the progress line is
// cleared first (a log line used to be glued to it). --log-prefix starts each line with the
// tick and the robot ("[t=120 fb7] ..."); --log-dir writes each robot's lines to
// DIR/<robot id>.log (loop functions: DIR/loop_functions.log) instead of the terminal.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "model/model.h"
#include "sim/world.h"

namespace essaim {

class Progress;

class LogPrinter {
 public:
  LogPrinter(const Model& model, bool prefix, std::string dir);
  ~LogPrinter() { Flush(); }
  LogPrinter(const LogPrinter&) = delete;
  LogPrinter& operator=(const LogPrinter&) = delete;

  /// Creates --log-dir (exit 2 on failure, before the first tick); true without one.
  bool Prepare(std::string* error);
  /// The progress line to clear before printing (null: none).
  void SetProgress(Progress* progress) { progress_ = progress; }
  void Print(char stream, const std::string& line, const LogOrigin& from);
  /// Writes what the per-robot files still hold in memory; false with `error` on failure.
  bool Flush(std::string* error = nullptr);

 private:
  std::string Prefix(const LogOrigin& from) const;
  /// The --log-dir slot of a script's line (0: loop functions; robot i: i + 1), made for a
  /// robot the loop functions added during the run.
  size_t SlotOf(const LogOrigin& from);
  bool WriteOut(size_t slot, std::string* error);
  std::string PathOf(size_t slot) const;  // DIR/<robot id>.log, DIR/loop_functions.log

  std::vector<std::string> robot_ids_;
  bool prefix_;
  std::string dir_;
  Progress* progress_ = nullptr;
  // --log-dir: per slot (SlotOf), lines waiting in memory and whether
  // the file was started. Written in blocks so a thousand robots need no thousand open files.
  std::vector<std::string> pending_;
  std::vector<bool> started_;
};

}  // namespace essaim
