# ARGoS projects include this (from ${ARGOS_PREFIX}/share/argos3/cmake) to learn whether Qt
# user functions can be built. essaim has no window and no Qt user functions, so the answer
# is no: a project then builds its loop functions without them.
set(ARGOS_COMPILE_QTOPENGL FALSE)
message(STATUS "essaim's ARGoS API: no Qt/OpenGL user functions (essaim is headless)")
