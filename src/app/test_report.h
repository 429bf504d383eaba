// What `essaim test` found: one row per expectation (and the built-in checks), printed as a
// table and, with --junit, written as JUnit XML (one testsuite per spec, one testcase per row).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace essaim {

struct ReportRow {
  std::string expectation;
  std::string value;
  bool pass = false;
  std::vector<uint64_t> failed_seeds;
  std::vector<std::string> details;  // printed under the row (why runs failed, golden differences)
  bool spec_error = false;           // a mistake of the spec (a value no run produced), not of the runs
};

struct TestReport {
  std::string suite;  // the spec's name
  std::string spec_file;
  double seconds = 0;
  std::vector<ReportRow> rows;
  bool Passed() const;
};

/// The table, as printed on stdout.
std::string FormatReport(const TestReport& report);
/// The report of a spec that cannot be run: one failed row carrying its errors.
TestReport SpecErrorReport(const std::string& spec_file, const std::string& suite,
                           const std::vector<std::string>& errors);
/// The JUnit XML text (the schema CI dashboards read: testsuites/testsuite/testcase/failure).
std::string JUnitXml(const TestReport& report);

}  // namespace essaim
