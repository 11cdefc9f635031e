// ros2vtk — expands xacro robot descriptions (`robot.urdf.xacro`) into URDF text.
//
// xacro is a Python program (PyPI `xacro`, the ros/xacro project); no C++ implementation exists,
// so the description is expanded by running it as a child process (KWSys Process, no shell), as
// `ros2 launch` files do with `Command(['xacro ', path])`. `$(find pkg)` inside the file resolves
// through AMENT_PREFIX_PATH, inherited by the child.
#ifndef ros2vtk_robot_XacroProcessor_hpp
#define ros2vtk_robot_XacroProcessor_hpp

#include <cstddef>
#include <string>
#include <vector>

namespace ros2vtk {
namespace robot {

class XacroProcessor
{
public:
  /// True for `*.xacro` (`arm.urdf.xacro`, `arm.xacro`), any case.
  static bool is_xacro_file(const std::string& path);

  /// The program to run. Empty (the default): $ROS2VTK_XACRO when set, else `xacro` on PATH,
  /// else `<$ROS2VTK_VENV>/bin/xacro`.
  void set_command(const std::string& command) { command_ = command; }
  const std::string& command() const { return command_; }

  /// xacro arguments as on its command line: "name:=value" items separated by white space.
  /// False (and why) for an item that is not name:=value.
  bool set_arguments(const std::string& arguments, std::string* error);
  const std::vector<std::string>& arguments() const { return arguments_; }

  /// Seconds before a hung expansion is killed.
  void set_timeout(double seconds) { timeout_ = seconds; }

  /// Expands `path`. False, and a message naming the file and the cause (no xacro installed and
  /// where it was looked for, xacro's own error text, a timeout, output over `max_bytes`).
  bool expand(
    const std::string& path, size_t max_bytes, std::string* urdf, std::string* error) const;

  /// The program expand() would run, or "" (and where it looked) when there is none.
  std::string find_command(std::string* searched) const;

private:
  std::string command_;
  std::vector<std::string> arguments_;
  double timeout_ = 60.0;
};

} // namespace robot
} // namespace ros2vtk

#endif
