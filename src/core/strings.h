// Strict text parsing for XML attributes and the command line: no silent defaults.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/paths.h"  // DirName, JoinPath, FileExists, ReadFile lived here; kept for includers

namespace essaim {

std::vector<std::string> Split(const std::string& s, char sep);
std::string Trim(const std::string& s);
/// Whole string must be a finite number.
std::optional<double> ParseDouble(const std::string& s);
std::optional<long long> ParseInt(const std::string& s);
/// ARGoS accepts only the literals "true" and "false".
std::optional<bool> ParseBool(const std::string& s);
/// Exactly n comma-separated numbers.
std::optional<std::vector<double>> ParseVector(const std::string& s, size_t n);
/// "a:b"
std::optional<std::pair<double, double>> ParseRange(const std::string& s);
/// Shortest text that reads back as the same double ("%.17g" trimmed).
std::string FormatDouble(double v);
/// Standard base64 (RFC 4648, with padding): bytes into a page or a JSON string.
std::string Base64Encode(const std::string& bytes);
/// The candidate closest to `typed` by edit distance, or "" when none is close enough
/// (leading dashes ignored, so "--tikcs" finds "--ticks"). For "did you mean".
std::string ClosestName(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace essaim
