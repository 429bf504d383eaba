#include "core/error_list.h"

#include <algorithm>

namespace essaim {

void ErrorList::Add(std::string file, int line, std::string element, std::string message) {
  errors_.push_back({std::move(file), line, std::move(element), std::move(message)});
}

void ErrorList::Append(const ErrorList& other) {
  errors_.insert(errors_.end(), other.errors_.begin(), other.errors_.end());
}

std::string ErrorList::Format() const {
  // Identical entries (a bad reference in a <distribute> of 189 robots) print once, counted.
  std::vector<std::string> lines;
  std::vector<size_t> counts;
  for (const InputError& e : errors_) {
    std::string line = e.file;
    if (e.line > 0) line += ":" + std::to_string(e.line);
    line += ": ";
    if (!e.element.empty()) line += "<" + e.element + ">: ";
    line += e.message;
    auto it = std::find(lines.begin(), lines.end(), line);
    if (it != lines.end()) {
      ++counts[static_cast<size_t>(it - lines.begin())];
    } else {
      lines.push_back(std::move(line));
      counts.push_back(1);
    }
  }
  std::string out;
  for (size_t i = 0; i < lines.size(); ++i) {
    out += lines[i];
    if (counts[i] > 1) out += " (" + std::to_string(counts[i]) + " times)";
    out += "\n";
  }
  return out;
}

}  // namespace essaim
