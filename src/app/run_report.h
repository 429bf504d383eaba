// What `run` and `check` say about a run beyond its errors: parameters nothing read.
#pragma once
#include <string>

#include "sim/world.h"

namespace essaim {

/// One line per unread parameter, "FILE:LINE: <element>: warning: parameter ... never read
/// by SCRIPT; did you mean ...?" ("error:" instead of "warning:" when `as_errors`).
std::string FormatUnreadParams(const std::vector<UnreadParam>& unread, bool as_errors);

}  // namespace essaim
