# Regenerates the shipped messages into OUTPUT_DIR (with ARGS_FILE, output_dir replaced) and
# compares the tree with GOLDEN_DIR file by file (both ways, so added or removed files count).
# GOLDEN_NAME (optional) is how messages name the golden folder.
foreach(_var PYTHON GENERATOR_DIR ARGS_FILE GOLDEN_DIR OUTPUT_DIR BUILD_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "check_golden.cmake: -D${_var}=... is required")
  endif()
endforeach()

if(NOT DEFINED GOLDEN_NAME)
  set(GOLDEN_NAME "generated/messages/")
endif()

file(READ "${ARGS_FILE}" _args)
string(JSON _args SET "${_args}" output_dir "\"${OUTPUT_DIR}\"")
file(REMOVE_RECURSE "${OUTPUT_DIR}")
file(WRITE "${OUTPUT_DIR}.json" "${_args}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${GENERATOR_DIR}"
          "${PYTHON}" -m ros2vtk_gen --args-file "${OUTPUT_DIR}.json"
  RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "generator failed on the shipped specs (${GOLDEN_NAME})")
endif()

file(GLOB_RECURSE _fresh RELATIVE "${OUTPUT_DIR}" "${OUTPUT_DIR}/*")
file(GLOB_RECURSE _golden RELATIVE "${GOLDEN_DIR}" "${GOLDEN_DIR}/*")
list(FILTER _golden EXCLUDE REGEX "^README")
set(_problems "")
foreach(_file IN LISTS _fresh)
  if(NOT EXISTS "${GOLDEN_DIR}/${_file}")
    string(APPEND _problems "  new, not in ${GOLDEN_NAME}: ${_file}\n")
  else()
    execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files
      "${OUTPUT_DIR}/${_file}" "${GOLDEN_DIR}/${_file}" RESULT_VARIABLE _differs)
    if(_differs)
      string(APPEND _problems "  differs: ${_file}\n")
    endif()
  endif()
endforeach()
foreach(_file IN LISTS _golden)
  if(NOT EXISTS "${OUTPUT_DIR}/${_file}")
    string(APPEND _problems "  stale, no longer generated: ${_file}\n")
  endif()
endforeach()
if(_problems)
  message(FATAL_ERROR "${GOLDEN_NAME} is out of date with the specs/templates:\n"
    "${_problems}"
    "Compare: diff -ru ${GOLDEN_DIR} ${OUTPUT_DIR}\n"
    "Refresh it with:\n  cmake --build ${BUILD_DIR} --target ros2vtk_regenerate\n")
endif()
list(LENGTH _fresh _count)
message(STATUS "${GOLDEN_NAME} matches the generator output (${_count} files)")
