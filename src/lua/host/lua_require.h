// `require` reports the files it loads, so a run's inputs include every module its
// controllers and loop functions use (summary.json's "inputs").
#pragma once

struct lua_State;

namespace essaim {

class InputFiles;

/// Wraps package.searchers[2] (Lua files on package.path, the sandbox's text-only one
/// included): each module file it finds is added to `inputs` as a "module". Null: nothing.
/// A guarded state's package not opened yet is wrapped when it opens.
void RecordRequiredFiles(lua_State* L, InputFiles* inputs);

/// The same on the package table at stack index `package`.
void WrapModuleSearcher(lua_State* L, int package, InputFiles* inputs);

}  // namespace essaim
