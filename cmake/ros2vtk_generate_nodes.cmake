#[==[.rst
ros2vtk_generate_nodes.cmake — VTK publisher/subscriber node classes from mapping rules
========================================================================================

.. code-block:: cmake

  ros2vtk_generate_nodes(<target>
    MESSAGES <target made by ros2vtk_generate_messages>
    MAPPINGS <rules.toml> ...
    [MODULE_NAME <namespace::Name>]   # default: ${PROJECT_NAME}::<target>
    [PYTHON]
    [NO_INSTALL])

Generates, for every mapping rule of ``MAPPINGS`` (format: msg_specs/mappings/README.md), the
wrapped classes ``vtkROS2Publisher<Short>Node`` / ``vtkROS2Subscriber<Short>Node``, the free
converters ``ros2vtk::nodes::ROS2ToVTK`` / ``VTKToROS2`` (header ``<target>Convert.hpp``) and a
registration source into ``${CMAKE_CURRENT_BINARY_DIR}/<target>/`` (``include/``, ``src/``,
``vtk/``), and builds them as a shared VTK module (library ``<target>``) linked to
``ros2vtk::Scene``, ``ros2vtk::Convert`` and the ``MESSAGES`` target. ``<target>`` names the
library target (an ALIAS when VTK names the real target after ``MODULE_NAME``).

``MESSAGES``
  The target whose message types the rules map; its specs (and those of its dependencies)
  are what the rules are checked against.
``MAPPINGS``
  ``.toml`` rule files, relative to ``CMAKE_CURRENT_SOURCE_DIR``.
``MODULE_NAME``
  The VTK module name (``ros2vtk::Nodes`` for the shipped module).
``PYTHON``
  Also wrap the module for Python: ``<build>/python/ros2vtk/<target>`` next to the runtime's
  modules; ``import ros2vtk`` imports it and thereby registers its classes (from a downstream
  build tree too: put ``<build>/python`` on ``PYTHONPATH`` next to the install's ``python``).
``NO_INSTALL``
  Build the module without install rules (the VTK module functions always write them), for
  modules only tests use.

The library registers its classes in the scene's node-class registry when it loads, and
exports ``extern "C" void ros2vtk_register_<target>_nodes()`` (header ``<target>Register.hpp``)
to do it explicitly. Rules are
validated at build time: an unknown ROS type, kind or field path stops the build with
``<file>:<line>: message``.

.. code-block:: cmake

  ros2vtk_generate(<target>
    SPECS <file.msg|folder> ... | ROS_PACKAGES <installed package> ...
    [MAPPINGS <rules.toml> ...]
    [DEPENDENCIES <ros2vtk_generate_messages target> ...]
    [PYTHON] [NO_INSTALL])

The downstream convenience: ``ros2vtk_generate_messages(<target>Messages SPECS ...
DEPENDENCIES ...)`` and, when ``MAPPINGS`` are given, ``ros2vtk_generate_nodes(<target>
MESSAGES <target>Messages MAPPINGS ... [PYTHON] [NO_INSTALL])``. Without ``MAPPINGS`` the messages target is
named ``<target>`` itself (types without a rule are still usable through the generic nodes).
#]==]

include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/ros2vtk_generate.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/ros2vtk_vtk.cmake")

# The VTK components the generated classes and converters use.
set(_ROS2VTK_NODES_VTK_COMPONENTS CommonCore CommonDataModel CommonMath CommonTransforms
  IOXMLParser CACHE INTERNAL "VTK components of generated node modules")

function(ros2vtk_generate_nodes target)
  set(_r2v_fn "ros2vtk_generate_nodes")
  set(_r2v_where "(cmake/ros2vtk_generate_nodes.cmake)")
  cmake_parse_arguments(PARSE_ARGV 1 _r2v "PYTHON;NO_INSTALL" "MESSAGES;MODULE_NAME" "MAPPINGS")
  if(NOT target OR target MATCHES "^(MESSAGES|MAPPINGS|MODULE_NAME|PYTHON|NO_INSTALL)$")
    message(FATAL_ERROR "${_r2v_fn}(): the first argument must be the target name ${_r2v_where}")
  endif()
  if(_r2v_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_r2v_fn}(${target}): unknown arguments '${_r2v_UNPARSED_ARGUMENTS}' "
      "(expected MESSAGES, MAPPINGS, MODULE_NAME, PYTHON, NO_INSTALL) ${_r2v_where}")
  endif()
  if(_r2v_KEYWORDS_MISSING_VALUES)
    message(FATAL_ERROR "${_r2v_fn}(${target}): ${_r2v_KEYWORDS_MISSING_VALUES} given without "
      "values ${_r2v_where}")
  endif()
  foreach(_r2v_required MESSAGES MAPPINGS)
    if(NOT _r2v_${_r2v_required})
      message(FATAL_ERROR "${_r2v_fn}(${target}): ${_r2v_required} is required ${_r2v_where}")
    endif()
  endforeach()
  if(TARGET "${target}")
    message(FATAL_ERROR "${_r2v_fn}(${target}): a target of that name already exists "
      "${_r2v_where}")
  endif()
  if(NOT target MATCHES "^[A-Za-z][A-Za-z0-9_]*$")
    message(FATAL_ERROR "${_r2v_fn}(${target}): the target name must be a C identifier (it "
      "names the library, its export macro and its register function) ${_r2v_where}")
  endif()
  if(NOT _r2v_MODULE_NAME)
    set(_r2v_MODULE_NAME "${PROJECT_NAME}::${target}")
  endif()
  if(NOT _r2v_MODULE_NAME MATCHES "^[A-Za-z0-9_]+::[A-Za-z0-9_]+$")
    message(FATAL_ERROR "${_r2v_fn}(${target}): MODULE_NAME '${_r2v_MODULE_NAME}' must look "
      "like namespace::Name ${_r2v_where}")
  endif()

  # cmake_parse_arguments folds an unknown keyword after MAPPINGS into the list: catch it.
  foreach(_r2v_entry IN LISTS _r2v_MAPPINGS)
    if(_r2v_entry MATCHES "^[A-Z][A-Z_]+$" AND NOT EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${_r2v_entry}")
      message(FATAL_ERROR "${_r2v_fn}(${target}): unknown keyword '${_r2v_entry}' (expected "
        "MESSAGES, MAPPINGS, MODULE_NAME, PYTHON, NO_INSTALL) ${_r2v_where}")
    endif()
  endforeach()

  # The messages target: made by ros2vtk_generate_messages (it records its specs).
  if(NOT TARGET "${_r2v_MESSAGES}")
    message(FATAL_ERROR "${_r2v_fn}(${target}): MESSAGES '${_r2v_MESSAGES}' is not a target "
      "(define it before this call) ${_r2v_where}")
  endif()
  get_target_property(_r2v_messages "${_r2v_MESSAGES}" ALIASED_TARGET)
  if(NOT _r2v_messages)
    set(_r2v_messages "${_r2v_MESSAGES}")
  endif()
  get_target_property(_r2v_specs "${_r2v_messages}" ROS2VTK_ALL_SPECS)
  if(NOT _r2v_specs)
    message(FATAL_ERROR "${_r2v_fn}(${target}): MESSAGES '${_r2v_MESSAGES}' was not made by "
      "ros2vtk_generate_messages ${_r2v_where}")
  endif()

  # Mapping files: existing .toml files, absolute.
  set(_r2v_mappings "")
  foreach(_r2v_entry IN LISTS _r2v_MAPPINGS)
    get_filename_component(_r2v_path "${_r2v_entry}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    if(NOT EXISTS "${_r2v_path}" OR IS_DIRECTORY "${_r2v_path}")
      message(FATAL_ERROR "${_r2v_fn}(${target}): mapping file '${_r2v_entry}' not found "
        "relative to ${CMAKE_CURRENT_SOURCE_DIR} ${_r2v_where}")
    endif()
    if(NOT _r2v_path MATCHES "\\.toml$")
      message(FATAL_ERROR "${_r2v_fn}(${target}): mapping file '${_r2v_entry}' is not .toml "
        "${_r2v_where}")
    endif()
    list(APPEND _r2v_mappings "${_r2v_path}")
  endforeach()
  list(REMOVE_DUPLICATES _r2v_mappings)

  if(NOT Python3_EXECUTABLE)
    find_package(Python3 3.11 REQUIRED COMPONENTS Interpreter) # tomllib
  endif()
  # As runtime/Scene does: VTK's Python targets need Python3::Module in this directory.
  if(_r2v_PYTHON)
    find_package(Python3 3.11 REQUIRED COMPONENTS Interpreter Development.Module)
    find_package(VTK 9.1 REQUIRED COMPONENTS ${_ROS2VTK_NODES_VTK_COMPONENTS}
      WrappingPythonCore Python)
  else()
    find_package(VTK 9.1 REQUIRED COMPONENTS ${_ROS2VTK_NODES_VTK_COMPONENTS})
  endif()

  # Generator arguments (JSON, rewritten only when they change), its outputs and command.
  set(_r2v_out "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  set(_r2v_args_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_args.json")
  _ros2vtk_json_list(_r2v_specs_json ${_r2v_specs})
  _ros2vtk_json_list(_r2v_mappings_json ${_r2v_mappings})
  _ros2vtk_add_generator_command("${_r2v_fn}(${target}) ${_r2v_where}" "${target}" "{
  \"family\": \"nodes\",
  \"target\": \"${target}\",
  \"library\": \"${target}\",
  \"messages_target\": \"${_r2v_messages}\",
  \"output_dir\": \"${_r2v_out}\",
  \"templates_dir\": \"${_ROS2VTK_TEMPLATES_DIR}\",
  \"specs\": ${_r2v_specs_json},
  \"mappings\": ${_r2v_mappings_json}
}
" "ros2vtk_gen: generating node classes of ${target}" "jinja2, tomllib" _r2v_outputs
    ${_r2v_specs} ${_r2v_mappings})
  # The module is built in a directory of its own (vtk_module_build adds the folder of its
  # vtk.module), so the generation is reached through this target.
  add_custom_target(${target}_generate DEPENDS ${_r2v_outputs})

  set(_r2v_sources ${_r2v_outputs})
  list(FILTER _r2v_sources INCLUDE REGEX "\\.(cpp|cxx)$")
  set(_r2v_class_headers ${_r2v_outputs})
  list(FILTER _r2v_class_headers INCLUDE REGEX "/vtk/[^/]+\\.h$")
  set(_r2v_plain_headers ${_r2v_outputs})
  list(FILTER _r2v_plain_headers INCLUDE REGEX "\\.hpp$")

  # vtk.module and the module's CMakeLists.txt, written into the build tree.
  set(_r2v_module_dir "${_r2v_out}/module")
  file(CONFIGURE OUTPUT "${_r2v_module_dir}/vtk.module" CONTENT "NAME
  ${_r2v_MODULE_NAME}
LIBRARY_NAME
  ${target}
DESCRIPTION
  ROS 2 publisher and subscriber node classes generated from mapping rules
DEPENDS
  ros2vtk::Scene
  VTK::CommonCore
  VTK::CommonDataModel
  VTK::CommonMath
  VTK::CommonTransforms
PRIVATE_DEPENDS
  VTK::IOXMLParser
" @ONLY)
  string(REPLACE ";" "\n    " _r2v_sources_text "${_r2v_sources}")
  string(REPLACE ";" "\n    " _r2v_class_headers_text "${_r2v_class_headers}")
  string(REPLACE ";" "\n    " _r2v_plain_headers_text "${_r2v_plain_headers}")
  file(CONFIGURE OUTPUT "${_r2v_module_dir}/CMakeLists.txt" CONTENT "\
# Written by ros2vtk_generate_nodes(${target}) (cmake/ros2vtk_generate_nodes.cmake). Do not edit.
set_source_files_properties(
    ${_r2v_sources_text}
    ${_r2v_class_headers_text}
    ${_r2v_plain_headers_text}
  PROPERTIES GENERATED TRUE)
vtk_module_add_module(${_r2v_MODULE_NAME}
  SOURCES
    ${_r2v_sources_text}
  HEADERS
    ${_r2v_class_headers_text}
  NOWRAP_HEADERS
    ${_r2v_plain_headers_text})
vtk_module_depend(${_r2v_MODULE_NAME} ${target}_generate)
# The wrap hierarchy reads the generated headers; Makefile generators know the rule that makes
# them only in the directory of ${target}_generate, so order it after that target too.
if(TARGET ${target}-hierarchy)
  add_dependencies(${target}-hierarchy ${target}_generate)
endif()
vtk_module_include(${_r2v_MODULE_NAME} PUBLIC
  \"$<BUILD_INTERFACE:${_r2v_out}/include>\"
  \"$<BUILD_INTERFACE:${_r2v_out}/vtk>\")
vtk_module_link(${_r2v_MODULE_NAME} PUBLIC ros2vtk::Convert ${_r2v_messages})
vtk_module_compile_options(${_r2v_MODULE_NAME}
  PRIVATE -Wall -Wextra -Wshadow -Wnon-virtual-dtor)
" @ONLY)

  if(_r2v_PYTHON)
    set(_r2v_wrap ON)
  else()
    set(_r2v_wrap OFF)
  endif()
  set(_r2v_no_install "")
  if(_r2v_NO_INSTALL)
    set(_r2v_no_install NO_INSTALL)
  endif()
  ros2vtk_add_vtk_module(MODULE_FILE "${_r2v_module_dir}/vtk.module" WRAP_PYTHON ${_r2v_wrap}
    ${_r2v_no_install})

  # `<target>` names the library whatever VTK called the real target.
  get_target_property(_r2v_real "${_r2v_MODULE_NAME}" ALIASED_TARGET)
  if(NOT _r2v_real)
    set(_r2v_real "${_r2v_MODULE_NAME}")
  endif()
  if(NOT TARGET "${target}")
    add_library(${target} ALIAS ${_r2v_real})
  endif()
  set_target_properties(${_r2v_real} PROPERTIES
    ROS2VTK_MAPPINGS "${_r2v_mappings}"
    ROS2VTK_ARGS_FILE "${_r2v_args_file}"
    ROS2VTK_OUTPUT_DIR "${_r2v_out}")
  if(COMMAND _ros2vtk_target_werror)
    _ros2vtk_target_werror(${_r2v_real})
  endif()
endfunction()

function(ros2vtk_generate target)
  set(_r2v_fn "ros2vtk_generate")
  cmake_parse_arguments(PARSE_ARGV 1 _r2v "PYTHON;NO_INSTALL" ""
    "SPECS;ROS_PACKAGES;MAPPINGS;DEPENDENCIES")
  if(NOT target OR target MATCHES "^(SPECS|ROS_PACKAGES|MAPPINGS|DEPENDENCIES|PYTHON|NO_INSTALL)$")
    message(FATAL_ERROR "${_r2v_fn}(): the first argument must be the target name "
      "(cmake/ros2vtk_generate_nodes.cmake)")
  endif()
  if(_r2v_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_r2v_fn}(${target}): unknown arguments '${_r2v_UNPARSED_ARGUMENTS}' "
      "(expected SPECS, ROS_PACKAGES, MAPPINGS, DEPENDENCIES, PYTHON, NO_INSTALL; "
      "cmake/ros2vtk_generate_nodes.cmake)")
  endif()
  if(NOT _r2v_SPECS AND NOT _r2v_ROS_PACKAGES)
    message(FATAL_ERROR "${_r2v_fn}(${target}): SPECS is required "
      "(cmake/ros2vtk_generate_nodes.cmake)")
  endif()
  set(_r2v_specs_args "")
  if(_r2v_SPECS)
    list(APPEND _r2v_specs_args SPECS ${_r2v_SPECS})
  endif()
  if(_r2v_ROS_PACKAGES)
    list(APPEND _r2v_specs_args ROS_PACKAGES ${_r2v_ROS_PACKAGES})
  endif()
  set(_r2v_dependencies "")
  if(_r2v_DEPENDENCIES)
    set(_r2v_dependencies DEPENDENCIES ${_r2v_DEPENDENCIES})
  endif()
  if(NOT _r2v_MAPPINGS)
    ros2vtk_generate_messages(${target} ${_r2v_specs_args} ${_r2v_dependencies})
    return()
  endif()
  ros2vtk_generate_messages(${target}Messages ${_r2v_specs_args} ${_r2v_dependencies})
  set(_r2v_options "")
  foreach(_r2v_option PYTHON NO_INSTALL)
    if(_r2v_${_r2v_option})
      list(APPEND _r2v_options ${_r2v_option})
    endif()
  endforeach()
  ros2vtk_generate_nodes(${target} MESSAGES ${target}Messages MAPPINGS ${_r2v_MAPPINGS}
    ${_r2v_options})
endfunction()
