# ctest driver (cmake -P): configure tests/subproject (add_subdirectory(confvis)) with Unix
# Makefiles, CMake's default generator, in a fresh folder; build the SPIR-V shaders (whose output
# folder Makefiles do not create by themselves) and a program linking confvis::base; run it.
# Arguments: -DSOURCE_DIR= -DWORK_DIR= [-DLAUNCHER=ccache]
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/driver_support.cmake)
require_driver_arguments(run_subproject_test.cmake SOURCE_DIR WORK_DIR)

file(REMOVE_RECURSE ${WORK_DIR})
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the parent project" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/subproject
    -B ${WORK_DIR} -G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Release
    -DCONFVIS_SOURCE_DIR=${SOURCE_DIR} ${launcher})
run("building the shaders and the parent's program" ${CMAKE_COMMAND} --build ${WORK_DIR}
    --target confvis_spirv parent_app --parallel 2)
file(GLOB spirv ${WORK_DIR}/confvis/backends/vulkan/generated/confvis_spirv/*.h)
list(LENGTH spirv count)
if(count LESS 10)
  message(FATAL_ERROR "only ${count} SPIR-V headers generated")
endif()
run("running the parent's program" ${WORK_DIR}/parent_app)
if(NOT output MATCHES "parent app: [^:]+: wall 'front': no resolution")
  message(FATAL_ERROR "unexpected output: ${output}")
endif()
