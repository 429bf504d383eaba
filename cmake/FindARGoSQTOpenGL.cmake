# find_package(ARGoSQTOpenGL), as ARGoS 3.0.0-beta59 installs it in share/argos3/cmake: whether
# Qt/OpenGL user functions can be built. essaim has no window, so they cannot: a project then
# builds without them, as it does on an ARGoS built without Qt.
set(ARGOS_QTOPENGL_FOUND FALSE)
set(ARGOS_QTOPENGL_INCLUDE_DIRS "")
set(ARGOS_QTOPENGL_LIBRARIES "")
if(NOT ARGoSQTOpenGL_FIND_QUIETLY)
  message(STATUS "essaim's ARGoS API: no Qt/OpenGL user functions (essaim is headless)")
endif()
if(ARGoSQTOpenGL_FIND_REQUIRED)
  message(FATAL_ERROR "essaim has no Qt/OpenGL user functions (essaim is headless): build without them")
endif()
