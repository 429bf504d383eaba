// ARGoS splits its API over libraries that projects link by name (argos3plugin_simulator_
// entities, _footbot, _media). essaim's API is one library, libargos3core_simulator; each
// of those names is a library with nothing of its own that depends on it, so that
// `-largos3plugin_simulator_footbot` links and loads the one API.
