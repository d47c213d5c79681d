# confvis_module(NAME DIR DEPS...): a library (static, or shared with CONFVIS_SHARED_LIBS: the
# root CMakeLists.txt sets CONFVIS_LIBRARY_TYPE) from DIR/src/**.cpp with public headers in
# DIR/include, linking DEPS publicly (see _confvis_add_module below for its two targets). Unit tests live beside each module in DIR/test/*_test.cpp and are collected into
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

# Each module is two targets:
# - NAME_objects, an OBJECT library that compiles the module's sources: a module's CMakeLists
#   gives its private compile options, include folders and definitions to NAME_objects;
# - NAME, the static or shared library made of those objects, which applications, the CLI and
#   the tools link and which is installed.
# The test binaries link every module's NAME_objects instead (the global property
# CONFVIS_TEST_LIBRARIES): the tests reach into internals (src/ headers) that a shared library,
# compiled with hidden visibility, does not export. Linked from the objects they see every
# symbol, each object is compiled once for both, and nothing links a module twice (an OBJECT
# library's objects go only to targets that link it directly; NAME_objects links the other
# modules' NAME_objects for their usage requirements alone).
function(_confvis_add_module name include_dir sources)
  set(object_dependencies "")
  foreach(dependency IN LISTS ARGN)
    if(TARGET ${dependency}_objects)
      list(APPEND object_dependencies ${dependency}_objects)
    else()
      list(APPEND object_dependencies ${dependency})
    endif()
  endforeach()
  add_library(${name}_objects OBJECT ${sources})
  target_include_directories(${name}_objects PUBLIC ${include_dir})
  target_link_libraries(${name}_objects PUBLIC ${object_dependencies})
  set_target_properties(${name}_objects PROPERTIES POSITION_INDEPENDENT_CODE ON)

  add_library(${name} ${CONFVIS_LIBRARY_TYPE} $<TARGET_OBJECTS:${name}_objects>)
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${include_dir}> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARGN})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON LINKER_LANGUAGE CXX)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${name}_objects)
  confvis_install_module(${name} ${include_dir})
endfunction()

# confvis_module_link_private(NAME LIBRARIES...): what the module's sources use but its public
# headers do not: linked by the library and (for the tests) by its objects.
function(confvis_module_link_private name)
  target_link_libraries(${name} PRIVATE ${ARGN})
  target_link_libraries(${name}_objects PRIVATE ${ARGN})
endfunction()

# confvis_module_objects(NAME OBJECT_LIBRARY): more objects for the module (sources compiled
# with other flags, as the Embree backend's AVX2 kernel): into its library and the tests.
function(confvis_module_objects name object_library)
  target_sources(${name} PRIVATE $<TARGET_OBJECTS:${object_library}>)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${object_library})
endfunction()

function(confvis_module name dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/*.cpp)
  _confvis_add_module(${name} ${dir}/include "${sources}" ${ARGN})
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
endfunction()

# confvis_module_sources(NAME DIR SUBDIR DEPS...): like confvis_module, but for a module that
# shares DIR with another (engine/core holds confvis_base in src/base and confvis_engine in
# src/engine); sources from DIR/src/SUBDIR, tests from DIR/test/SUBDIR.
function(confvis_module_sources name dir subdir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/${subdir}/*.cpp)
  _confvis_add_module(${name} ${dir}/include "${sources}" ${ARGN})
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/${subdir}/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
endfunction()
