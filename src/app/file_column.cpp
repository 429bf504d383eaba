#include "app/file_column.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "core/paths.h"
#include "core/strings.h"
#include "output/run_files.h"

namespace essaim {

namespace {
const std::vector<std::string> kStats = {"last", "first", "mean", "sum", "min", "max", "rows"};

struct FileValue {
  std::string path;    // below files/
  std::string column;  // a name or a position from 1
  std::string stat;
};

bool ParseFileValue(const std::string& value, FileValue* out, std::string* error) {
  const size_t open = value.find('['), close = value.find(']');
  const std::string form = "files/PATH[COLUMN].STAT, e.g. files/zone_counts.txt[count].last";
  if (!IsFileValue(value) || open == std::string::npos || close == std::string::npos || close < open) {
    *error = "'" + value + "' is not " + form;
    return false;
  }
  out->path = value.substr(6, open - 6);
  out->column = value.substr(open + 1, close - open - 1);
  out->stat = close + 1 < value.size() && value[close + 1] == '.' ? value.substr(close + 2) : "";
  if (out->path.empty() || out->column.empty() || out->path.find("..") != std::string::npos) {
    *error = "'" + value + "' is not " + form + " (a path below files/, a column)";
    return false;
  }
  if (std::find(kStats.begin(), kStats.end(), out->stat) == kStats.end()) {
    std::string hint = ClosestName(out->stat, kStats);
    *error = "'" + value + "': after the column comes .last, .first, .mean, .sum, .min, .max or .rows" +
             (hint.empty() ? "" : "; did you mean '." + hint + "'?");
    return false;
  }
  return true;
}

std::vector<std::string> Cells(const std::string& line, bool commas) {
  std::vector<std::string> cells;
  if (commas) {
    for (const std::string& c : Split(line, ',')) cells.push_back(Trim(c));
    return cells;
  }
  std::istringstream in(line);
  for (std::string c; in >> c;) cells.push_back(c);
  return cells;
}

bool AllNumbers(const std::vector<std::string>& cells) {
  return std::all_of(cells.begin(), cells.end(), [](const std::string& c) { return ParseDouble(c).has_value(); });
}

/// The column's index in a table whose first row is `first`; -1 with `why`.
int ColumnIndex(const std::vector<std::string>& first, bool header, const std::string& column, std::string* why) {
  std::optional<double> n = ParseDouble(column);
  if (n && *n >= 1 && *n == static_cast<int>(*n)) return static_cast<int>(*n) - 1;
  auto it = header ? std::find(first.begin(), first.end(), column) : first.end();
  if (it != first.end()) return static_cast<int>(it - first.begin());
  std::string names;
  for (const std::string& c : first) names += (names.empty() ? "" : ", ") + c;
  *why = header ? "no column '" + column + "' (columns: " + names + ")"
                : "no header row to find '" + column + "' in: give the column's position from 1";
  return -1;
}

/// The numbers of the column, in order; false with `why`.
bool ColumnNumbers(const std::string& text, const std::string& column, std::vector<double>* out, std::string* why) {
  std::vector<std::string> lines = Split(text, '\n');
  size_t i = 0;
  while (i < lines.size() && Trim(lines[i]).empty()) ++i;
  if (i == lines.size()) {
    *why = "the file is empty";
    return false;
  }
  std::string head = Trim(lines[i]);
  const bool commas = head.find(',') != std::string::npos;
  if (!head.empty() && head[0] == '#') head = Trim(head.substr(1));
  std::vector<std::string> first = Cells(head, commas);
  const bool header = !AllNumbers(first);
  const int index = ColumnIndex(first, header, column, why);
  if (index < 0) return false;
  for (size_t k = header ? i + 1 : i; k < lines.size(); ++k) {
    const std::string line = Trim(lines[k]);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = Cells(line, commas);
    std::optional<double> v = static_cast<size_t>(index) < cells.size() ? ParseDouble(cells[index]) : std::nullopt;
    if (v) out->push_back(*v);
  }
  if (out->empty()) *why = "column '" + column + "' holds no number";
  return !out->empty();
}

double Statistic(const std::string& stat, const std::vector<double>& v) {
  if (stat == "first") return v.front();
  if (stat == "last") return v.back();
  if (stat == "rows") return static_cast<double>(v.size());
  if (stat == "min") return *std::min_element(v.begin(), v.end());
  if (stat == "max") return *std::max_element(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  return stat == "sum" ? sum : sum / static_cast<double>(v.size());
}
}  // namespace

bool IsFileValue(const std::string& value) { return value.rfind(kFileValuePrefix, 0) == 0; }

size_t RatioSlash(const std::string& text) {
  for (size_t i = 0; i < text.size(); ++i) {
    if ((i == 0 || text[i - 1] == '/') && IsFileValue(text.substr(i))) {
      i = text.find(']', i);
      if (i == std::string::npos) return std::string::npos;
    } else if (text[i] == '/') {
      return i;
    }
  }
  return std::string::npos;
}

bool CheckFileValue(const std::string& value, std::string* error) {
  FileValue v;
  return ParseFileValue(value, &v, error);
}

std::optional<double> FileColumnValue(const std::string& run_folder, const std::string& value, std::string* why) {
  FileValue v;
  if (!ParseFileValue(value, &v, why)) return std::nullopt;
  const std::string path = JoinPath(run_folder, std::string(kFileValuePrefix) + v.path);
  std::string text;
  if (!ReadFile(path, &text)) {
    std::string wrote;  // what it did write: a misspelt name shows at once
    for (const std::string& f : FilesUnder(JoinPath(run_folder, kRunFilesFolder)))
      wrote += (wrote.empty() ? "" : ", ") + std::string(kFileValuePrefix) + f;
    *why = "files/" + v.path + ": the run wrote no such file (" +
           (wrote.empty() ? "it wrote none" : "it wrote " + wrote) + ")";
    return std::nullopt;
  }
  std::vector<double> numbers;
  std::string reason;
  if (!ColumnNumbers(text, v.column, &numbers, &reason)) {
    *why = "files/" + v.path + ": " + reason;
    return std::nullopt;
  }
  return Statistic(v.stat, numbers);
}

}  // namespace essaim
