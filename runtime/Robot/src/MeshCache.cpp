// ros2vtk — the parsed-mesh cache (see the header).
#include "ros2vtk/robot/MeshCache.hpp"

#include <vtkPolyData.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace ros2vtk {
namespace robot {

MeshCache::MeshCache(size_t max_bytes)
  : max_bytes_(max_bytes)
{
}

std::shared_ptr<MeshCache> MeshCache::shared()
{
  static const std::shared_ptr<MeshCache> cache = std::make_shared<MeshCache>();
  return cache;
}

std::string MeshCache::key_of(const std::string& path, const std::array<double, 3>& scale)
{
  std::error_code ec;
  const auto stamp = std::filesystem::last_write_time(path, ec);
  const long long time = ec ? 0 : static_cast<long long>(stamp.time_since_epoch().count());
  const auto size = std::filesystem::file_size(path, ec);
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "|%lld|%llu|%.17g,%.17g,%.17g", time,
    static_cast<unsigned long long>(ec ? 0 : size), scale[0], scale[1], scale[2]);
  return path + buffer;
}

bool MeshCache::find(const std::string& key, MeshData* mesh)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = entries_.find(key);
  if (it == entries_.end())
    return false;
  uses_.splice(uses_.begin(), uses_, it->second.use);
  *mesh = it->second.mesh;
  return true;
}

void MeshCache::insert(const std::string& key, const MeshData& mesh)
{
  // vtkDataObject::GetActualMemorySize is in KiB.
  const size_t bytes = mesh.polydata ? size_t(mesh.polydata->GetActualMemorySize()) * 1024 : 0;
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = entries_.find(key);
  if (it != entries_.end())
  {
    bytes_ -= it->second.bytes;
    uses_.erase(it->second.use);
    entries_.erase(it);
  }
  if (bytes > max_bytes_)
    return; // larger than the whole cache: not kept
  uses_.push_front(key);
  entries_[key] = Entry{ mesh, bytes, uses_.begin() };
  bytes_ += bytes;
  evict_locked();
}

void MeshCache::evict_locked()
{
  while (bytes_ > max_bytes_ && !uses_.empty())
  {
    auto it = entries_.find(uses_.back());
    bytes_ -= it->second.bytes;
    entries_.erase(it);
    uses_.pop_back();
  }
}

void MeshCache::clear()
{
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.clear();
  uses_.clear();
  bytes_ = 0;
}

size_t MeshCache::size() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

size_t MeshCache::bytes() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return bytes_;
}

} // namespace robot
} // namespace ros2vtk
