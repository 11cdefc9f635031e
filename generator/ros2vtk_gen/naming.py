"""Every name derived from a ROS type, in one place (C++ names, files, DDS names, guards)."""
from __future__ import annotations

import re

from .model import Action, BaseType, Message, Service

CPP_ROOT_NAMESPACE = "ros2vtk"


def snake_case(name: str) -> str:
    """CamelCase -> snake_case as rosidl names its files: PointCloud2 -> point_cloud2,
    TFMessage -> tf_message, GetParameters_Request -> get_parameters__request."""
    value = re.sub(r"(.)([A-Z][a-z]+)", r"\1_\2", name)
    value = re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", value)
    return value.lower()


def cpp_namespace(package: str, kind: str) -> str:
    """ros2vtk::<pkg>::msg (rosidl's tail under our prefix, so no clash with a ROS install)."""
    return f"{CPP_ROOT_NAMESPACE}::{package}::{kind}"


def cpp_qualified_name(message: Message) -> str:
    return f"{cpp_namespace(message.package, message.kind)}::{message.name}"


def cpp_type_of_message(base: BaseType) -> str:
    """Fully qualified C++ struct of a referenced message type."""
    return f"::{cpp_namespace(str(base.package), base.interface)}::{base.name}"


def dds_type_name(message: Message) -> str:
    """`pkg::msg::dds_::Type_`; services: `pkg::srv::dds_::Srv_Request_` (rmw_fastrtps)."""
    return f"{message.package}::{message.kind}::dds_::{message.name}_"


def header_path(package: str, kind: str, name: str) -> str:
    """Include path, as written in #include and relative to the output's include/ folder."""
    return f"ros2vtk/{package}/{kind}/{snake_case(name)}.hpp"


def message_header(message: Message) -> str:
    return header_path(message.package, message.kind, message.name)


def service_header(service: Service) -> str:
    return header_path(service.package, service.kind, service.name)


def action_header(action: Action) -> str:
    return header_path(action.package, "action", action.name)


def source_path(package: str, kind: str, name: str, artefact: str) -> str:
    """Source path relative to the output's src/ folder: `<pkg>/<kind>/<snake>__<artefact>.cpp`."""
    return f"{package}/{kind}/{snake_case(name)}__{artefact}.cpp"


def include_guard(include_path: str) -> str:
    """ros2vtk/std_msgs/msg/header.hpp -> ROS2VTK__STD_MSGS__MSG__HEADER_HPP_"""
    return re.sub(r"[^A-Za-z0-9_]", "__", include_path.replace(".hpp", "_hpp")).upper() + "_"


def register_function(target: str) -> str:
    """The exported C function a generated library offers to force its registration."""
    return f"ros2vtk_register_{target}_types"


def register_header(target: str) -> str:
    """Include path (under include/) of the header declaring a message library's register
    function: ros2vtk/ros2vtkMessagesRegister.hpp."""
    return f"ros2vtk/{c_identifier(target)}Register.hpp"


def c_identifier(name: str) -> str:
    """A CMake target name made safe for use inside a C identifier."""
    return re.sub(r"[^A-Za-z0-9_]", "_", name)
