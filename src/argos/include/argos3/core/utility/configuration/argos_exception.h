// ARGoS's exception (argos3/core/utility/configuration/argos_exception.h). A hook that
// throws it ends the run with its message and where it was thrown (exit 1).
#pragma once
#include <sstream>
#include <stdexcept>
#include <string>

namespace argos {

class CARGoSException : public std::exception {
 public:
  explicit CARGoSException(const std::string& str_what, const char* str_file = "", int n_line = 0)
      : m_strWhat(str_what), m_strFile(str_file), m_nLine(n_line) {}
  /// Keeps the cause's message after this one's, as ARGoS prints a nested exception.
  CARGoSException(const std::string& str_what, const std::exception& c_nested, const char* str_file = "",
                  int n_line = 0)
      : CARGoSException(str_what + "\n[NESTED] " + c_nested.what(), str_file, n_line) {
    const CARGoSException* pcNested = dynamic_cast<const CARGoSException*>(&c_nested);
    m_bConfiguration = pcNested && pcNested->IsConfigurationError();
  }
  const char* what() const noexcept override { return m_strWhat.c_str(); }
  /// The source file and line of the THROW_ARGOSEXCEPTION that made it ("" and 0 otherwise).
  const std::string& GetFile() const { return m_strFile; }
  int GetLine() const { return m_nLine; }
  /// essaim: thrown (or caused, when nested) by the configuration helpers on a bad
  /// .argos element, whose message names the file and line: bad input, exit 2.
  bool IsConfigurationError() const { return m_bConfiguration; }
  static CARGoSException Configuration(const std::string& str_what) {
    CARGoSException cException(str_what);
    cException.m_bConfiguration = true;
    return cException;
  }

 private:
  std::string m_strWhat;
  std::string m_strFile;
  int m_nLine;
  bool m_bConfiguration = false;
};

}  // namespace argos

/// Throws a CARGoSException whose message is `message` written to a stream (`"x=" << x`).
#define THROW_ARGOSEXCEPTION(message)                                                \
  {                                                                                  \
    std::ostringstream argos_exception_message;                                      \
    argos_exception_message << message;                                              \
    throw argos::CARGoSException(argos_exception_message.str(), __FILE__, __LINE__); \
  }

#define THROW_ARGOSEXCEPTION_NESTED(message, nested)                                         \
  {                                                                                          \
    std::ostringstream argos_exception_message;                                              \
    argos_exception_message << message;                                                      \
    throw argos::CARGoSException(argos_exception_message.str(), nested, __FILE__, __LINE__); \
  }
