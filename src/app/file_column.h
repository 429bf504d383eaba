// An `essaim test` value read from a file the run's scripts wrote (docs/testing.md, "Files
// the run wrote"): files/PATH[COLUMN].STAT, e.g. files/zone_counts.txt[count].last. PATH is
// as summary.json's "files" lists it, below the run folder's files/; the file is a table,
// comma-separated when its first row holds a comma, else whitespace-separated; COLUMN a name
// of its header row (a first row that is not all numbers; a leading '#' is dropped) or a
// position from 1; lines starting with '#' after the header are comments; rows whose cell is
// not a number are passed over. STAT: last, first, mean, sum, min, max, rows.
#pragma once
#include <optional>
#include <string>

namespace essaim {

/// The prefix that makes a value a file column.
constexpr const char* kFileValuePrefix = "files/";

/// Whether `value` names a file column (starts with files/).
bool IsFileValue(const std::string& value);
/// Where `text` splits into A/B: the first '/' outside a files/...] part; npos when none.
size_t RatioSlash(const std::string& text);
/// False with a message when `value` is not files/PATH[COLUMN].STAT.
bool CheckFileValue(const std::string& value, std::string* error);
/// The value in the run whose folder is `run_folder`; nothing with `why` (the file or the
/// column missing, no number in it) otherwise.
std::optional<double> FileColumnValue(const std::string& run_folder, const std::string& value, std::string* why);

}  // namespace essaim
