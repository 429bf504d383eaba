// User-input errors, collected rather than thrown: the loader reports every problem at
// once with file, line and element (MuJoCo's error buffer, Jolt's Result).
#pragma once
#include <string>
#include <vector>

namespace essaim {

struct InputError {
  std::string file;
  int line = 0;         // 0 when unknown
  std::string element;  // XML element tag, or empty
  std::string message;
};

class ErrorList {
 public:
  void Add(std::string file, int line, std::string element, std::string message);
  void Append(const ErrorList& other);
  bool Empty() const { return errors_.empty(); }
  size_t Size() const { return errors_.size(); }
  const std::vector<InputError>& Items() const { return errors_; }
  /// "file:line: <element>: message", one per line; identical lines once, with " (N times)".
  std::string Format() const;

 private:
  std::vector<InputError> errors_;
};

}  // namespace essaim
