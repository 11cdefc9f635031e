// ros2vtk — parsed robot meshes kept for the next load, keyed by file, modification time, size
// and scale.
//
// Reading a large Collada mesh costs far more than drawing it (20 MB: ~0.6 s). A loader keeps
// its own cache by default; the scene's robot nodes share the process-wide one, so a reload, a
// second robot with the same meshes, or a robot whose description changed only in its joints
// reads no mesh file again. Bounded in memory: least recently used meshes go first.
#ifndef ros2vtk_robot_MeshCache_hpp
#define ros2vtk_robot_MeshCache_hpp

#include "ros2vtk/robot/MeshLoader.hpp"

#include <array>
#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace ros2vtk {
namespace robot {

class MeshCache
{
public:
  /// Meshes kept up to `max_bytes` (their polydata's memory), 512 MiB by default.
  explicit MeshCache(size_t max_bytes = size_t(512) << 20);

  /// The cache the scene's robot nodes share.
  static std::shared_ptr<MeshCache> shared();

  /// The key of a file as it is now: a changed file (time or size) is a new key.
  static std::string key_of(const std::string& path, const std::array<double, 3>& scale);

  /// True and the mesh when `key` is cached. Thread-safe.
  bool find(const std::string& key, MeshData* mesh);
  /// Keeps a copy of `mesh` (its polydata shared, to be treated as read-only by everyone).
  void insert(const std::string& key, const MeshData& mesh);

  void clear();
  size_t size() const;
  size_t bytes() const;

private:
  void evict_locked();

  struct Entry
  {
    MeshData mesh;
    size_t bytes = 0;
    std::list<std::string>::iterator use; // position in uses_
  };
  mutable std::mutex mutex_;
  size_t max_bytes_;
  size_t bytes_ = 0;
  std::map<std::string, Entry> entries_;
  std::list<std::string> uses_; // most recently used first
};

} // namespace robot
} // namespace ros2vtk

#endif
