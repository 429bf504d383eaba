# The ARGoS API for C++ loop functions (src/argos, docs/loop-functions.md): one shared
# library holding the API over an interface to the world (argos/argos_world.h), under essaim's
# own soname; the names ARGoS's libraries have as symbolic links to it; the pkg-config file and
# CMake package ARGoS projects look for. In the build tree they are laid out as an install is,
# under build/argos3-sdk, so tests build projects against the build.
set(ARGOS_SDK_DIR ${CMAKE_BINARY_DIR}/argos3-sdk)
set(ARGOS_INCLUDE_SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/argos/include)

add_library(essaim_argos_api SHARED
  argos/api/session.cpp
  argos/api/space.cpp
  argos/api/entities.cpp
  argos/api/entity_specs.cpp
  argos/api/rng.cpp
  argos/api/log.cpp
  argos/api/controllers.cpp
  argos/api/devices.cpp
  argos/api/sensors.cpp
  argos/api/actuators.cpp
  argos/api/constants.cpp
)
target_include_directories(essaim_argos_api
  PUBLIC $<BUILD_INTERFACE:${ARGOS_INCLUDE_SOURCE}> PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
# essaim_core for the random streams only; its symbols stay inside (--exclude-libs), so the
# library exports the ARGoS API and the session, nothing of essaim's.
target_link_libraries(essaim_argos_api PRIVATE essaim_core ${CMAKE_DL_LIBS})
target_include_directories(essaim_argos_api PRIVATE $<TARGET_PROPERTY:PkgConfig::LUA,INTERFACE_INCLUDE_DIRECTORIES>)
target_link_options(essaim_argos_api PRIVATE "LINKER:--exclude-libs,ALL")
# The soname (libessaim_argos_api.so.1) is what essaim and every project linked against it
# record: an ARGoS installed beside essaim (its libargos3core_simulator.so on LD_LIBRARY_PATH
# or in ld.so.conf) is never loaded in its place. Version mismatches are caught by
# REGISTER_LOOP_FUNCTIONS's API version, with a clear message, so the soname stays .1.
set_target_properties(essaim_argos_api PROPERTIES SOVERSION 1 LIBRARY_OUTPUT_DIRECTORY ${ARGOS_SDK_DIR}/lib)

# Every library ARGoS installs for the simulator build (its CMakeLists: the one core library
# and the plugins), as a symbolic link to essaim's: `-largos3plugin_simulator_footbot` (or the
# file's path) makes the linker read essaim's library and record its soname.
set(ARGOS_LIBRARY_NAMES argos3core_simulator)
foreach(plugin block builderbot drone dynamics2d dynamics3d dynamics3d_floor dynamics3d_gravity
               dynamics3d_magnetism dynamics3d_srocs entities epuck eyebot footbot genericrobot media pipuck
               pointmass3d prototype qtopengl spiri)
  list(APPEND ARGOS_LIBRARY_NAMES argos3plugin_simulator_${plugin})
endforeach()
set(ARGOS_LIBRARY_LINKS "")
set(link_commands "")
foreach(name ${ARGOS_LIBRARY_NAMES})
  set(link ${ARGOS_SDK_DIR}/lib/lib${name}.so)
  list(APPEND ARGOS_LIBRARY_LINKS ${link})
  list(APPEND link_commands COMMAND ${CMAKE_COMMAND} -E rm -f ${link}
       COMMAND ${CMAKE_COMMAND} -E create_symlink $<TARGET_SONAME_FILE_NAME:essaim_argos_api> ${link})
endforeach()
add_custom_command(TARGET essaim_argos_api POST_BUILD ${link_commands} VERBATIM)

# The host side: loading libraries, driving the session over the EntityStore.
add_library(essaim_argos STATIC
  argos/store_world.cpp
  argos/argos_host.cpp
  argos/config_tree.cpp
  argos/cpp_loop_functions.cpp
  argos/cpp_controller.cpp
  argos/robot_io.cpp
  argos/plugin_libraries.cpp
  argos/lua_linkage.cpp
  argos/library_group.cpp
)
target_include_directories(essaim_argos PRIVATE ${ARGOS_INCLUDE_SOURCE})
target_link_libraries(essaim_argos PUBLIC essaim_lua_robot essaim_argos_api ${CMAKE_DL_LIBS} PRIVATE PkgConfig::LUA)

# pkg-config file, CMake package and ARGoS's cmake helpers: for the build tree, then the install.
get_target_property(lua_includes PkgConfig::LUA INTERFACE_INCLUDE_DIRECTORIES)
list(GET lua_includes 0 ARGOS_LUA_INCLUDE_DIR)  # the Lua 5.4 FindLua52/53 give (FindArgosLua.cmake.in)
list(GET LUA_LINK_LIBRARIES 0 ARGOS_LUA_LIBRARY)
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
  configure_file(${PROJECT_SOURCE_DIR}/cmake/FindARGoSQTOpenGL.cmake ${out}/share/argos3/cmake/FindARGoSQTOpenGL.cmake
                 COPYONLY)
  # The Lua finders older ARGoS releases installed (FindLua52 to beta55, FindLua53 after).
  foreach(ARGOS_LUA_PACKAGE Lua52 Lua53)
    configure_file(${PROJECT_SOURCE_DIR}/cmake/FindArgosLua.cmake.in
                   ${out}/share/argos3/cmake/Find${ARGOS_LUA_PACKAGE}.cmake @ONLY)
  endforeach()
endfunction()
essaim_argos_package(${ARGOS_SDK_DIR} ${ARGOS_SDK_DIR} ${ARGOS_SDK_DIR}/lib ${ARGOS_INCLUDE_SOURCE}
                     ${ARGOS_SDK_DIR} ${ARGOS_INCLUDE_SOURCE})
essaim_argos_package(${CMAKE_BINARY_DIR}/argos3-install "\${pcfiledir}/../.." "\${prefix}/lib" "\${prefix}/include"
                     "\${CMAKE_CURRENT_LIST_DIR}/../../.." "\${CMAKE_CURRENT_LIST_DIR}/../../../include")

install(TARGETS essaim_argos_api LIBRARY DESTINATION lib)
install(FILES ${ARGOS_LIBRARY_LINKS} DESTINATION lib)  # installed as the links they are
install(DIRECTORY ${ARGOS_INCLUDE_SOURCE}/argos3 DESTINATION include)
install(DIRECTORY ${CMAKE_BINARY_DIR}/argos3-install/ DESTINATION .)
