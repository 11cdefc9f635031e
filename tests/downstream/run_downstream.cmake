# cmake -P script of the downstream_install_example test (tests/downstream/CMakeLists.txt).
# Each step stops the test with the step's output on failure.
foreach(_var BUILD_DIR INSTALL_DIR EXAMPLE_SOURCE_DIR EXAMPLE_BUILD_DIR GENERATOR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_downstream.cmake: -D${_var}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE RelWithDebInfo)
endif()

function(run_step name)
  message(STATUS "downstream: ${name}: ${ARGN}")
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE _result OUTPUT_VARIABLE _output ERROR_VARIABLE _output)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "downstream: ${name} failed (${_result}):\n${_output}")
  endif()
  set(step_output "${_output}" PARENT_SCOPE)
endfunction()

# 1. Install the toolkit.
run_step(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${INSTALL_DIR}")

# 2. Configure the example against the install tree only (not the build tree's files).
set(_python "")
if(Python3_EXECUTABLE)
  set(_python "-DPython3_EXECUTABLE=${Python3_EXECUTABLE}")
endif()
run_step(configure "${CMAKE_COMMAND}" -S "${EXAMPLE_SOURCE_DIR}" -B "${EXAMPLE_BUILD_DIR}"
  -G "${GENERATOR}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_PREFIX_PATH=${INSTALL_DIR}"
  "-Dros2vtk_DIR=${INSTALL_DIR}/lib/cmake/ros2vtk" ${_python})
file(STRINGS "${EXAMPLE_BUILD_DIR}/CMakeCache.txt" _ros2vtk_dir REGEX "^ros2vtk_DIR:")
if(NOT _ros2vtk_dir MATCHES "downstream-install")
  message(FATAL_ERROR "downstream: ros2vtk was not found in ${INSTALL_DIR}: ${_ros2vtk_dir}")
endif()

# 3. Build it (small: -j2) and run the program.
run_step(build "${CMAKE_COMMAND}" --build "${EXAMPLE_BUILD_DIR}" -j2)
run_step(run "${EXAMPLE_BUILD_DIR}/needle_guide_demo")
message(STATUS "downstream: program output:\n${step_output}")
foreach(_expected
    "round trip ok"
    "translation_mm 100.0 -20.0 35.0 depth_m 0.045"
    "NeedleGuide OK")
  string(FIND "${step_output}" "${_expected}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "downstream: the program's output lacks '${_expected}':\n${step_output}")
  endif()
endforeach()
message(STATUS "downstream: passed")
