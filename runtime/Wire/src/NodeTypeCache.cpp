// ros2vtk — the types one node uses (rcl's node_type_cache).
#include "ros2vtk/wire/NodeTypeCache.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace ros2vtk {
namespace wire {

namespace {

std::string lower_case(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace

NodeTypeCache::Registration::Registration(NodeTypeCache* cache, std::string type_hash)
  : cache_(cache)
  , type_hash_(std::move(type_hash))
{
}

NodeTypeCache::Registration::~Registration()
{
  this->release();
}

NodeTypeCache::Registration::Registration(Registration&& other) noexcept
  : cache_(other.cache_)
  , type_hash_(std::move(other.type_hash_))
{
  other.cache_ = nullptr;
}

NodeTypeCache::Registration& NodeTypeCache::Registration::operator=(Registration&& other) noexcept
{
  if (this != &other)
  {
    this->release();
    cache_ = other.cache_;
    type_hash_ = std::move(other.type_hash_);
    other.cache_ = nullptr;
  }
  return *this;
}

void NodeTypeCache::Registration::release()
{
  if (cache_)
  {
    cache_->remove(type_hash_);
    cache_ = nullptr;
  }
}

NodeTypeCache::Registration NodeTypeCache::add(
  const char* type_hash, const TypeDescriptionTable* description)
{
  if (!type_hash || !*type_hash || !description)
  {
    return Registration();
  }
  std::string key = lower_case(type_hash);
  std::lock_guard<std::mutex> lock(mutex_);
  Entry& entry = entries_[key];
  entry.description = description;
  ++entry.references;
  return Registration(this, std::move(key));
}

void NodeTypeCache::remove(const std::string& type_hash)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = entries_.find(type_hash);
  if (it != entries_.end() && --it->second.references == 0)
  {
    entries_.erase(it);
  }
}

const TypeDescriptionTable* NodeTypeCache::find(const std::string& type_hash) const
{
  const std::string key = lower_case(type_hash);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : it->second.description;
}

size_t NodeTypeCache::size() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

} // namespace wire
} // namespace ros2vtk
