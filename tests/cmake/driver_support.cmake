# Shared by the ctest drivers (cmake -P) that build and run projects against confvis
# (consumer/run_consumer_test.cmake, consumer/run_shared_consumer_test.cmake,
# subproject/run_subproject_test.cmake).

# require_driver_arguments(DRIVER VAR...): each VAR must be given as -DVAR=... and not empty.
function(require_driver_arguments driver)
  foreach(var IN LISTS ARGN)
    if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
      message(FATAL_ERROR "${driver} needs -D${var}=...")
    endif()
  endforeach()
endfunction()

# run(STEP COMMAND...): runs the command; fails the test naming STEP with the command's exit
# status and output when it fails, else leaves its standard output in `output`.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()
