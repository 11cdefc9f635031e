# ros2vtk — build one VTK module from its vtk.module file, and wrap it for Python.
#
# The runtime's Scene module and the generated node module are both ordinary VTK modules
# (`vtk.module` + `vtk_module_add_module` in the folder's CMakeLists.txt). This file holds the
# one place that knows how Debian's VTK 9.1 wants them scanned, built and wrapped, so every
# module of the project is built the same way.

include_guard(GLOBAL)
include(GNUInstallDirs)

# Where wrapped Python modules land in the build tree: <build>/python/ros2vtk/, next to the
# package's __init__.py (copied there by python/CMakeLists.txt). PYTHONPATH=<build>/python.
set(ROS2VTK_PYTHON_BUILD_DIR "${CMAKE_BINARY_DIR}/python" CACHE INTERNAL
  "Build-tree folder that holds the ros2vtk Python package")

#[==[
ros2vtk_add_vtk_module(
  MODULE_FILE  <path/to/vtk.module>
  [WRAP_PYTHON <ON|OFF>]          # default: ROS2VTK_WRAP_PYTHON (ON when unset)
  [PYTHON_PACKAGE <package>]      # default: ros2vtk
  [PROVIDES_MODULES <variable>]   # set to the module names built (e.g. ros2vtk::Scene)
  [NO_INSTALL])                   # build only: no install rules (test-only modules)

Scans and builds the module(s) described by MODULE_FILE as shared libraries and, when wrapping,
builds one Python extension module per VTK module into <build>/python/<package>/.

Why the explicit settings:
- Debian's VTK 9.1 exports absolute install destinations, which vtk_module_build rejects, so
  every destination is given here, relative (found by a probe project: vtk_module_build with default destinations fails on this VTK).
- Modules are always shared: the node-class registry and the message-type registry are process
  singletons that the Scene module and the generated module must share.
- vtk_module_build refuses two calls with the same PACKAGE, so each module file gets its own.
- vtk_module_build and vtk_module_wrap_python always write install rules. NO_INSTALL builds the
  module in a subdirectory added EXCLUDE_FROM_ALL, whose install rules CMake leaves out of
  `cmake --install`; its targets are put back into `all` so the build is unchanged.
#]==]
function(ros2vtk_add_vtk_module)
  cmake_parse_arguments(PARSE_ARGV 0 _r2v "NO_INSTALL" "MODULE_FILE;WRAP_PYTHON;PYTHON_PACKAGE;PROVIDES_MODULES" "")
  if(_r2v_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "ros2vtk_add_vtk_module(): unknown arguments: ${_r2v_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT _r2v_MODULE_FILE)
    message(FATAL_ERROR "ros2vtk_add_vtk_module(): MODULE_FILE is required")
  endif()
  get_filename_component(_r2v_module_file "${_r2v_MODULE_FILE}" ABSOLUTE)
  if(NOT EXISTS "${_r2v_module_file}")
    message(FATAL_ERROR "ros2vtk_add_vtk_module(): module file '${_r2v_MODULE_FILE}' not found "
                        "(relative to ${CMAKE_CURRENT_SOURCE_DIR})")
  endif()
  if(NOT DEFINED _r2v_WRAP_PYTHON)
    if(DEFINED ROS2VTK_WRAP_PYTHON)
      set(_r2v_WRAP_PYTHON "${ROS2VTK_WRAP_PYTHON}")
    else()
      set(_r2v_WRAP_PYTHON ON)
    endif()
  endif()
  if(NOT _r2v_PYTHON_PACKAGE)
    set(_r2v_PYTHON_PACKAGE ros2vtk)
  endif()

  if(_r2v_NO_INSTALL)
    if(_ROS2VTK_EXPORT_VTK_MODULES)
      message(FATAL_ERROR "ros2vtk_add_vtk_module(): NO_INSTALL with an exported module")
    endif()
    # The same call without NO_INSTALL, from a subdirectory outside `cmake --install`.
    string(MD5 _r2v_hash "${_r2v_module_file}")
    string(SUBSTRING "${_r2v_hash}" 0 8 _r2v_hash)
    set(_r2v_sub "${CMAKE_CURRENT_BINARY_DIR}/ros2vtk_no_install_${_r2v_hash}")
    file(CONFIGURE OUTPUT "${_r2v_sub}/src/CMakeLists.txt" CONTENT "\
# Written by ros2vtk_add_vtk_module(NO_INSTALL) (cmake/ros2vtk_vtk.cmake). Do not edit.
ros2vtk_add_vtk_module(MODULE_FILE \"@_r2v_module_file@\" WRAP_PYTHON @_r2v_WRAP_PYTHON@
  PYTHON_PACKAGE \"@_r2v_PYTHON_PACKAGE@\" PROVIDES_MODULES _r2v_sub_modules)
set_property(GLOBAL PROPERTY _ROS2VTK_NO_INSTALL_MODULES \"\${_r2v_sub_modules}\")
" @ONLY)
    add_subdirectory("${_r2v_sub}/src" "${_r2v_sub}/bin" EXCLUDE_FROM_ALL)
    _ros2vtk_include_in_all("${_r2v_sub}/src")
    if(_r2v_PROVIDES_MODULES)
      get_property(_r2v_modules GLOBAL PROPERTY _ROS2VTK_NO_INSTALL_MODULES)
      set(${_r2v_PROVIDES_MODULES} ${_r2v_modules} PARENT_SCOPE)
    endif()
    return()
  endif()

  # Function scope only: the project's own plain libraries are not affected.
  set(BUILD_SHARED_LIBS ON)

  vtk_module_scan(
    MODULE_FILES        "${_r2v_module_file}"
    WANT_BY_DEFAULT     ON
    HIDE_MODULES_FROM_CACHE ON
    PROVIDES_MODULES    _r2v_modules
    ENABLE_TESTS        OFF)
  if(NOT _r2v_modules)
    message(FATAL_ERROR "ros2vtk_add_vtk_module(): '${_r2v_MODULE_FILE}' provides no module "
                        "(are its DEPENDS found by find_package(VTK)?)")
  endif()

  list(GET _r2v_modules 0 _r2v_first)
  string(REPLACE "::" "_" _r2v_package "${_r2v_first}")
  # The toolkit's own modules (built while _ROS2VTK_EXPORT_VTK_MODULES is set, see the top-level
  # CMakeLists.txt) join an export set of their own, so find_package(ros2vtk) imports them with
  # their VTK module properties (cmake/ros2vtk_install.cmake, ros2vtkConfig.cmake).
  set(_r2v_export "")
  if(_ROS2VTK_EXPORT_VTK_MODULES)
    set(_r2v_export INSTALL_EXPORT "${_r2v_package}Targets")
    set_property(GLOBAL APPEND PROPERTY ROS2VTK_EXPORTED_VTK_PACKAGES "${_r2v_package}")
  endif()
  vtk_module_build(
    ${_r2v_export}
    MODULES               ${_r2v_modules}
    PACKAGE               "${_r2v_package}"
    BUILD_WITH_KITS       OFF
    ENABLE_WRAPPING       ${_r2v_WRAP_PYTHON}
    INSTALL_HEADERS       ON
    HEADERS_DESTINATION   "${CMAKE_INSTALL_INCLUDEDIR}/ros2vtk"
    ARCHIVE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}"
    LIBRARY_DESTINATION   "${CMAKE_INSTALL_LIBDIR}"
    RUNTIME_DESTINATION   "${CMAKE_INSTALL_BINDIR}"
    CMAKE_DESTINATION     "${CMAKE_INSTALL_LIBDIR}/cmake/ros2vtk"
    LICENSE_DESTINATION   "${CMAKE_INSTALL_DATAROOTDIR}/licenses/ros2vtk"
    HIERARCHY_DESTINATION "${CMAKE_INSTALL_LIBDIR}/vtk/hierarchy/ros2vtk")
  # Installed module libraries find their sibling libraries (libros2vtkDisplay.so needs
  # libros2vtkNodes.so): the Python extensions' RUNPATH does not reach a library's own needs.
  foreach(_r2v_module IN LISTS _r2v_modules)
    get_target_property(_r2v_library "${_r2v_module}" ALIASED_TARGET)
    if(_r2v_library)
      set_property(TARGET "${_r2v_library}" APPEND PROPERTY INSTALL_RPATH "\$ORIGIN")
    endif()
  endforeach()

  if(_r2v_WRAP_PYTHON)
    # Exported modules also export their Python package (INTERFACE_vtk_module_python_package):
    # a downstream module wrapped on top of them imports them from it. The properties file is
    # named after the package, so each module gets a folder of its own.
    set(_r2v_python_export INSTALL_HEADERS OFF)
    if(_ROS2VTK_EXPORT_VTK_MODULES)
      set(_r2v_python_export INSTALL_HEADERS ON)
    endif()
    vtk_module_wrap_python(
      MODULES             ${_r2v_modules}
      TARGET              "${_r2v_package}_python"
      PYTHON_PACKAGE      "${_r2v_PYTHON_PACKAGE}"
      MODULE_DESTINATION  "python"
      LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
      CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/ros2vtk/${_r2v_package}"
      ${_r2v_python_export}
      BUILD_STATIC        OFF)
  endif()

  if(_r2v_PROVIDES_MODULES)
    set(${_r2v_PROVIDES_MODULES} ${_r2v_modules} PARENT_SCOPE)
  endif()
endfunction()

# Puts the library and executable targets under `dir` (and its subdirectories), added
# EXCLUDE_FROM_ALL for its install rules only, back into `all`. Utility targets keep their own
# setting (add_custom_target without ALL is excluded on purpose).
function(_ros2vtk_include_in_all dir)
  get_property(_r2v_targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  foreach(_r2v_target IN LISTS _r2v_targets)
    get_target_property(_r2v_type "${_r2v_target}" TYPE)
    if(_r2v_type MATCHES "^(SHARED_LIBRARY|STATIC_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      set_property(TARGET "${_r2v_target}" PROPERTY EXCLUDE_FROM_ALL OFF)
    endif()
  endforeach()
  get_property(_r2v_subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(_r2v_subdir IN LISTS _r2v_subdirs)
    _ros2vtk_include_in_all("${_r2v_subdir}")
  endforeach()
endfunction()
