#include "core/error_list.h"

namespace essaim {

void ErrorList::Add(std::string file, int line, std::string element, std::string message) {
  errors_.push_back({std::move(file), line, std::move(element), std::move(message)});
}

void ErrorList::Append(const ErrorList& other) {
  errors_.insert(errors_.end(), other.errors_.begin(), other.errors_.end());
}

std::string ErrorList::Format() const {
  std::string out;
  for (const InputError& e : errors_) {
    out += e.file;
    if (e.line > 0) out += ":" + std::to_string(e.line);
    out += ": ";
    if (!e.element.empty()) out += "<" + e.element + ">: ";
    out += e.message + "\n";
  }
  return out;
}

}  // namespace essaim
