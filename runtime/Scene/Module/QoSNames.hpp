// ros2vtk — QoS policy names as ROS 2 spells them ("best_effort", "transient_local", …), for the
// scene's QoS setters and scene files. Private to the Scene module.
#ifndef ros2vtk_scene_QoSNames_hpp
#define ros2vtk_scene_QoSNames_hpp

#include "ros2vtk/wire/QoS.hpp"

namespace ros2vtk {
namespace scene {

/// Each parse_* returns false (leaving `value` alone) for a null or unknown name.
bool parse_reliability(const char* name, wire::QoS::Reliability& value);
bool parse_durability(const char* name, wire::QoS::Durability& value);
bool parse_history(const char* name, wire::QoS::History& value);

const char* to_name(wire::QoS::Reliability value);
const char* to_name(wire::QoS::Durability value);
const char* to_name(wire::QoS::History value);

} // namespace scene
} // namespace ros2vtk

#endif
