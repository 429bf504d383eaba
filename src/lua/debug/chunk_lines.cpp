// Reads Lua 5.4's binary chunk format (ldump.c/lundump.c of 5.4.4) only as far as the line
// information of each function prototype.
#include "lua/debug/chunk_lines.h"

#include <cstdint>
#include <lua.hpp>
#include <vector>

namespace essaim {

namespace {
constexpr int kAbsLineInfo = -0x80;  // ldebug.h's ABSLINEINFO

int CollectDump(lua_State*, const void* p, size_t size, void* ud) {
  auto* out = static_cast<std::string*>(ud);
  out->append(static_cast<const char*>(p), size);
  return 0;
}

/// A cursor over the dump; every read past the end sets `bad`.
struct Reader {
  const std::string& bytes;
  size_t at = 0;
  bool bad = false;

  uint8_t Byte() {
    if (at >= bytes.size()) {
      bad = true;
      return 0;
    }
    return static_cast<uint8_t>(bytes[at++]);
  }
  void Skip(size_t n) {
    if (bytes.size() - at < n) bad = true;
    at = bad ? bytes.size() : at + n;
  }
  size_t Size() {  // lundump.c's loadUnsigned: 7 bits a byte, the last with 0x80
    size_t x = 0;
    for (int i = 0; i < 10 && !bad; ++i) {
      const uint8_t b = Byte();
      x = (x << 7) | (b & 0x7f);
      if (b & 0x80) return x;
    }
    bad = true;
    return 0;
  }
  void SkipString() {
    const size_t n = Size();
    if (n > 0) Skip(n - 1);
  }
};

void SkipConstants(Reader& r) {
  const size_t n = r.Size();
  for (size_t i = 0; i < n && !r.bad; ++i) {
    const int tag = r.Byte();
    if (tag == LUA_TNUMBER || tag == (LUA_TNUMBER | (1 << 4)))
      r.Skip(8);  // lua_Integer or lua_Number
    else if ((tag & 0x0f) == LUA_TSTRING)
      r.SkipString();
  }
}

void ReadFunction(Reader& r, std::set<int>* lines);

// The prototype's instructions' lines (ldebug.c's collectvalidlines), then its children.
void ReadLines(Reader& r, int linedefined, bool vararg, size_t code_size, std::set<int>* lines) {
  const size_t n = r.Size();
  std::vector<int8_t> deltas(n);
  for (size_t i = 0; i < n; ++i) deltas[i] = static_cast<int8_t>(r.Byte());
  const size_t nabs = r.Size();
  std::vector<std::pair<size_t, int>> absolute(nabs);
  for (auto& a : absolute) {
    a.first = r.Size();
    a.second = static_cast<int>(r.Size());
  }
  int line = linedefined;
  size_t next_abs = 0;
  for (size_t pc = 0; pc < n && pc < code_size; ++pc) {
    if (deltas[pc] != kAbsLineInfo)
      line += deltas[pc];
    else if (next_abs < absolute.size())
      line = absolute[next_abs++].second;
    if (!(vararg && pc == 0)) lines->insert(line);  // a vararg function's VARARGPREP is not a line
  }
}

void ReadFunction(Reader& r, std::set<int>* lines) {
  r.SkipString();  // source
  const int linedefined = static_cast<int>(r.Size());
  r.Size();   // lastlinedefined
  r.Skip(1);  // numparams
  const bool vararg = r.Byte() != 0;
  r.Skip(1);  // maxstacksize
  const size_t code_size = r.Size();
  r.Skip(code_size * 4);
  SkipConstants(r);
  r.Skip(r.Size() * 3);  // upvalues: instack, idx, kind
  const size_t protos = r.Size();
  for (size_t i = 0; i < protos && !r.bad; ++i) ReadFunction(r, lines);
  ReadLines(r, linedefined, vararg, code_size, lines);
  const size_t locals = r.Size();
  for (size_t i = 0; i < locals && !r.bad; ++i) {
    r.SkipString();
    r.Size();
    r.Size();
  }
  const size_t upnames = r.Size();
  for (size_t i = 0; i < upnames && !r.bad; ++i) r.SkipString();
}

// lundump.c's checkHeader: signature, version, format, LUAC_DATA, sizes, LUAC_INT, LUAC_NUM,
// then the main closure's upvalue count.
constexpr size_t kHeaderSize = 4 + 1 + 1 + 6 + 3 + 8 + 8 + 1;

bool LinesOfLoaded(lua_State* L, std::set<int>* lines, std::string* error) {
  std::string dump;
  lua_dump(L, CollectDump, &dump, 0);
  Reader r{dump};
  r.Skip(kHeaderSize);
  ReadFunction(r, lines);
  if (r.bad) *error = "unexpected compiled chunk layout";
  return !r.bad;
}

bool LinesOf(lua_State* L, int loaded, std::set<int>* lines, std::string* error) {
  bool ok = loaded == LUA_OK;
  if (!ok)
    *error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "does not load";
  else
    ok = LinesOfLoaded(L, lines, error);
  lua_close(L);
  return ok;
}
}  // namespace

bool ActiveLinesOfFile(const std::string& path, std::set<int>* lines, std::string* error) {
  lua_State* L = luaL_newstate();
  return LinesOf(L, luaL_loadfilex(L, path.c_str(), "t"), lines, error);
}

bool ActiveLinesOfText(const std::string& text, const std::string& chunkname, std::set<int>* lines,
                       std::string* error) {
  lua_State* L = luaL_newstate();
  return LinesOf(L, luaL_loadbufferx(L, text.data(), text.size(), chunkname.c_str(), "t"), lines, error);
}

int NextActiveLine(const std::set<int>& lines, int line) {
  auto it = lines.lower_bound(line);
  return it == lines.end() ? 0 : *it;
}

}  // namespace essaim
