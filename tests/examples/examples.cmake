# Code examples that integrators read (README.md, header comments) are compiled and run by the
# test suite: extract_example copies each marked example out of its file at build time into
# build/tests/generated/examples/NAME.inc, which the tests here include. Editing an example
# rebuilds its test; an example that no longer compiles breaks the build.
# Included by tests/CMakeLists.txt after confvis_tests is defined.
add_executable(confvis_extract_example ${CMAKE_CURRENT_LIST_DIR}/extract_example.cpp)
set(confvis_examples_dir ${CMAKE_CURRENT_BINARY_DIR}/generated/examples)
file(MAKE_DIRECTORY ${confvis_examples_dir})

# confvis_example(NAME SOURCE): NAME.inc from the example marked NAME in SOURCE.
function(confvis_example name source)
  set(output ${confvis_examples_dir}/${name}.inc)
  add_custom_command(OUTPUT ${output}
    COMMAND confvis_extract_example ${source} ${name} ${output}
    DEPENDS ${source} confvis_extract_example
    COMMENT "example ${name} from ${source}"
    VERBATIM)
  set_property(GLOBAL APPEND PROPERTY CONFVIS_EXAMPLE_OUTPUTS ${output})
endfunction()

confvis_example(readme_loop ${PROJECT_SOURCE_DIR}/README.md)
confvis_example(readme_main ${PROJECT_SOURCE_DIR}/README.md)
confvis_example(map_follower_loop
  ${PROJECT_SOURCE_DIR}/engine/runtime/include/confvis/runtime/map_follower.hpp)
confvis_example(background_bake
  ${PROJECT_SOURCE_DIR}/engine/runtime/include/confvis/runtime/background_bake.hpp)
confvis_example(frame_stats
  ${PROJECT_SOURCE_DIR}/backends/common/include/confvis/backends/frame_stats.hpp)

get_property(confvis_example_outputs GLOBAL PROPERTY CONFVIS_EXAMPLE_OUTPUTS)
file(GLOB confvis_example_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*_test.cpp)
target_sources(confvis_tests PRIVATE ${confvis_example_tests} ${confvis_example_outputs})
target_include_directories(confvis_tests PRIVATE ${confvis_examples_dir})

# The README's application (its loop and its main) as an executable: built, not run (it shows a
# display until killed).
add_executable(confvis_readme_app ${CMAKE_CURRENT_LIST_DIR}/readme_app.cpp
  ${confvis_examples_dir}/readme_loop.inc ${confvis_examples_dir}/readme_main.inc)
target_link_libraries(confvis_readme_app PRIVATE confvis::confvis)
target_include_directories(confvis_readme_app PRIVATE ${confvis_examples_dir})
set_target_properties(confvis_readme_app PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
