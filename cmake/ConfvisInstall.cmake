# Packaging, included once at the end of the root CMakeLists.txt: `cmake --install build` installs
# every module library registered by cmake/ConfvisModule.cmake, their public headers, the confvis
# CLI and the shipped display configs, plus a CMake package, so an application writes
#   find_package(confvis REQUIRED)
#   target_link_libraries(app PRIVATE confvis::confvis)
# Module targets are exported as confvis::<module> (confvis_engine -> confvis::engine); the
# umbrella target confvis::confvis links them all. A module that links a package beyond the core
# list below declares it with confvis_package_dependency("NAME [VERSION] [ARGS]").
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(confvis_install_targets GLOBAL PROPERTY CONFVIS_INSTALL_TARGETS)
get_property(confvis_install_include_dirs GLOBAL PROPERTY CONFVIS_INSTALL_INCLUDE_DIRS)
get_property(confvis_extra_dependencies GLOBAL PROPERTY CONFVIS_PACKAGE_DEPENDENCIES)
list(REMOVE_DUPLICATES confvis_install_include_dirs)

foreach(target IN LISTS confvis_install_targets)
  string(REGEX REPLACE "^confvis_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
endforeach()

# "confvis" is the CLI's target name, so the umbrella target is confvis_all in this tree and
# confvis::confvis everywhere else (the alias makes in-tree code read the same).
add_library(confvis_all INTERFACE)
target_link_libraries(confvis_all INTERFACE ${confvis_install_targets})
set_target_properties(confvis_all PROPERTIES EXPORT_NAME confvis)
add_library(confvis::confvis ALIAS confvis_all)

install(TARGETS ${confvis_install_targets} confvis_all EXPORT confvisTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir IN LISTS confvis_install_include_dirs)
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
if(TARGET confvis)
  install(TARGETS confvis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
set(CONFVIS_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/confvis)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/configs/ DESTINATION ${CONFVIS_DATA_INSTALL_DIR}/configs)

set(confvis_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/confvis)
install(EXPORT confvisTargets NAMESPACE confvis:: DESTINATION ${confvis_package_dir})

# The packages the module libraries link (static libraries pass their private dependencies on
# to the consumer's link line, so those count too), as found in the root CMakeLists.txt.
set(confvis_dependencies
  "Threads" "Eigen3 3.3 NO_MODULE" "OpenMesh" "nlohmann_json 3" "OpenEXR 3" "PNG" "glm"
  "tinyobjloader" "TinyGLTF" ${confvis_extra_dependencies})
list(REMOVE_DUPLICATES confvis_dependencies)
set(CONFVIS_FIND_DEPENDENCIES "")
foreach(dependency IN LISTS confvis_dependencies)
  string(APPEND CONFVIS_FIND_DEPENDENCIES "find_dependency(${dependency})\n")
endforeach()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/confvisConfig.cmake.in
  ${PROJECT_BINARY_DIR}/confvisConfig.cmake
  INSTALL_DESTINATION ${confvis_package_dir}
  PATH_VARS CONFVIS_DATA_INSTALL_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/confvisConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/confvisConfig.cmake
  ${PROJECT_BINARY_DIR}/confvisConfigVersion.cmake DESTINATION ${confvis_package_dir})
