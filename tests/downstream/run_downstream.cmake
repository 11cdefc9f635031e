# cmake -P script of the downstream_install_example test (tests/downstream/CMakeLists.txt).
# Each step stops the test with the step's output on failure.
# GENERATOR: one CMake generator or a ;-list; the example is configured, built and run with
# each, in <EXAMPLE_BUILD_DIR>-<n> (issue 20: Makefiles with Python wrapping must work too).
# LAUNCHER (optional): the compiler launcher of the toolkit's build (ccache), reused.
foreach(_var BUILD_DIR INSTALL_DIR EXAMPLE_SOURCE_DIR EXAMPLE_BUILD_DIR GENERATOR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "run_downstream.cmake: -D${_var}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE RelWithDebInfo)
endif()

function(run_step name)
  string(TIMESTAMP _start "%s" UTC)
  message(STATUS "downstream: ${name}: ${ARGN}")
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE _result OUTPUT_VARIABLE _output ERROR_VARIABLE _output)
  string(TIMESTAMP _end "%s" UTC)
  math(EXPR _seconds "${_end} - ${_start}")
  message(STATUS "downstream: ${name} took ${_seconds} s")
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "downstream: ${name} failed (${_result}):\n${_output}")
  endif()
  set(step_output "${_output}" PARENT_SCOPE)
endfunction()

function(expect_output step)
  foreach(_expected IN LISTS ARGN)
    string(FIND "${step_output}" "${_expected}" _at)
    if(_at EQUAL -1)
      message(FATAL_ERROR "downstream: the ${step} output lacks '${_expected}':\n${step_output}")
    endif()
  endforeach()
endfunction()

# 1. Install the toolkit into a fresh prefix (no files left from an earlier install).
file(REMOVE_RECURSE "${INSTALL_DIR}" "${EXAMPLE_BUILD_DIR}")
foreach(_n RANGE 0 3)
  file(REMOVE_RECURSE "${EXAMPLE_BUILD_DIR}-${_n}")
endforeach()
run_step(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${INSTALL_DIR}")
# The runtime libraries are there; the tests' generated module (NO_INSTALL) is not.
foreach(_library ros2vtkWire ros2vtkTf2 ros2vtkTf2Ros ros2vtkRobotModel ros2vtkRobotLoader)
  if(NOT EXISTS "${INSTALL_DIR}/lib/lib${_library}.a")
    message(FATAL_ERROR "downstream: lib${_library}.a is not installed")
  endif()
endforeach()
file(GLOB_RECURSE _test_files "${INSTALL_DIR}/*ros2vtkTestNodes*" "${INSTALL_DIR}/*nodes_test_msgs*")
if(_test_files)
  message(FATAL_ERROR "downstream: test-only files were installed: ${_test_files}")
endif()

set(_launcher "")
if(LAUNCHER)
  set(_launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}" "-DCMAKE_C_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
set(_index 0)
set(_example_base "${EXAMPLE_BUILD_DIR}")
set(_generators "${GENERATOR}")
foreach(GENERATOR IN LISTS _generators)
  set(EXAMPLE_BUILD_DIR "${_example_base}-${_index}")
  math(EXPR _index "${_index} + 1")
  message(STATUS "downstream: generator '${GENERATOR}' in ${EXAMPLE_BUILD_DIR}")
  # 2. Configure the example against the install tree only (not the build tree's files), with
  #    Python wrapping when the toolkit was built with it.
  set(_python "")
  if(Python3_EXECUTABLE)
    set(_python "-DPython3_EXECUTABLE=${Python3_EXECUTABLE}")
  endif()
  set(_wrap OFF)
  if(WRAP_PYTHON)
    set(_wrap ON)
  endif()
  run_step(configure "${CMAKE_COMMAND}" -S "${EXAMPLE_SOURCE_DIR}" -B "${EXAMPLE_BUILD_DIR}"
    -G "${GENERATOR}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" "-DCMAKE_PREFIX_PATH=${INSTALL_DIR}"
    "-Dros2vtk_DIR=${INSTALL_DIR}/lib/cmake/ros2vtk" "-DNEEDLE_GUIDE_PYTHON=${_wrap}" ${_python} ${_launcher})
  file(STRINGS "${EXAMPLE_BUILD_DIR}/CMakeCache.txt" _ros2vtk_dir REGEX "^ros2vtk_DIR:")
  if(NOT _ros2vtk_dir MATCHES "downstream-install")
    message(FATAL_ERROR "downstream: ros2vtk was not found in ${INSTALL_DIR}: ${_ros2vtk_dir}")
  endif()

  # 3. Build it (small: -j2) and run the program.
  run_step(build "${CMAKE_COMMAND}" --build "${EXAMPLE_BUILD_DIR}" -j2)
  run_step(run "${EXAMPLE_BUILD_DIR}/needle_guide_demo")
  message(STATUS "downstream: program output:\n${step_output}")
  expect_output(program
    "round trip ok"
    "translation_mm 100.0 -20.0 35.0 depth_m 0.045"
    "NeedleGuide OK"
    "tf2 world->guide 1.100 -0.020 0.035"   # ros2vtk::Tf2
    "dds topic rt/needle_guide"            # ros2vtk::Wire
    "holder stage z 0.055"                 # ros2vtk::RobotModel: 0.01 m origin + 0.045 m depth
    "holder visuals 2"                     # ros2vtk::RobotLoader
    "igtl TRANSFORM guide 106 bytes x_mm 100.0") # ros2vtk::IGTL: 58-byte header + 48-byte body

  # 4. The wrapped module from Python (Debian's python3-vtk9): the installed package plus this
  #    build's python/ros2vtk/, a NeedleGuide publisher and subscriber by short name.
  if(WRAP_PYTHON)
    if(NOT EXISTS "${EXAMPLE_BUILD_DIR}/python/ros2vtk")
      message(FATAL_ERROR "downstream: no wrapped module in ${EXAMPLE_BUILD_DIR}/python/ros2vtk")
    endif()
    run_step(python "${CMAKE_COMMAND}" -E env
      "PYTHONPATH=${EXAMPLE_BUILD_DIR}/python:${INSTALL_DIR}/python"
      /usr/bin/python3 "${EXAMPLE_SOURCE_DIR}/needle_guide.py")
    message(STATUS "downstream: Python output:\n${step_output}")
    expect_output(Python
      "classes vtkROS2PublisherNeedleGuideNode vtkROS2SubscriberNeedleGuideNode"
      "received_mm 100.0 -20.0 35.0"
      "igtl connector listening"
      "NeedleGuide Python OK")
  endif()
  message(STATUS "downstream: passed with ${GENERATOR}")
endforeach()
message(STATUS "downstream: passed")
