// ros2vtk — the types one node uses, as rcl's node_type_cache: every publisher, subscription,
// service server and client registers its type's REP 2011 description under the type's RIHS01
// hash while it exists, so the node's ~/get_type_description (TypeDescriptionService) serves
// exactly the types in use. Plain C++ (no DDS), so it is easy to test.
#ifndef ros2vtk_wire_NodeTypeCache_hpp
#define ros2vtk_wire_NodeTypeCache_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace ros2vtk {
namespace wire {

class NodeTypeCache
{
public:
  /// One endpoint's hold on its type: the type stays served until every registration of it is
  /// gone (rcl counts them the same way). Move-only; empty when nothing was registered.
  class Registration
  {
  public:
    Registration() = default;
    ~Registration();
    Registration(Registration&& other) noexcept;
    Registration& operator=(Registration&& other) noexcept;
    Registration(const Registration&) = delete;
    Registration& operator=(const Registration&) = delete;

  private:
    friend class NodeTypeCache;
    Registration(NodeTypeCache* cache, std::string type_hash);
    void release();
    NodeTypeCache* cache_ = nullptr;
    std::string type_hash_;
  };

  /// Registers `description` under `type_hash` ("RIHS01_<64 hex>"). Hand-written type tables
  /// (tests) have neither: nothing is registered and the registration is empty.
  Registration add(const char* type_hash, const TypeDescriptionTable* description);

  /// The description of a type in use with this hash (compared case-insensitively, as rosidl
  /// parses hashes), or nullptr.
  const TypeDescriptionTable* find(const std::string& type_hash) const;

  /// How many distinct types are in use.
  size_t size() const;

private:
  void remove(const std::string& type_hash);

  struct Entry
  {
    const TypeDescriptionTable* description = nullptr;
    size_t references = 0;
  };
  mutable std::mutex mutex_;             // endpoints come and go from any thread
  std::map<std::string, Entry> entries_; // by lower-case hash
};

} // namespace wire
} // namespace ros2vtk

#endif
