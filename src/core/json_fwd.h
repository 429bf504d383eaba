// essaim::Json by declaration only, for headers that pass documents around (keeps the
// full nlohmann/json header out of most translation units).
#pragma once
#include <nlohmann/json_fwd.hpp>

namespace essaim {
/// A JSON document; objects keep insertion order, so output is deterministic.
using Json = nlohmann::ordered_json;
}  // namespace essaim
