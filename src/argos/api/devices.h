// Inside the ARGoS API library: the sensor and actuator objects a C++ controller gets, one
// per (tag, implementation) its .argos element declares, each ARGoS's simulator class.
#pragma once
#include <string>

#include "argos/api/session_state.h"

namespace essaim {

/// Makes the object for `device`, bound to `io`, started as ARGoS's Init starts it, owned
/// by `slot` and added to its controller under the tag; throws naming `where` when essaim
/// has no class for the pair.
void AddDevice(const ArgosDeviceDecl& device, ArgosRobotIo* io, const std::string& where, ArgosControllerSlot& slot);

}  // namespace essaim
