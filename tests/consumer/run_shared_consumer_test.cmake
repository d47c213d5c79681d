# ctest driver (cmake -P): confvis as shared libraries (CONFVIS_SHARED_LIBS=ON). Configures the
# source tree in a fresh folder, builds only confvis_base and confvis_engine (the rest would
# double CI's build for nothing more to learn), installs those two components with the headers
# and the package, and then
# - checks the symbols the libraries export (nm -D): the public API (functions, the type
#   information of confvis::Error), none of the internals declared in the sources' own headers;
# - builds tests/consumer's views_only.cpp against the installed package
#   (find_package(confvis COMPONENTS engine)), checks that it links the shared library and runs
#   it: closed-form views, and a confvis::Error thrown inside the library caught by the program.
# Arguments: -DSOURCE_DIR= -DWORK_DIR= -DGENERATOR= -DNM= -DREADELF= [-DLAUNCHER=ccache]
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/driver_support.cmake)
require_driver_arguments(run_shared_consumer_test.cmake SOURCE_DIR WORK_DIR GENERATOR NM READELF)

file(REMOVE_RECURSE ${WORK_DIR})
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring confvis with shared libraries" ${CMAKE_COMMAND} -S ${SOURCE_DIR}
    -B ${WORK_DIR}/confvis -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCONFVIS_SHARED_LIBS=ON -DCONFVIS_BUILD_TESTS=OFF -DCONFVIS_WERROR=ON ${launcher})
run("building confvis_base and confvis_engine" ${CMAKE_COMMAND} --build ${WORK_DIR}/confvis
    --target confvis_base confvis_engine --parallel 2)
set(prefix ${WORK_DIR}/installed)
foreach(component IN ITEMS Unspecified base engine)
  run("installing the component ${component}" ${CMAKE_COMMAND} --install ${WORK_DIR}/confvis
      --prefix ${prefix} --component ${component})
endforeach()

# Exported symbols, demangled: one line per symbol of each library.
function(exported library result)
  file(GLOB path ${prefix}/lib*/lib${library}.so)
  if(NOT path)
    message(FATAL_ERROR "the install has no lib${library}.so")
  endif()
  execute_process(COMMAND ${NM} -D -C --defined-only ${path} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE listing)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${path}")
  endif()
  set(${result} "${listing}" PARENT_SCOPE)
endfunction()
exported(confvis_base base_symbols)
exported(confvis_engine engine_symbols)
# Declared in public headers: exported.
foreach(symbol IN ITEMS "confvis::toString(confvis::ErrorCode)" "typeinfo for confvis::Error"
                        "confvis::writeTextAtomically(")
  string(FIND "${base_symbols}" "${symbol}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "libconfvis_base.so does not export ${symbol}")
  endif()
endforeach()
foreach(symbol IN ITEMS "confvis::loadDisplayConfig(" "confvis::makeViews("
                        "confvis::detail::parseNumber(")  # number_text.hpp, used by the runtime
  string(FIND "${engine_symbols}" "${symbol}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "libconfvis_engine.so does not export ${symbol}")
  endif()
endforeach()
# Declared in the sources' own headers (src/base/exr_internal.hpp, src/engine/display_checks.hpp,
# src/engine/import_parts.hpp): hidden.
foreach(symbol IN ITEMS "confvis::detail::requireWritableImage(" "confvis::detail::readExrLayer(")
  string(FIND "${base_symbols}" "${symbol}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "libconfvis_base.so exports the internal ${symbol}")
  endif()
endforeach()
foreach(symbol IN ITEMS "confvis::detail::checkWallShape(" "confvis::detail::wallsOverlap("
                        "confvis::detail::setImportedNode(")
  string(FIND "${engine_symbols}" "${symbol}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "libconfvis_engine.so exports the internal ${symbol}")
  endif()
endforeach()
# The internals are there, only hidden: the check above would otherwise prove nothing.
file(GLOB engine_library ${prefix}/lib*/libconfvis_engine.so)
execute_process(COMMAND ${NM} -C --defined-only ${engine_library} OUTPUT_VARIABLE all_symbols)
string(FIND "${all_symbols}" "confvis::detail::checkWallShape(" at)
if(at EQUAL -1)
  execute_process(COMMAND ${READELF} -sW -C ${engine_library} OUTPUT_VARIABLE all_symbols)
  string(FIND "${all_symbols}" "confvis::detail::checkWallShape(" at)
endif()
if(at EQUAL -1)
  message(FATAL_ERROR "libconfvis_engine.so has no confvis::detail::checkWallShape at all "
                      "(stripped, or renamed: update this test)")
endif()

file(WRITE ${WORK_DIR}/broken.json
  [[{"name": "broken", "reference": [0, 0, 0], "walls": [{"name": "front",
  "lower_left": [-1.5, -1.5, -1.5], "lower_right": [1.5, -1.5, -1.5],
  "upper_left": [-1.5, 1.5, -1.5]}]}]])  # no resolution
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer
    -B ${WORK_DIR}/consumer -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCONSUMER_COMPONENTS=engine -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON)
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run("reading the consumer's dynamic section" ${READELF} -d ${WORK_DIR}/consumer/views_only)
if(NOT output MATCHES "NEEDED[^\n]*libconfvis_engine\\.so")
  message(FATAL_ERROR "views_only does not link libconfvis_engine.so:\n${output}")
endif()
run("running the consumer" ${WORK_DIR}/consumer/views_only
    ${prefix}/share/confvis/configs/cave5.json ${WORK_DIR}/broken.json)
message(STATUS "consumer output:\n${output}")
# Head 0.5 m right of the centre of the 3 m cube: the front wall spans [-2, 1] at 1.5 m, the
# left wall is 2 m away, the right wall 1 m.
set(expected
  "view front -2.000 1.000 1.500"
  "view left -1.500 1.500 2.000"
  "view right -1.500 1.500 1.000"
  "caught invalid input: ")
foreach(line IN LISTS expected)
  string(FIND "${output}" "${line}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "consumer output lacks '${line}':\n${output}")
  endif()
endforeach()
if(NOT output MATCHES "caught invalid input: [^\n]*broken[^\n]*front")
  message(FATAL_ERROR "the error does not name the file and the wall:\n${output}")
endif()
