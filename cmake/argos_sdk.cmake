# The ARGoS API for C++ loop functions (src/argos, docs/loop-functions.md): one shared
# library holding the API over an interface to the world (argos/argos_world.h), named as
# ARGoS's core library; ARGoS's plugin libraries' names as aliases of it; the pkg-config
# file and CMake package ARGoS projects look for. In the build tree they are laid out as
# an install is, under build/argos3-sdk, so tests build projects against the build.
set(ARGOS_SDK_DIR ${CMAKE_BINARY_DIR}/argos3-sdk)
set(ARGOS_INCLUDE_SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/argos/include)

add_library(argos3core_simulator SHARED
  argos/api/session.cpp
  argos/api/space.cpp
  argos/api/entities.cpp
  argos/api/entity_specs.cpp
  argos/api/rng.cpp
  argos/api/log.cpp
  argos/api/constants.cpp
)
target_include_directories(argos3core_simulator
  PUBLIC $<BUILD_INTERFACE:${ARGOS_INCLUDE_SOURCE}> PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
# essaim_core for the random streams only; its symbols stay inside (--exclude-libs), so the
# library exports the ARGoS API and the session, nothing of essaim's.
target_link_libraries(argos3core_simulator PRIVATE essaim_core)
target_include_directories(argos3core_simulator PRIVATE $<TARGET_PROPERTY:PkgConfig::LUA,INTERFACE_INCLUDE_DIRECTORIES>)
target_link_options(argos3core_simulator PRIVATE "LINKER:--exclude-libs,ALL")
set_target_properties(argos3core_simulator PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARGOS_SDK_DIR}/lib)

set(ARGOS_ALIASES argos3plugin_simulator_entities argos3plugin_simulator_footbot argos3plugin_simulator_media)
foreach(alias ${ARGOS_ALIASES})
  add_library(${alias} SHARED argos/api/library_alias.cpp)
  target_link_libraries(${alias} PRIVATE argos3core_simulator)
  target_link_options(${alias} PRIVATE "LINKER:--no-as-needed")
  set_target_properties(${alias} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARGOS_SDK_DIR}/lib INSTALL_RPATH "$ORIGIN")
endforeach()

# The host side: loading libraries, driving the session over the EntityStore.
add_library(essaim_argos STATIC
  argos/store_world.cpp
  argos/cpp_loop_functions.cpp
  argos/plugin_libraries.cpp
  argos/lua_linkage.cpp
)
target_include_directories(essaim_argos PRIVATE ${ARGOS_INCLUDE_SOURCE})
add_dependencies(essaim_argos ${ARGOS_ALIASES})
target_link_libraries(essaim_argos PUBLIC essaim_lua_robot argos3core_simulator ${CMAKE_DL_LIBS} PRIVATE PkgConfig::LUA)

# pkg-config file, CMake package and ARGoS's cmake helpers: for the build tree, then the install.
get_target_property(lua_includes PkgConfig::LUA INTERFACE_INCLUDE_DIRECTORIES)
set(ARGOS_PC_LUA_CFLAGS "")
set(ARGOS_CONFIG_LUA_INCLUDE "")
foreach(dir ${lua_includes})
  string(APPEND ARGOS_PC_LUA_CFLAGS " -I${dir}")
  string(APPEND ARGOS_CONFIG_LUA_INCLUDE " \"${dir}\"")
endforeach()
# The build tree's names absolute paths; the install's are relative to where the files
# are (pkg-config's ${pcfiledir}, CMake's CMAKE_CURRENT_LIST_DIR), so it can be moved.
function(essaim_argos_package out pc_prefix pc_libdir pc_includedir config_prefix config_includedir)
  set(ARGOS_PC_PREFIX ${pc_prefix})
  set(ARGOS_PC_LIBDIR ${pc_libdir})
  set(ARGOS_PC_INCLUDEDIR ${pc_includedir})
  set(ARGOS_CONFIG_PREFIX ${config_prefix})
  set(ARGOS_CONFIG_INCLUDEDIR ${config_includedir})
  configure_file(${PROJECT_SOURCE_DIR}/cmake/argos3_simulator.pc.in ${out}/lib/pkgconfig/argos3_simulator.pc @ONLY)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/ARGoSConfig.cmake.in ${out}/lib/cmake/ARGoS/ARGoSConfig.cmake @ONLY)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/ARGoSCheckQTOpenGL.cmake ${out}/share/argos3/cmake/ARGoSCheckQTOpenGL.cmake
                 COPYONLY)
endfunction()
essaim_argos_package(${ARGOS_SDK_DIR} ${ARGOS_SDK_DIR} ${ARGOS_SDK_DIR}/lib ${ARGOS_INCLUDE_SOURCE}
                     ${ARGOS_SDK_DIR} ${ARGOS_INCLUDE_SOURCE})
essaim_argos_package(${CMAKE_BINARY_DIR}/argos3-install "\${pcfiledir}/../.." "\${prefix}/lib" "\${prefix}/include"
                     "\${CMAKE_CURRENT_LIST_DIR}/../../.." "\${CMAKE_CURRENT_LIST_DIR}/../../../include")

install(TARGETS argos3core_simulator ${ARGOS_ALIASES} LIBRARY DESTINATION lib)
install(DIRECTORY ${ARGOS_INCLUDE_SOURCE}/argos3 DESTINATION include)
install(DIRECTORY ${CMAKE_BINARY_DIR}/argos3-install/ DESTINATION .)
