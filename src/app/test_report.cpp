#include "app/test_report.h"

#include <algorithm>
#include <cstdio>

namespace essaim {

namespace {
std::string SeedList(const std::vector<uint64_t>& seeds) {
  std::string s;
  for (size_t i = 0; i < seeds.size() && i < 20; ++i) s += (i ? ", " : "") + std::to_string(seeds[i]);
  if (seeds.size() > 20) s += ", ... (" + std::to_string(seeds.size()) + ")";
  return s;
}

std::string Padded(const std::string& s, size_t width) {
  return s + std::string(width > s.size() ? width - s.size() : 0, ' ');
}

std::string XmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
      out += ' ';  // not allowed in XML 1.0
    else
      out += c;
  }
  return out;
}

size_t Failures(const TestReport& r) {
  return static_cast<size_t>(
      std::count_if(r.rows.begin(), r.rows.end(), [](const ReportRow& row) { return !row.pass; }));
}

std::string TestCase(const TestReport& report, const ReportRow& row) {
  std::string xml = "    <testcase classname=\"essaim." + XmlEscaped(report.suite) + "\" name=\"" +
                    XmlEscaped(row.expectation) + "\" time=\"0\"";
  if (row.pass) return xml + "/>\n";
  std::string message = row.value + (row.failed_seeds.empty() ? "" : "; seeds " + SeedList(row.failed_seeds));
  std::string body;
  for (const std::string& d : row.details) body += d + "\n";
  const char* type = row.spec_error ? "spec" : "expectation";
  return xml + ">\n      <failure type=\"" + type + "\" message=\"" + XmlEscaped(message) + "\">" + XmlEscaped(body) +
         "</failure>\n    </testcase>\n";
}
}  // namespace

bool TestReport::Passed() const { return Failures(*this) == 0; }

TestReport SpecErrorReport(const std::string& spec_file, const std::string& suite,
                           const std::vector<std::string>& errors) {
  TestReport report;
  report.suite = suite;
  report.spec_file = spec_file;
  ReportRow row;
  row.expectation = "the spec " + spec_file + " reads";
  row.value = std::to_string(errors.size()) + " error(s) in the spec: nothing was run";
  row.details = errors;
  row.spec_error = true;
  report.rows.push_back(row);
  return report;
}

std::string FormatReport(const TestReport& report) {
  size_t width_e = 11, width_v = 5;
  for (const ReportRow& row : report.rows) {
    width_e = std::max(width_e, row.expectation.size());
    width_v = std::max(width_v, row.value.size());
  }
  std::string out = Padded("expectation", width_e) + "  " + Padded("value", width_v) + "  verdict  failed seeds\n";
  for (const ReportRow& row : report.rows) {
    out += Padded(row.expectation, width_e) + "  " + Padded(row.value, width_v) + "  " +
           (row.pass         ? "pass     "
            : row.spec_error ? "ERROR    "
                             : "FAIL     ") +
           (row.pass ? "" : SeedList(row.failed_seeds)) + "\n";
    for (const std::string& d : row.details) out += "    " + d + "\n";
  }
  size_t failed = Failures(report);
  auto mistakes =
      std::count_if(report.rows.begin(), report.rows.end(), [](const ReportRow& r) { return r.spec_error; });
  char line[200];
  std::snprintf(line, sizeof line, "%s: %zu of %zu expectations hold (%.1f s): %s\n", report.spec_file.c_str(),
                report.rows.size() - failed, report.rows.size(), report.seconds,
                mistakes ? "the spec has mistakes (ERROR rows)"
                : failed ? "FAILED"
                         : "passed");
  return out + line;
}

std::string JUnitXml(const TestReport& report) {
  char head[512];
  std::snprintf(head, sizeof head,
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<testsuites tests=\"%zu\" failures=\"%zu\" errors=\"0\" time=\"%.3f\">\n"
                "  <testsuite name=\"%s\" tests=\"%zu\" failures=\"%zu\" errors=\"0\" skipped=\"0\" time=\"%.3f\">\n",
                report.rows.size(), Failures(report), report.seconds, XmlEscaped(report.suite).c_str(),
                report.rows.size(), Failures(report), report.seconds);
  std::string xml = head;
  for (const ReportRow& row : report.rows) xml += TestCase(report, row);
  return xml + "  </testsuite>\n</testsuites>\n";
}

}  // namespace essaim
