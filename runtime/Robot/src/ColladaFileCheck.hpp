// ros2vtk — checks the numbers of a Collada file before assimp reads it.
//
// Why by hand: assimp 5.2 trusts the counts and index lists of a Collada file; one corrupted byte
// inside a <p> index list made it ask for 400 MB (tests/fuzz/crashes), and a mutated count makes
// it reserve what the count says. No library checks a Collada document's arrays against each
// other, so this parses the XML with tinyxml2 (well-formedness, its depth limit) and walks the
// elements once: every array holds only numbers of its kind and exactly the count it announces,
// every accessor stays inside its array, and every primitive's index lists match its count and
// inputs. Only a file that passes goes on to assimp.
#ifndef ros2vtk_robot_ColladaFileCheck_hpp
#define ros2vtk_robot_ColladaFileCheck_hpp

#include <string>

namespace ros2vtk {
namespace robot {

class ColladaFileCheck
{
public:
  /// True when `path` is well-formed XML whose geometry arrays, accessors and primitives agree;
  /// otherwise false and a message naming the file, the element (with its line) and the problem.
  static bool check(const std::string& path, std::string* error);
};

} // namespace robot
} // namespace ros2vtk

#endif
