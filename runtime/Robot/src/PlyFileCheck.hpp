// ros2vtk — checks a PLY file against its own header before assimp reads it.
//
// Why by hand: assimp 5.2 trusts a PLY file (a header cut short never returns, a face line with an
// extra value ends in SIGBUS: tests/fuzz/crashes), and VTK 9.1's PLY reader crashes on malformed
// files too (see MeshLoader.cpp). No library validates a PLY without reading it, so this walks the
// header grammar and then every record of the body once (linear in the file size): ASCII records
// one per line with exactly the values the header announces, binary records within the file, list
// counts in range and vertex indices below the vertex count. Only a file that passes goes on.
#ifndef ros2vtk_robot_PlyFileCheck_hpp
#define ros2vtk_robot_PlyFileCheck_hpp

#include <string>

namespace ros2vtk {
namespace robot {

class PlyFileCheck
{
public:
  /// True when `path` is a PLY file whose body matches its header; otherwise false and a message
  /// naming the file, the line or byte offset and what is wrong.
  static bool check(const std::string& path, std::string* error);
};

} // namespace robot
} // namespace ros2vtk

#endif
