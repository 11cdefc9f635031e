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
