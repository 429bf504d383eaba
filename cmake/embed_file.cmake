# Turns a text file into a C++ source defining `const char SYMBOL[]` (NUL-terminated) and
# `const std::size_t SYMBOL_size`, so big templates (the replay page) stay editable files
# instead of string literals. Run at build time:
#   cmake -DINPUT=in.html -DOUTPUT=out.cpp -DSYMBOL=kName -P cmake/embed_file.cmake
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR size "${hex_length} / 2")
# 0x.. bytes, 32 to a line.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "((0x..,){32})" "\\1\n" bytes "${bytes}")
get_filename_component(name "${INPUT}" NAME)
file(WRITE "${OUTPUT}"
  "// Generated from ${name} by cmake/embed_file.cmake: edit the source file, not this one.\n"
  "#include <cstddef>\n"
  "namespace essaim {\n"
  "extern const char ${SYMBOL}[] = {\n${bytes}0x00};\n"
  "extern const std::size_t ${SYMBOL}_size = ${size};\n"
  "}  // namespace essaim\n")
