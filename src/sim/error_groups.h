// Controller errors as printed: robots that failed the same way in the same stage are one
// message with a count, not one line per robot (189 identical init errors are one).
#pragma once
#include <string>
#include <vector>

#include "sim/world.h"

namespace essaim {

/// errors[from..] grouped by their text after the "robot <id>: " prefix, in first-seen
/// order: the first robot's message, then "(the same error in N more robots: a, b, ...)".
std::vector<std::string> GroupControllerErrors(const std::vector<ControllerError>& errors, size_t from);

}  // namespace essaim
