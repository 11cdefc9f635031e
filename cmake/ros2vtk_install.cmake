# ros2vtk — install rules and the package config, so that `find_package(ros2vtk)` works from an
# install tree (examples/downstream/ is the project that proves it: tests/downstream/).
#
# Installed layout (<prefix>):
#   lib/                          libros2vtkMessage.a, libros2vtkMessages.a, libros2vtkConvert.a,
#                                 libros2vtkWire.a, libros2vtkTf2.a, libros2vtkTf2Ros.a,
#                                 libros2vtkRobotModel.a, libros2vtkRobotLoader.a,
#                                 libros2vtkIGTL.a (with libopenigtlink-dev),
#                                 libros2vtkScene.so, libros2vtkNodes.so, libros2vtkDisplay.so,
#                                 libros2vtkIGTLConnector.so
#   include/                      ros2vtk/{wire,convert,tf2,tf2_ros,robot}/*, the generated
#                                 message headers (ros2vtk/<package>/msg/*.hpp) and, from VTK's
#                                 module install, include/ros2vtk/ (the scene and node classes)
#   python/ros2vtk/               the Python package (PYTHONPATH=<prefix>/python) with the
#                                 wrapped modules, when built with ROS2VTK_WRAP_PYTHON
#   lib/cmake/ros2vtk/            ros2vtkConfig.cmake (+ version), the exported targets, the VTK
#                                 module properties (Python ones in <package>/) and the
#                                 downstream functions
#                                 (ros2vtk_generate*.cmake, ros2vtk_vtk.cmake)
#   share/ros2vtk/generator/      the ros2vtk_gen Python package (run with PYTHONPATH=this folder)
#   share/ros2vtk/templates/      its Jinja2 templates
#   share/ros2vtk/msg_specs/      the shipped interface specs and mapping rules
#
# The VTK modules (ros2vtk::Scene, ros2vtk::Nodes, ros2vtk::Display, ros2vtk::IGTLConnector) are installed and exported by
# vtk_module_build itself (cmake/ros2vtk_vtk.cmake, one export set per module); this file
# exports the plain libraries they and generated downstream code link.

include_guard(GLOBAL)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(ROS2VTK_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/ros2vtk")
set(ROS2VTK_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/ros2vtk")
set(ROS2VTK_INSTALL_PYTHONDIR "python")  # as MODULE_DESTINATION in cmake/ros2vtk_vtk.cmake

# The plain libraries: exported under their own names (the generator names register functions
# after the real target, e.g. ros2vtk_register_ros2vtkMessages_types); ros2vtkConfig.cmake adds
# the ros2vtk::<Name> aliases the build tree has.
set(_ros2vtk_exported_libraries ros2vtkMessage ros2vtkMessages ros2vtkConvert ros2vtkWire
  ros2vtkTf2 ros2vtkTf2Ros ros2vtkRobotModel ros2vtkRobotLoader)
# The OpenIGTLink connector's library, when libopenigtlink-dev was found (runtime/IGTL).
if(TARGET ros2vtkIGTL)
  list(APPEND _ros2vtk_exported_libraries ros2vtkIGTL)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/runtime/IGTL/include/"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
endif()
install(TARGETS ${_ros2vtk_exported_libraries}
  EXPORT ros2vtkTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
  INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(EXPORT ros2vtkTargets
  FILE ros2vtkTargets.cmake
  DESTINATION "${ROS2VTK_INSTALL_CMAKEDIR}")
# The VTK modules' build-tree export() needs their dependencies exported from the build tree too.
export(EXPORT ros2vtkTargets
  FILE "${PROJECT_BINARY_DIR}/${ROS2VTK_INSTALL_CMAKEDIR}/ros2vtkTargets.cmake")

# Headers of those libraries (the generated message headers come from the build tree).
install(DIRECTORY
    "${PROJECT_SOURCE_DIR}/runtime/Message/include/"
    "${PROJECT_SOURCE_DIR}/runtime/Convert/include/"
    "${PROJECT_SOURCE_DIR}/runtime/Wire/include/"
    "${PROJECT_SOURCE_DIR}/runtime/Tf2/include/"
    "${PROJECT_SOURCE_DIR}/runtime/Tf2Ros/include/"
    "${PROJECT_SOURCE_DIR}/runtime/Robot/include/"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
# (msg_specs/CMakeLists.txt installs them, next to the target that makes them).

# The Python package's own files, next to the wrapped modules VTK installs in python/ros2vtk/.
if(ROS2VTK_WRAP_PYTHON)
  get_property(_ros2vtk_python_files GLOBAL PROPERTY ROS2VTK_PYTHON_PACKAGE_FILES)  # python/CMakeLists.txt
  foreach(_file IN LISTS _ros2vtk_python_files)  # keep subpackages (ros2vtk/app/) in their folder
    file(RELATIVE_PATH _relative "${PROJECT_SOURCE_DIR}/python/ros2vtk" "${_file}")
    get_filename_component(_subfolder "${_relative}" DIRECTORY)
    install(FILES "${_file}" DESTINATION "${ROS2VTK_INSTALL_PYTHONDIR}/ros2vtk/${_subfolder}")
  endforeach()
endif()

# The generator, its templates, the shipped specs (those of ros2vtk::Messages) and mappings.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/generator/ros2vtk_gen"
  DESTINATION "${ROS2VTK_INSTALL_DATADIR}/generator"
  PATTERN "__pycache__" EXCLUDE
  PATTERN "*.pyc" EXCLUDE)
install(PROGRAMS "${PROJECT_SOURCE_DIR}/generator/ros2vtk-gen"
  DESTINATION "${ROS2VTK_INSTALL_DATADIR}/generator")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/templates/"
  DESTINATION "${ROS2VTK_INSTALL_DATADIR}/templates")
get_target_property(_ros2vtk_specs ros2vtkMessages ROS2VTK_ALL_SPECS)
foreach(_ros2vtk_spec IN LISTS _ros2vtk_specs)
  file(RELATIVE_PATH _ros2vtk_rel "${PROJECT_SOURCE_DIR}/msg_specs" "${_ros2vtk_spec}")
  get_filename_component(_ros2vtk_rel_dir "${_ros2vtk_rel}" DIRECTORY)
  install(FILES "${_ros2vtk_spec}"
    DESTINATION "${ROS2VTK_INSTALL_DATADIR}/msg_specs/${_ros2vtk_rel_dir}")
endforeach()
install(DIRECTORY "${PROJECT_SOURCE_DIR}/msg_specs/mappings"
  DESTINATION "${ROS2VTK_INSTALL_DATADIR}/msg_specs"
  FILES_MATCHING PATTERN "*.toml" PATTERN "*.md")

# The downstream functions.
install(FILES
    "${PROJECT_SOURCE_DIR}/cmake/ros2vtk_generate.cmake"
    "${PROJECT_SOURCE_DIR}/cmake/ros2vtk_generate_nodes.cmake"
    "${PROJECT_SOURCE_DIR}/cmake/ros2vtk_vtk.cmake"
    "${PROJECT_SOURCE_DIR}/cmake/ros2vtk_internal.cmake"
  DESTINATION "${ROS2VTK_INSTALL_CMAKEDIR}")

# ros2vtkConfig.cmake + version.
get_property(ROS2VTK_EXPORTED_VTK_PACKAGES GLOBAL PROPERTY ROS2VTK_EXPORTED_VTK_PACKAGES)
set(ROS2VTK_INSTALLED_WRAP_PYTHON "${ROS2VTK_WRAP_PYTHON}")
configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/ros2vtkConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/ros2vtkConfig.cmake"
  INSTALL_DESTINATION "${ROS2VTK_INSTALL_CMAKEDIR}"
  PATH_VARS ROS2VTK_INSTALL_DATADIR ROS2VTK_INSTALL_PYTHONDIR)
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/ros2vtkConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(FILES
    "${PROJECT_BINARY_DIR}/ros2vtkConfig.cmake"
    "${PROJECT_BINARY_DIR}/ros2vtkConfigVersion.cmake"
  DESTINATION "${ROS2VTK_INSTALL_CMAKEDIR}")
