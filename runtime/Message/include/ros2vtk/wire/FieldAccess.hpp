// ros2vtk — container accessors that generated introspection tables point at.
//
// One template per access pattern instead of one function per generated field: the generated
// tables name `&container_size<std::vector<double>>` and the compiler instantiates it once.
#ifndef ros2vtk_wire_FieldAccess_hpp
#define ros2vtk_wire_FieldAccess_hpp

#include <cstddef>
#include <tuple>

namespace ros2vtk {
namespace wire {

template<typename Container>
size_t container_size(const void* field)
{
  return static_cast<const Container*>(field)->size();
}

template<typename Container>
void* container_element(void* field, size_t index)
{
  return &(*static_cast<Container*>(field))[index];
}

/// std::vector (bounded or not): any size. Bounds are enforced by serialize/deserialize.
template<typename Container>
bool vector_resize(void* field, size_t count)
{
  static_cast<Container*>(field)->resize(count);
  return true;
}

/// std::array: only its own size.
template<typename Container>
bool array_resize(void*, size_t count)
{
  return count == std::tuple_size<Container>::value;
}

template<typename Container>
bool container_get_bool(const void* field, size_t index)
{
  return (*static_cast<const Container*>(field))[index];
}

template<typename Container>
void container_set_bool(void* field, size_t index, bool value)
{
  (*static_cast<Container*>(field))[index] = value;
}

} // namespace wire
} // namespace ros2vtk

#endif
