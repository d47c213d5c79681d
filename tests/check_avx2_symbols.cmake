# Fails unless the object files in OBJECTS (the AVX2 build of the Embree surface kernel) define
# no global or weak symbol outside the namespace NAMESPACE (default confvis::embree::avx2): a
# weak copy of a shared inline function compiled with AVX2 could be the one the linker keeps,
# and baseline code calling it would then fault on a CPU without AVX2.
if(NOT NAMESPACE)
  set(NAMESPACE "confvis::embree::avx2::")
endif()
execute_process(COMMAND ${NM} --defined-only -C ${OBJECTS} OUTPUT_VARIABLE listing
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${OBJECTS}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(kernels 0)
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-fA-F]* ([A-Za-z]) (.*)$")
    set(type "${CMAKE_MATCH_1}")
    set(name "${CMAKE_MATCH_2}")
    if(type MATCHES "^[a-z]$" AND NOT type STREQUAL "u" AND NOT type STREQUAL "v"
       AND NOT type STREQUAL "w")
      continue()  # local to the object
    endif()
    string(FIND "${name}" "${NAMESPACE}" at)
    if(NOT type STREQUAL "T" OR NOT at EQUAL 0)
      message(FATAL_ERROR "${OBJECTS} exports '${name}' (type ${type}) outside ${NAMESPACE}")
    endif()
    math(EXPR kernels "${kernels} + 1")
  endif()
endforeach()
if(kernels EQUAL 0)
  message(FATAL_ERROR "no ${NAMESPACE} symbol in ${OBJECTS}")
endif()
message(STATUS "${kernels} symbol(s), all in ${NAMESPACE}")
