# Private helpers of the ros2vtk build. Every name starts with _ros2vtk_.

# Warnings on, for our own targets only (never global flags).
function(_ros2vtk_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
endfunction()

# -Werror on a generated message/node library when ROS2VTK_WERROR is on (the toolkit's own build:
# a warning in generated code fails it). Downstream projects leave the option undefined.
function(_ros2vtk_target_werror target)
  if(ROS2VTK_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# AddressSanitizer + UndefinedBehaviorSanitizer on one target (ROS2VTK_ENABLE_ASAN; never global
# flags). UB stops the test at the first report. -O1 -g1 as the ASan documentation recommends:
# line tables are enough for symbolized reports, and the sanitized builds compile in half the
# time of RelWithDebInfo's -O2 -g (a third of the whole build was sanitized code).
function(_ros2vtk_target_sanitizers target)
  set(_flags -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_compile_options(${target} PRIVATE ${_flags} -O1 -g1)
  target_link_options(${target} PRIVATE ${_flags})
endfunction()

# _ros2vtk_sanitized_objects(<library> <out_var>): the sources of one static runtime library
# compiled once under the sanitizers, as an object library <real name>_asan_objects shared by
# every sanitized twin and fuzz target that compiles that library in (each used to compile its
# own copy: MessageYaml three times). Sets <out_var> to the object library's name.
function(_ros2vtk_sanitized_objects real out_var)
  set(_objects ${real}_asan_objects)
  if(NOT TARGET ${_objects})
    get_target_property(_lib_dir ${real} SOURCE_DIR)
    get_target_property(_lib_sources ${real} SOURCES)
    set(_sources)
    foreach(_s IN LISTS _lib_sources)
      if(_s MATCHES "\\.(c|cc|cpp|cxx)$")
        if(NOT IS_ABSOLUTE "${_s}")
          set(_s "${_lib_dir}/${_s}")
        endif()
        list(APPEND _sources "${_s}")
      endif()
    endforeach()
    add_library(${_objects} OBJECT ${_sources})
    target_include_directories(${_objects} PRIVATE $<TARGET_PROPERTY:${real},INCLUDE_DIRECTORIES>)
    target_compile_definitions(${_objects} PRIVATE $<TARGET_PROPERTY:${real},COMPILE_DEFINITIONS>)
    target_compile_features(${_objects} PRIVATE cxx_std_17)
    get_target_property(_deps ${real} LINK_LIBRARIES)
    if(_deps)
      # Only for the usage requirements (include folders, definitions) of what the library uses.
      target_link_libraries(${_objects} PRIVATE ${_deps})
    endif()
    add_dependencies(${_objects} ${real}) # whatever the library waits for (generated headers)
    _ros2vtk_target_sanitizers(${_objects})
  endif()
  set(${out_var} ${_objects} PARENT_SCOPE)
endfunction()

# _ros2vtk_compile_in(<target> <library>...): links the sanitized objects of the given (static)
# runtime libraries into <target> (_ros2vtk_sanitized_objects), with their include folders and
# definitions, and links what they link in their place; so that a sanitized test or fuzz target
# instruments the code it exercises.
function(_ros2vtk_compile_in target)
  set(_compiled_in)
  foreach(_lib IN LISTS ARGN)
    get_target_property(_real ${_lib} ALIASED_TARGET)
    if(NOT _real)
      set(_real ${_lib})
    endif()
    list(APPEND _compiled_in ${_lib} ${_real})
  endforeach()
  set(_pending)
  foreach(_lib IN LISTS ARGN)
    get_target_property(_real ${_lib} ALIASED_TARGET)
    if(NOT _real)
      set(_real ${_lib})
    endif()
    _ros2vtk_sanitized_objects(${_real} _objects)
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:${_objects}>)
    target_include_directories(${target} PRIVATE $<TARGET_PROPERTY:${_real},INCLUDE_DIRECTORIES>)
    target_compile_definitions(${target} PRIVATE $<TARGET_PROPERTY:${_real},COMPILE_DEFINITIONS>)
    get_target_property(_deps ${_real} LINK_LIBRARIES)
    if(_deps)
      list(APPEND _pending ${_deps})
    endif()
  endforeach()
  set(_links)
  foreach(_lib IN LISTS _pending)
    if(NOT _lib IN_LIST _compiled_in AND NOT _lib IN_LIST _links)
      list(APPEND _links ${_lib})
    endif()
  endforeach()
  if(_links)
    target_link_libraries(${target} PRIVATE ${_links})
  endif()
endfunction()

# _ros2vtk_add_sanitized_twin(<name> TEST <test target> [COMPILE_IN <library>...]
#                              [MAX_ALLOCATION_MB <n> (256)] [ASAN_OPTIONS <a=b:...>]
#                              [ENVIRONMENT ...])
# A copy of an existing test executable built under the sanitizers, with the sources of the
# libraries under test compiled into it (_ros2vtk_compile_in), registered as one CTest named
# <name> (label `sanitizer`).
function(_ros2vtk_add_sanitized_twin name)
  cmake_parse_arguments(ARG "" "TEST;MAX_ALLOCATION_MB;ASAN_OPTIONS" "COMPILE_IN;ENVIRONMENT" ${ARGN})
  if(NOT ARG_MAX_ALLOCATION_MB)
    set(ARG_MAX_ALLOCATION_MB 256)
  endif()
  get_target_property(_test_dir ${ARG_TEST} SOURCE_DIR)
  get_target_property(_test_sources ${ARG_TEST} SOURCES)
  set(_sources)
  foreach(_s IN LISTS _test_sources)
    if(NOT IS_ABSOLUTE "${_s}")
      set(_s "${_test_dir}/${_s}")
    endif()
    list(APPEND _sources "${_s}")
  endforeach()
  # The test's own sources are compiled once, uninstrumented, into an object library that the test
  # and its twin both take as $<TARGET_OBJECTS>: only the library under test needs the sanitizers'
  # instrumentation (the test code calls into it), and compiling every test file a second time was
  # a sixth of a clean build. The object library links what the test links for its usage
  # requirements only: no target links the object library itself, so the twin never links the
  # uninstrumented copy of the library it compiles in.
  set(_test_objects ${ARG_TEST}_objects)
  add_library(${_test_objects} OBJECT ${_sources})
  foreach(_property INCLUDE_DIRECTORIES COMPILE_DEFINITIONS COMPILE_OPTIONS)
    set_property(TARGET ${_test_objects} PROPERTY ${_property}
      "$<TARGET_PROPERTY:${ARG_TEST},${_property}>")
  endforeach()
  get_target_property(_test_links ${ARG_TEST} LINK_LIBRARIES)
  target_link_libraries(${_test_objects} PRIVATE ${_test_links})
  set_property(TARGET ${ARG_TEST} PROPERTY SOURCES "$<TARGET_OBJECTS:${_test_objects}>")
  set_property(TARGET ${ARG_TEST} PROPERTY LINKER_LANGUAGE CXX)
  add_executable(${name} $<TARGET_OBJECTS:${_test_objects}>)
  set_property(TARGET ${name} PROPERTY LINKER_LANGUAGE CXX)
  set(_skip)
  foreach(_lib IN LISTS ARG_COMPILE_IN)
    get_target_property(_real ${_lib} ALIASED_TARGET)
    list(APPEND _skip ${_lib} ${_real})
  endforeach()
  get_target_property(_test_links ${ARG_TEST} LINK_LIBRARIES)
  set(_links)
  foreach(_lib IN LISTS _test_links)
    if(NOT _lib IN_LIST _skip)
      list(APPEND _links ${_lib})
    endif()
  endforeach()
  target_link_libraries(${name} PRIVATE ${_links})
  if(ARG_COMPILE_IN)
    _ros2vtk_compile_in(${name} ${ARG_COMPILE_IN})
  endif()
  _ros2vtk_target_sanitizers(${name})
  add_test(NAME ${name} COMMAND ${name})
  set(_extra "")
  if(ARG_ASAN_OPTIONS)
    set(_extra ":${ARG_ASAN_OPTIONS}")
  endif()
  # One allocation above the maximum is a bug in these tests; leaks are reported.
  set_tests_properties(${name} PROPERTIES LABELS sanitizer TIMEOUT 300
    ENVIRONMENT "ASAN_OPTIONS=max_allocation_size_mb=${ARG_MAX_ALLOCATION_MB}:allocator_may_return_null=0:detect_leaks=1${_extra};UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1;${ARG_ENVIRONMENT}")
endfunction()

# One plain runtime library, as every runtime/<Folder>/CMakeLists.txt makes it: the target
# ros2vtk<Name> from the given sources, its alias ros2vtk::<Name>, the folder's include/ as PUBLIC
# include directory (build and install trees) and src/ as PRIVATE one, C++17, our warnings.
function(_ros2vtk_add_library name)
  set(_r2v_target "ros2vtk${name}")
  add_library(${_r2v_target} ${ARGN})
  add_library(ros2vtk::${name} ALIAS ${_r2v_target})
  target_include_directories(${_r2v_target}
    PUBLIC
      "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>"
      "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>"
    PRIVATE
      "${CMAKE_CURRENT_SOURCE_DIR}/src")
  target_compile_features(${_r2v_target} PUBLIC cxx_std_17)
  _ros2vtk_target_warnings(${_r2v_target})
endfunction()
