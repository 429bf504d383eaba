// A behaviour test of one experiment (`essaim test SPEC.toml`, docs/testing.md): which file,
// which seeds and ticks, which --set overrides, the expectations over the runs' outputs, and
// an optional golden run. Loaded from TOML by test_spec_toml.cpp, the one toml++ user.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace essaim {

/// One `--set PATH=VALUE` the spec's [set] table gives every run.
struct SpecSetting {
  std::string path;
  std::string value;
};

/// An expectation as written, with the line it came from (for error messages).
struct SpecExpectation {
  std::string text;
  int line = 0;
};

struct TestSpec {
  std::string file;         // the spec as given on the command line
  std::string name;         // its file name without .toml: the JUnit suite's name
  std::string experiment;   // the .argos file, relative to the spec's folder when written so
  std::string workdir;      // where each run's process starts (default: the spec's folder)
  int experiment_line = 0;  // where the spec gives them (0: not given)
  int workdir_line = 0;
  uint64_t ticks = 0;  // 0: the experiment's own length
  std::vector<uint64_t> seeds;
  std::vector<SpecSetting> sets;
  std::vector<SpecExpectation> expectations;
  std::string golden;        // the golden file ("" = no golden run)
  uint64_t golden_seed = 0;  // the seed whose run is recorded and compared
  int timeout_s = 600;       // for ctest (essaim_add_test) and the runs themselves
  std::vector<std::string> labels;
};

/// Reads `path`; false with every problem as "FILE:LINE: message" in `errors`.
bool LoadTestSpec(const std::string& path, TestSpec* spec, std::vector<std::string>* errors);

}  // namespace essaim
