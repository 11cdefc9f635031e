#[==[.rst
ros2vtk_generate.cmake — build C++ from ROS 2 interface specs with ros2vtk_gen
===============================================================================

.. code-block:: cmake

  ros2vtk_generate_messages(<target>
    SPECS        <file.msg|file.srv|file.action|folder> ...
    [ROS_PACKAGES <installed ROS package name> ...]
    [DEPENDENCIES <target made by ros2vtk_generate_messages> ...])

Generates, for every message (and every service's Request/Response, every action's eight
synthesized messages and its ``ActionTypeSupport`` table), the C++ struct, its CDR
serializer and its ``ros2vtk::wire::MessageTypeSupport`` table into
``${CMAKE_CURRENT_BINARY_DIR}/<target>/`` (``include/`` and ``src/``), and builds them as the
library ``<target>``, linked PUBLIC to ``ros2vtk::Message`` with the generated ``include/`` as
PUBLIC include directory.

``SPECS``
  Spec files or folders (searched recursively for ``*.msg`` / ``*.srv`` / ``*.action``),
  relative to ``CMAKE_CURRENT_SOURCE_DIR``. Files must be laid out ``<package>/msg/<Type>.msg``,
  ``<package>/srv/<Srv>.srv`` or ``<package>/action/<X>.action``: the package name comes from
  the path. Actions need ``unique_identifier_msgs``, ``builtin_interfaces`` and ``action_msgs``
  (shipped in ``ros2vtk::Messages``).
  A ROS package's installed share folder works as it is (``<prefix>/share/lab_msgs``: its
  ``.idl``/``.json`` files are skipped).
``ROS_PACKAGES``
  Names of installed ROS interface packages, found as ``<prefix>/share/<name>`` for each
  ``<prefix>`` of the ``AMENT_PREFIX_PATH`` environment variable (a sourced ROS install, or the
  venv of the ROS 2 wheels), so no ``.msg`` file is copied. SPECS may then be left out.
``DEPENDENCIES``
  Other targets made by this function whose types the specs reference (for example
  ``ros2vtkMessages`` for ``std_msgs/Header``). They are linked PUBLIC and their register
  function is called by this target's.

The library exports ``extern "C" void ros2vtk_register_<target>_types()`` (declared in the
generated header ``ros2vtk/<target>Register.hpp``); every type also
registers itself when the library loads, but a static library's objects may be dropped by the
linker unless something references them — calling that function forces it.

The generator runs at build time (``add_custom_command``) and writes only files whose content
changed; it is re-run when a spec, a template or the generator itself changes. Its arguments
go through a JSON file (``<target>_args.json`` in the binary dir).

Still to come in this file (another family of the same generator): ``ros2vtk_generate_nodes``
(VTK publisher/subscriber node classes from mapping rules) and ``ros2vtk_generate`` doing both.
#]==]

# Where the generator and its templates live (this file is cmake/ in the source tree).
get_filename_component(_ROS2VTK_GENERATE_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
set(_ROS2VTK_GENERATOR_DIR "${_ROS2VTK_GENERATE_ROOT}/generator" CACHE INTERNAL
  "ros2vtk_gen Python package folder")
set(_ROS2VTK_TEMPLATES_DIR "${_ROS2VTK_GENERATE_ROOT}/templates" CACHE INTERNAL
  "ros2vtk_gen templates folder")

# Expands SPECS entries (files or folders, relative to the current source dir) into absolute
# spec files; a missing entry is a FATAL_ERROR naming the calling function.
function(_ros2vtk_expand_specs function_name out_var)
  set(_r2v_files "")
  foreach(_r2v_entry IN LISTS ARGN)
    get_filename_component(_r2v_path "${_r2v_entry}" ABSOLUTE
      BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    if(IS_DIRECTORY "${_r2v_path}")
      file(GLOB_RECURSE _r2v_found CONFIGURE_DEPENDS "${_r2v_path}/*.msg" "${_r2v_path}/*.srv"
        "${_r2v_path}/*.action")
      if(NOT _r2v_found)
        message(FATAL_ERROR "${function_name}: folder '${_r2v_entry}' holds no .msg/.srv/.action "
          "file (cmake/ros2vtk_generate.cmake)")
      endif()
      list(SORT _r2v_found)
      list(APPEND _r2v_files ${_r2v_found})
    elseif(EXISTS "${_r2v_path}")
      if(NOT _r2v_path MATCHES "\\.(msg|srv|action)$")
        message(FATAL_ERROR "${function_name}: spec '${_r2v_entry}' is not .msg, .srv or "
          ".action (cmake/ros2vtk_generate.cmake)")
      endif()
      list(APPEND _r2v_files "${_r2v_path}")
    else()
      message(FATAL_ERROR "${function_name}: spec '${_r2v_entry}' not found relative to "
        "${CMAKE_CURRENT_SOURCE_DIR} (cmake/ros2vtk_generate.cmake)")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES _r2v_files)
  set(${out_var} "${_r2v_files}" PARENT_SCOPE)
endfunction()

# <prefix>/share/<package> of the first AMENT_PREFIX_PATH entry that has it (with msg/ or srv/).
function(_ros2vtk_find_ros_package where package out_var)
  string(REPLACE ":" ";" _r2v_prefixes "$ENV{AMENT_PREFIX_PATH}")
  foreach(_r2v_prefix IN LISTS _r2v_prefixes)
    if(IS_DIRECTORY "${_r2v_prefix}/share/${package}/msg"
       OR IS_DIRECTORY "${_r2v_prefix}/share/${package}/srv")
      set(${out_var} "${_r2v_prefix}/share/${package}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "${where}: ROS package '${package}' not found as <prefix>/share/${package}"
    "/msg for any prefix of AMENT_PREFIX_PATH ('$ENV{AMENT_PREFIX_PATH}'): source its install "
    "(or the venv of the ROS 2 wheels), or give its folder in SPECS "
    "(cmake/ros2vtk_generate.cmake)")
endfunction()

# A JSON array of quoted strings.
function(_ros2vtk_json_list out_var)
  set(_r2v_json "")
  foreach(_r2v_item IN LISTS ARGN)
    string(REPLACE "\\" "\\\\" _r2v_item "${_r2v_item}")
    string(REPLACE "\"" "\\\"" _r2v_item "${_r2v_item}")
    if(_r2v_json)
      string(APPEND _r2v_json ", ")
    endif()
    string(APPEND _r2v_json "\"${_r2v_item}\"")
  endforeach()
  set(${out_var} "[${_r2v_json}]" PARENT_SCOPE)
endfunction()

# The Python that runs the generator: ROS2VTK_GENERATOR_PYTHON (the installed package config
# records the toolkit's own), else Python3_EXECUTABLE, else the first python3 found. It must
# import what the generator needs (`modules`); if not, one line says what to install.
function(_ros2vtk_generator_python where out_var modules)
  if(ROS2VTK_GENERATOR_PYTHON AND EXISTS "${ROS2VTK_GENERATOR_PYTHON}")
    set(_r2v_python "${ROS2VTK_GENERATOR_PYTHON}")
  else()
    if(NOT Python3_EXECUTABLE)
      find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter)
    endif()
    set(_r2v_python "${Python3_EXECUTABLE}")
  endif()
  string(MAKE_C_IDENTIFIER "${_r2v_python}_${modules}" _r2v_key)
  if(NOT _ROS2VTK_PYTHON_OK_${_r2v_key})
    execute_process(COMMAND "${_r2v_python}" -c "import ${modules}"
      RESULT_VARIABLE _r2v_result OUTPUT_QUIET ERROR_QUIET)
    if(NOT _r2v_result EQUAL 0)
      message(FATAL_ERROR "${where}: the generator's Python ${_r2v_python} cannot import "
        "${modules}: install Jinja2 for it (Debian: apt-get install python3-jinja2; pip: "
        "python3 -m pip install Jinja2; tomllib needs Python >= 3.11), or point "
        "-DROS2VTK_GENERATOR_PYTHON=<python> at one that has it")
    endif()
    set(_ROS2VTK_PYTHON_OK_${_r2v_key} TRUE CACHE INTERNAL "generator Python checked")
  endif()
  set(${out_var} "${_r2v_python}" PARENT_SCOPE)
endfunction()

# What both generator functions do once their arguments are checked (as rosidl shares its
# argument writer): write <target>_args.json (`args_json`, rewritten only when it changes), ask
# the generator for its outputs at configure time, and add the command that generates them at
# build time, re-run when an input (`ARGN`), a template or the generator changes. Sets
# `out_var` to the output paths.
function(_ros2vtk_add_generator_command where target args_json comment modules out_var)
  _ros2vtk_generator_python("${where}" _r2v_python "${modules}")
  set(_r2v_args_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_args.json")
  file(CONFIGURE OUTPUT "${_r2v_args_file}" CONTENT "${args_json}" @ONLY)
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${_ROS2VTK_GENERATOR_DIR}"
            "${_r2v_python}" -m ros2vtk_gen --args-file "${_r2v_args_file}" --list-outputs
    OUTPUT_VARIABLE _r2v_outputs
    ERROR_VARIABLE _r2v_error
    RESULT_VARIABLE _r2v_result
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT _r2v_result EQUAL 0)
    message(FATAL_ERROR "${where}: the generator could not list its outputs:\n${_r2v_error}")
  endif()
  string(REPLACE "\n" ";" _r2v_outputs "${_r2v_outputs}")
  file(GLOB_RECURSE _r2v_generator_files CONFIGURE_DEPENDS
    "${_ROS2VTK_GENERATOR_DIR}/ros2vtk_gen/*.py")
  file(GLOB_RECURSE _r2v_template_files CONFIGURE_DEPENDS "${_ROS2VTK_TEMPLATES_DIR}/*.j2")
  add_custom_command(
    OUTPUT ${_r2v_outputs}
    COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${_ROS2VTK_GENERATOR_DIR}"
            "${_r2v_python}" -m ros2vtk_gen --args-file "${_r2v_args_file}"
    DEPENDS ${_r2v_generator_files} ${_r2v_template_files} ${ARGN} "${_r2v_args_file}"
    COMMENT "${comment}"
    VERBATIM)
  set(${out_var} "${_r2v_outputs}" PARENT_SCOPE)
endfunction()

function(ros2vtk_generate_messages target)
  set(_r2v_fn "ros2vtk_generate_messages")
  cmake_parse_arguments(PARSE_ARGV 1 _r2v "" "" "SPECS;ROS_PACKAGES;DEPENDENCIES")
  if(NOT target OR target MATCHES "^(SPECS|ROS_PACKAGES|DEPENDENCIES)$")
    message(FATAL_ERROR "${_r2v_fn}(): the first argument must be the target name "
      "(cmake/ros2vtk_generate.cmake)")
  endif()
  if(_r2v_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${_r2v_fn}(${target}): unknown arguments '${_r2v_UNPARSED_ARGUMENTS}'"
      " (expected SPECS, ROS_PACKAGES and DEPENDENCIES; cmake/ros2vtk_generate.cmake)")
  endif()
  foreach(_r2v_package IN LISTS _r2v_ROS_PACKAGES)
    _ros2vtk_find_ros_package("${_r2v_fn}(${target})" "${_r2v_package}" _r2v_share)
    list(APPEND _r2v_SPECS "${_r2v_share}")
  endforeach()
  if(_r2v_KEYWORDS_MISSING_VALUES)
    message(FATAL_ERROR "${_r2v_fn}(${target}): ${_r2v_KEYWORDS_MISSING_VALUES} given without "
      "values (cmake/ros2vtk_generate.cmake)")
  endif()
  if(NOT _r2v_SPECS)
    message(FATAL_ERROR "${_r2v_fn}(${target}): SPECS is required (or ROS_PACKAGES) "
      "(cmake/ros2vtk_generate.cmake)")
  endif()
  if(TARGET "${target}")
    message(FATAL_ERROR "${_r2v_fn}(${target}): a target of that name already exists "
      "(cmake/ros2vtk_generate.cmake)")
  endif()
  # cmake_parse_arguments folds an unknown keyword after SPECS into the spec list: catch it.
  foreach(_r2v_entry IN LISTS _r2v_SPECS _r2v_DEPENDENCIES)
    if(_r2v_entry MATCHES "^[A-Z][A-Z_]+$" AND NOT TARGET "${_r2v_entry}"
       AND NOT EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${_r2v_entry}")
      message(FATAL_ERROR "${_r2v_fn}(${target}): unknown keyword '${_r2v_entry}' (expected "
        "SPECS, ROS_PACKAGES and DEPENDENCIES; cmake/ros2vtk_generate.cmake)")
    endif()
  endforeach()
  _ros2vtk_expand_specs("${_r2v_fn}(${target})" _r2v_specs ${_r2v_SPECS})

  # Dependencies: targets made by this function; their specs resolve our nested types.
  set(_r2v_dep_json "")
  set(_r2v_dep_specs "")
  foreach(_r2v_dep IN LISTS _r2v_DEPENDENCIES)
    if(NOT TARGET "${_r2v_dep}")
      message(FATAL_ERROR "${_r2v_fn}(${target}): DEPENDENCIES entry '${_r2v_dep}' is not a "
        "target (define it before this call; cmake/ros2vtk_generate.cmake)")
    endif()
    get_target_property(_r2v_real "${_r2v_dep}" ALIASED_TARGET)
    if(NOT _r2v_real)
      set(_r2v_real "${_r2v_dep}")
    endif()
    get_target_property(_r2v_specs_of_dep "${_r2v_real}" ROS2VTK_SPECS)
    if(NOT _r2v_specs_of_dep)
      message(FATAL_ERROR "${_r2v_fn}(${target}): DEPENDENCIES entry '${_r2v_dep}' was not "
        "made by ros2vtk_generate_messages (cmake/ros2vtk_generate.cmake)")
    endif()
    get_target_property(_r2v_dep_dep_specs "${_r2v_real}" ROS2VTK_ALL_SPECS)
    _ros2vtk_json_list(_r2v_list ${_r2v_dep_dep_specs})
    if(_r2v_dep_json)
      string(APPEND _r2v_dep_json ", ")
    endif()
    string(APPEND _r2v_dep_json "{\"target\": \"${_r2v_real}\", \"specs\": ${_r2v_list}}")
    list(APPEND _r2v_dep_specs ${_r2v_dep_dep_specs})
  endforeach()

  set(_r2v_out "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  set(_r2v_args_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_args.json")
  _ros2vtk_json_list(_r2v_specs_json ${_r2v_specs})
  _ros2vtk_add_generator_command("${_r2v_fn}(${target}) (cmake/ros2vtk_generate.cmake)"
    "${target}" "{
  \"family\": \"messages\",
  \"target\": \"${target}\",
  \"output_dir\": \"${_r2v_out}\",
  \"templates_dir\": \"${_ROS2VTK_TEMPLATES_DIR}\",
  \"specs\": ${_r2v_specs_json},
  \"dependencies\": [${_r2v_dep_json}]
}
" "ros2vtk_gen: generating messages of ${target}" "jinja2" _r2v_outputs
    ${_r2v_specs} ${_r2v_dep_specs})

  set(_r2v_sources ${_r2v_outputs})
  list(FILTER _r2v_sources INCLUDE REGEX "\\.cpp$")
  set(_r2v_headers ${_r2v_outputs})
  list(FILTER _r2v_headers INCLUDE REGEX "\\.hpp$")
  add_library(${target} ${_r2v_sources} ${_r2v_headers})
  target_include_directories(${target} PUBLIC
    "$<BUILD_INTERFACE:${_r2v_out}/include>"
    "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  target_link_libraries(${target} PUBLIC ros2vtk::Message ${_r2v_DEPENDENCIES})
  target_compile_features(${target} PUBLIC cxx_std_17)
  # Linked into shared VTK modules (ros2vtk_generate_nodes), so position-independent whatever
  # the calling project's CMAKE_POSITION_INDEPENDENT_CODE. Compiled as unity batches: two small
  # files per type that parse the same headers (the common interfaces are ~500 files); the
  # templates keep each type's helpers in its own namespace for this.
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
    UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 32)
  if(COMMAND _ros2vtk_target_warnings)
    _ros2vtk_target_warnings(${target})
  endif()
  if(COMMAND _ros2vtk_target_werror)
    _ros2vtk_target_werror(${target})
  endif()
  set(_r2v_all_specs ${_r2v_dep_specs} ${_r2v_specs})
  list(REMOVE_DUPLICATES _r2v_all_specs)
  set_target_properties(${target} PROPERTIES
    ROS2VTK_SPECS "${_r2v_specs}"
    ROS2VTK_ALL_SPECS "${_r2v_all_specs}"
    ROS2VTK_ARGS_FILE "${_r2v_args_file}"
    ROS2VTK_OUTPUT_DIR "${_r2v_out}")
endfunction()
