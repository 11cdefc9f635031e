# Refreshes a committed copy of generator output (generated/messages/, generated/nodes/) by
# running the generator straight into it with the build's arguments (ARGS_FILE, output_dir
# replaced by GOLDEN_DIR). The generator deletes files it no longer lists (emit.prune_stale), so
# a removed package leaves nothing behind, and the result is what tests/golden compares with.
# Run by the ros2vtk_regenerate target: cmake -DPYTHON=... -DGENERATOR_DIR=... -DARGS_FILE=...
#   -DGOLDEN_DIR=... -DWORK_FILE=<scratch .json> -P ros2vtk_regenerate.cmake
foreach(_var PYTHON GENERATOR_DIR ARGS_FILE GOLDEN_DIR WORK_FILE)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "ros2vtk_regenerate.cmake: -D${_var}=... is required")
  endif()
endforeach()
file(READ "${ARGS_FILE}" _args)
string(JSON _args SET "${_args}" output_dir "\"${GOLDEN_DIR}\"")
file(WRITE "${WORK_FILE}" "${_args}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${GENERATOR_DIR}"
          "${PYTHON}" -m ros2vtk_gen --args-file "${WORK_FILE}"
  RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "ros2vtk_regenerate: the generator failed (${ARGS_FILE})")
endif()
message(STATUS "ros2vtk_regenerate: ${GOLDEN_DIR} is the generator output")
