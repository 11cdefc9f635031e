"""Derived names: the rosidl snake_case rule, C++ namespaces, DDS type names, paths, guards."""
import pytest

from ros2vtk_gen import naming
from ros2vtk_gen.msg_parser import parse_message_text, parse_service_text


@pytest.mark.parametrize("camel,snake", [
    ("Header", "header"), ("PointCloud2", "point_cloud2"), ("TFMessage", "tf_message"),
    ("Float64MultiArray", "float64_multi_array"), ("Int64", "int64"),
    ("ParticipantEntitiesInfo", "participant_entities_info"),
    ("GetParameters_Request", "get_parameters__request"), ("Point32", "point32"),
])
def test_snake_case_like_rosidl(camel, snake):
    assert naming.snake_case(camel) == snake


def test_message_names():
    message = parse_message_text("int32 x\n", "geometry_msgs", "PoseStamped")
    assert naming.cpp_qualified_name(message) == "ros2vtk::geometry_msgs::msg::PoseStamped"
    assert naming.dds_type_name(message) == "geometry_msgs::msg::dds_::PoseStamped_"
    assert naming.message_header(message) == "ros2vtk/geometry_msgs/msg/pose_stamped.hpp"
    assert naming.source_path("geometry_msgs", "msg", "PoseStamped", "cdr") == \
        "geometry_msgs/msg/pose_stamped__cdr.cpp"
    assert naming.include_guard("ros2vtk/std_msgs/msg/header.hpp") == \
        "ROS2VTK__STD_MSGS__MSG__HEADER_HPP_"


def test_service_names():
    service = parse_service_text("string[] names\n---\nbool ok\n", "rcl_interfaces",
                                 "GetParameters")
    assert naming.dds_type_name(service.request) == \
        "rcl_interfaces::srv::dds_::GetParameters_Request_"
    assert naming.dds_type_name(service.response) == \
        "rcl_interfaces::srv::dds_::GetParameters_Response_"
    assert naming.cpp_qualified_name(service.request) == \
        "ros2vtk::rcl_interfaces::srv::GetParameters_Request"
    assert naming.service_header(service) == "ros2vtk/rcl_interfaces/srv/get_parameters.hpp"
    assert naming.message_header(service.response) == \
        "ros2vtk/rcl_interfaces/srv/get_parameters__response.hpp"


def test_register_function_of_a_target():
    assert naming.register_function(naming.c_identifier("ros2vtk-extra.msgs")) == \
        "ros2vtk_register_ros2vtk_extra_msgs_types"
