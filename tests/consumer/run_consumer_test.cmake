# ctest driver (cmake -P): install the built confvis into a temporary prefix, move it, check that
# the package names no absolute path, configure and build tests/consumer against the moved copy
# alone (all components; then views and maps only, Embree, TBB and Vulkan disabled), run both,
# and check their output against closed-form values (the consumer renders real frames through a
# real bake: their pixels too).
# Arguments: -DBUILD_DIR= -DSOURCE_DIR= -DWORK_DIR= -DGENERATOR= -DEXAMPLES_DIR=
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/driver_support.cmake)
require_driver_arguments(run_consumer_test.cmake BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR EXAMPLES_DIR)

file(REMOVE_RECURSE ${WORK_DIR})
set(installed ${WORK_DIR}/installed)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${installed})

# Relocatable: the package is used from a copy of the prefix, the original gone, so a path
# recorded at install time would break the build below.
set(prefix ${WORK_DIR}/moved)
file(COPY ${installed}/ DESTINATION ${prefix})
file(REMOVE_RECURSE ${installed})
# No absolute path in the exported targets: not the build tree, not the source tree, not a
# library file of the build machine (Debian's libstb.so was one).
file(GLOB_RECURSE package_files ${prefix}/*.cmake)
if(NOT package_files)
  message(FATAL_ERROR "no CMake package files under ${prefix}")
endif()
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(path IN ITEMS "${BUILD_DIR}" "${SOURCE_DIR}" "${installed}")
    string(FIND "${text}" "${path}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} names ${path}")
    endif()
  endforeach()
  # An absolute path begins after a quote, a list separator or a blank (not after ${_IMPORT_PREFIX}).
  if(text MATCHES "[\";:( ]/([A-Za-z0-9_.+-]+/)*lib[A-Za-z0-9_+-]*\\.(so|a)")
    message(FATAL_ERROR "${file} names the library file ${CMAKE_MATCH_0}")
  endif()
endforeach()
foreach(file IN ITEMS share/confvis/shaders/confvis_warp.glsl include/confvis/confvis.hpp)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the install lacks ${file}")
  endif()
endforeach()

run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer
    -B ${WORK_DIR}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DREADME_EXAMPLES_DIR=${EXAMPLES_DIR})
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run("running the consumer" ${WORK_DIR}/build/consumer ${prefix}/share/confvis/configs/cave5.json)
message(STATUS "consumer output:\n${output}")
foreach(file IN ITEMS readme_app warp_consumer.spv)
  if(NOT EXISTS ${WORK_DIR}/build/${file})
    message(FATAL_ERROR "the consumer build made no ${file}")
  endif()
endforeach()
set(consumer_output "${output}")

# The README's application renders real frames through a real bake (Vulkan, lavapipe in CI) on
# the shipped CAVE made small: 16-pixel walls, a coarse map.
file(READ ${prefix}/share/confvis/configs/cave5.json cave)
string(JSON cave SET "${cave}" cube_resolution 32)
string(JSON cave SET "${cave}" edge_length 0.5)
string(JSON walls LENGTH "${cave}" walls)
math(EXPR last "${walls} - 1")
foreach(i RANGE ${last})
  string(JSON cave SET "${cave}" walls ${i} resolution "[16, 16]")
endforeach()
file(WRITE ${WORK_DIR}/small-cave.json "${cave}")
run("running the README's application" ${WORK_DIR}/build/readme_app ${WORK_DIR}/small-cave.json
    ${prefix}/share/confvis/configs/paths/cave-walk.csv checker-sphere 30)
message(STATUS "README application output:\n${output}")
if(NOT output MATCHES "app: 30 frames on 5 walls, [0-9]+ re-bakes")
  message(FATAL_ERROR "the README's application printed: ${output}")
endif()

# Views and maps only: the config must not look for Embree, TBB or Vulkan at all.
run("configuring the maps-only consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer
    -B ${WORK_DIR}/build-maps -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCONSUMER_COMPONENTS=conformal -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON)
run("building the maps-only consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build-maps)
run("running the maps-only consumer" ${WORK_DIR}/build-maps/maps_only
    ${prefix}/share/confvis/configs/cave5.json)
message(STATUS "maps-only consumer output:\n${output}")
if(NOT output MATCHES "maps-only front 1.500 map 16 reference 0.25 ahead shown")
  message(FATAL_ERROR "maps-only consumer output unexpected: ${output}")
endif()
# An unknown component is one clear error naming it.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer
    -B ${WORK_DIR}/build-unknown -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCONSUMER_COMPONENTS=raytracer
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "unknown confvis component 'raytracer'")
  message(FATAL_ERROR "an unknown component was not refused by name (${rc}):\n${err}")
endif()
set(output "${consumer_output}")

# Real frames through a real bake (main.cpp): every pixel of 5 walls of 24 x 24 against the
# checker sphere's colour in the direction the map gives it (at most 5 % off: square edges within
# the map's interpolation; measured 1.4 %), the plain frame against its own directions (at most
# 1 %; measured 0), and the conformal frame checked as if plain must be far off (measured 57 %:
# the map moves the scene, so the check could not pass by accident).
if(NOT output MATCHES "frames 5 pixels 2880 conformal off ([0-9]+) \\(as plain ([0-9]+)\\) plain off ([0-9]+) rays ([0-9]+)")
  message(FATAL_ERROR "consumer output lacks the frames line:\n${output}")
endif()
set(conformal_off ${CMAKE_MATCH_1})
set(conformal_as_plain_off ${CMAKE_MATCH_2})
set(plain_off ${CMAKE_MATCH_3})
set(rays ${CMAKE_MATCH_4})
if(conformal_off GREATER 144 OR plain_off GREATER 29 OR conformal_as_plain_off LESS 720
   OR rays LESS 2880)
  message(FATAL_ERROR "the consumer's frames are not what the map and the scene make: ${output}")
endif()

set(expected
  "display cave5 walls 5"
  "view front -1.500 1.500 -1.500 1.500 1.500"
  "view left -1.500 1.500 -1.500 1.500 1.500"
  "view floor -1.500 1.500 -1.500 1.500 1.500"
  "identity ok"
  "follower generation 1 reference 0.30 0.00 0.00"
  "pvx walls 3 first front")
foreach(line IN LISTS expected)
  string(FIND "${output}" "${line}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "consumer output lacks '${line}'")
  endif()
endforeach()
