# Packaging, included once at the end of the root CMakeLists.txt: `cmake --install build` installs
# every module library registered by cmake/ConfvisModule.cmake, their public headers, the confvis
# CLI, the shipped display configs and the GLSL warp include, plus a CMake package, so an
# application writes
#   find_package(confvis REQUIRED)                          # every component
#   find_package(confvis REQUIRED COMPONENTS conformal)     # views and maps: no Embree, TBB, Vulkan
#   target_link_libraries(app PRIVATE confvis::confvis)     # the components found
# Each module is a component, exported as confvis::<module> (confvis_engine -> confvis::engine) in
# its own export set; the config finds a component's packages only when the component (or one
# that needs it) is asked for. A module that links a package beyond the core list below declares
# it with confvis_package_dependency("NAME [VERSION] [ARGS]") right after its confvis_module.
# The installed tree is relocatable: every path in the package is relative to its prefix.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(confvis_install_targets GLOBAL PROPERTY CONFVIS_INSTALL_TARGETS)
get_property(confvis_install_include_dirs GLOBAL PROPERTY CONFVIS_INSTALL_INCLUDE_DIRS)
get_property(confvis_install_shaders GLOBAL PROPERTY CONFVIS_INSTALL_SHADERS)
list(REMOVE_DUPLICATES confvis_install_include_dirs)

set(confvis_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/confvis)
set(CONFVIS_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/confvis)

# "confvis" is the CLI's target name, so the umbrella target is confvis_all in this tree (alias
# confvis::confvis, as for add_subdirectory(confvis) users); the installed package makes its own
# confvis::confvis from the components it found (confvisConfig.cmake.in).
add_library(confvis_all INTERFACE)
target_link_libraries(confvis_all INTERFACE ${confvis_install_targets})
add_library(confvis::confvis ALIAS confvis_all)

# Per component: its export set, the components it links, the packages it declared.
set(CONFVIS_COMPONENTS "")
set(CONFVIS_COMPONENT_TABLE "")
foreach(target IN LISTS confvis_install_targets)
  string(REGEX REPLACE "^confvis_" "" component ${target})
  list(APPEND CONFVIS_COMPONENTS ${component})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${component})
  # Each library is also an install component of its own name (cmake --install --component
  # engine), so a partial build installs what it built: headers, configs and the package files
  # are the component Unspecified, the CLI the component cli.
  install(TARGETS ${target} EXPORT confvis-${component}-targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${component}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${component}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT confvis-${component}-targets NAMESPACE confvis::
    DESTINATION ${confvis_package_dir})

  get_target_property(links ${target} LINK_LIBRARIES)
  set(requires "")
  foreach(link IN LISTS links)
    if(link IN_LIST confvis_install_targets)
      string(REGEX REPLACE "^confvis_" "" linked ${link})
      list(APPEND requires ${linked})
    endif()
  endforeach()
  get_property(packages GLOBAL PROPERTY CONFVIS_PACKAGE_DEPENDENCIES_${target})
  set(find_lines "")
  foreach(package IN LISTS packages)
    string(APPEND find_lines " [[${package}]]")
  endforeach()
  string(APPEND CONFVIS_COMPONENT_TABLE
    "set(_confvis_requires_${component} ${requires})\n"
    "set(_confvis_packages_${component}${find_lines})\n")
endforeach()

foreach(dir IN LISTS confvis_install_include_dirs)
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
if(TARGET confvis)
  install(TARGETS confvis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/configs/ DESTINATION ${CONFVIS_DATA_INSTALL_DIR}/configs)
install(FILES ${confvis_install_shaders} DESTINATION ${CONFVIS_DATA_INSTALL_DIR}/shaders)

# The packages every module needs (static libraries pass their private dependencies on to the
# consumer's link line, so those count too), as found in the root CMakeLists.txt.
set(confvis_core_dependencies
  "Threads" "Eigen3 3.3 NO_MODULE" "OpenMesh" "nlohmann_json 3" "OpenEXR 3" "PNG" "glm"
  "tinyobjloader" "TinyGLTF")
set(CONFVIS_FIND_DEPENDENCIES "")
foreach(dependency IN LISTS confvis_core_dependencies)
  string(APPEND CONFVIS_FIND_DEPENDENCIES "find_dependency(${dependency})\n")
endforeach()

list(JOIN CONFVIS_COMPONENTS ", " CONFVIS_COMPONENTS_TEXT)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/confvisConfig.cmake.in
  ${PROJECT_BINARY_DIR}/confvisConfig.cmake
  INSTALL_DESTINATION ${confvis_package_dir}
  PATH_VARS CONFVIS_DATA_INSTALL_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/confvisConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/confvisConfig.cmake
  ${PROJECT_BINARY_DIR}/confvisConfigVersion.cmake DESTINATION ${confvis_package_dir})
