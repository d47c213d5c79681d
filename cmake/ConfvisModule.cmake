# confvis_module(NAME DIR DEPS...): a library (static, or shared with CONFVIS_SHARED_LIBS: the
# root CMakeLists.txt sets CONFVIS_LIBRARY_TYPE) from DIR/src/**.cpp with public headers in
# DIR/include. Unit tests live beside each module in DIR/test/*_test.cpp and are collected into
# the single test binary by tests/CMakeLists.txt (pbrt-v4 style: one binary, tests near code).
set_property(GLOBAL PROPERTY CONFVIS_TEST_SOURCES "")

# Packaging (cmake/ConfvisInstall.cmake, included once at the end of the root CMakeLists.txt):
# every module library registers itself here and is installed and exported as confvis::NAME
# (the "confvis_" prefix dropped), its include/ folder installed beside the others.
set_property(GLOBAL PROPERTY CONFVIS_INSTALL_TARGETS "")
set_property(GLOBAL PROPERTY CONFVIS_INSTALL_INCLUDE_DIRS "")

function(confvis_install_module name include_dir)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_INSTALL_TARGETS ${name})
  set_property(GLOBAL APPEND PROPERTY CONFVIS_INSTALL_INCLUDE_DIRS ${include_dir})
  set_property(GLOBAL PROPERTY CONFVIS_LAST_MODULE ${name})
  # The name an application uses, here (add_subdirectory(confvis)) as after find_package.
  string(REGEX REPLACE "^confvis_" "" component ${name})
  add_library(confvis::${component} ALIAS ${name})
endfunction()

# confvis_package_dependency("embree 3"): the module registered last (confvis_module just before
# the call) links this package (publicly, or privately: static libraries carry their private
# dependencies to the consumer's link line), so the generated confvisConfig.cmake runs
# find_dependency(embree 3) when an application asks for that module's component. The packages
# every module needs are listed in cmake/ConfvisInstall.cmake.
function(confvis_package_dependency arguments)
  get_property(module GLOBAL PROPERTY CONFVIS_LAST_MODULE)
  if(NOT module)
    message(FATAL_ERROR "confvis_package_dependency(${arguments}) before any confvis_module")
  endif()
  set_property(GLOBAL APPEND PROPERTY CONFVIS_PACKAGE_DEPENDENCIES_${module} "${arguments}")
endfunction()

function(confvis_module name dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/*.cpp)
  add_library(${name} ${CONFVIS_LIBRARY_TYPE} ${sources})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${dir}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARGN})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${name})
  confvis_install_module(${name} ${dir}/include)
endfunction()

# confvis_module_sources(NAME DIR SUBDIR DEPS...): like confvis_module, but for a module that
# shares DIR with another (engine/ holds confvis_base in src/base and confvis_engine in
# src/engine); sources from DIR/src/SUBDIR, tests from DIR/test/SUBDIR.
function(confvis_module_sources name dir subdir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/${subdir}/*.cpp)
  add_library(${name} ${CONFVIS_LIBRARY_TYPE} ${sources})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${dir}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARGN})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/${subdir}/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${name})
  confvis_install_module(${name} ${dir}/include)
endfunction()
