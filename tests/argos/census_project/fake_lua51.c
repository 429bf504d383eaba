/* Stands for Debian's liblua5.1.so.0 in the linkage test: a library of that name that
   defines a Lua function. */
int lua_gettop(void* L) { return L != 0; }
