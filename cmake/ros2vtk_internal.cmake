# Private helpers of the ros2vtk build. Every name starts with _ros2vtk_.

# Warnings on, for our own targets only (never global flags).
function(_ros2vtk_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
endfunction()
