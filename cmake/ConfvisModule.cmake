# confvis_module(NAME DIR DEPS...): a static library from DIR/src/**.cpp with public headers in
# DIR/include. Unit tests live beside each module in DIR/test/*_test.cpp and are collected into
# the single test binary by tests/CMakeLists.txt (pbrt-v4 style: one binary, tests near code).
set_property(GLOBAL PROPERTY CONFVIS_TEST_SOURCES "")

function(confvis_module name dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/*.cpp)
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${dir}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARGN})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${name})
endfunction()

# confvis_module_sources(NAME DIR SUBDIR DEPS...): like confvis_module, but for a module that
# shares DIR with another (engine/ holds confvis_base in src/base and confvis_engine in
# src/engine); sources from DIR/src/SUBDIR, tests from DIR/test/SUBDIR.
function(confvis_module_sources name dir subdir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/src/${subdir}/*.cpp)
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${dir}/include> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARGN})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${dir}/test/${subdir}/*_test.cpp)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_SOURCES ${tests})
  set_property(GLOBAL APPEND PROPERTY CONFVIS_TEST_LIBRARIES ${name})
endfunction()
