// ros2vtk — ROS 2 name rules (rcl/src/rcl/expand_topic_name.c, rmw names.hpp, demangle.cpp).
#include "ros2vtk/wire/Names.hpp"

#include <cctype>
#include <vector>

namespace ros2vtk {
namespace wire {
namespace {

bool set_error(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
  return false;
}

// rmw's RMW_TOPIC_MAX_NAME_LENGTH (255 - 8): room for the DDS prefix and the service suffixes.
const size_t topic_name_max_length = 255 - 8;

bool is_token_char(char c)
{
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// A fully qualified name: starts with '/', tokens of [A-Za-z0-9_] not starting with a digit,
// no empty token, no trailing '/' (except the root namespace "/" when allowed).
bool validate_fully_qualified(
  const std::string& name, bool allow_root, const char* what, size_t max_length, std::string* error)
{
  if (name.empty() || name[0] != '/')
  {
    return set_error(error, std::string(what) + " '" + name + "' must start with '/'");
  }
  if (name == "/")
  {
    return allow_root ? true : set_error(error, std::string(what) + " '/' has no name");
  }
  if (name.back() == '/')
  {
    return set_error(error, std::string(what) + " '" + name + "' must not end with '/'");
  }
  size_t token_start = 1;
  for (size_t i = 1; i <= name.size(); ++i)
  {
    if (i == name.size() || name[i] == '/')
    {
      if (i == token_start)
      {
        return set_error(error, std::string(what) + " '" + name + "' contains '//'");
      }
      if (std::isdigit(static_cast<unsigned char>(name[token_start])))
      {
        return set_error(
          error, std::string(what) + " '" + name + "' has a token starting with a digit");
      }
      token_start = i + 1;
      continue;
    }
    if (!is_token_char(name[i]))
    {
      return set_error(error,
        std::string(what) + " '" + name + "' contains '" + std::string(1, name[i]) +
          "' (allowed: letters, digits, '_' and '/')");
    }
  }
  if (name.size() > max_length)
  {
    return set_error(error,
      std::string(what) + " '" + name + "' is longer than " + std::to_string(max_length) +
        " characters");
  }
  return true;
}

} // namespace

bool validate_node_name(const std::string& name, std::string* error)
{
  if (name.empty())
  {
    return set_error(error, "node name must not be empty");
  }
  if (std::isdigit(static_cast<unsigned char>(name[0])))
  {
    return set_error(error, "node name '" + name + "' must not start with a digit");
  }
  for (char c : name)
  {
    if (!is_token_char(c))
    {
      return set_error(error,
        "node name '" + name + "' contains '" + std::string(1, c) +
          "' (allowed: letters, digits and '_')");
    }
  }
  if (name.size() > 255)
  {
    return set_error(error, "node name '" + name + "' is longer than 255 characters");
  }
  return true;
}

bool normalize_namespace(const std::string& ns, std::string& normalized, std::string* error)
{
  std::string candidate = ns.empty() ? "/" : ns;
  if (candidate[0] != '/')
  {
    candidate = "/" + candidate;
  }
  if (!validate_fully_qualified(candidate, true, "namespace", 255, error))
  {
    return false;
  }
  normalized = candidate;
  return true;
}

std::string fully_qualified_node_name(const std::string& ns, const std::string& node)
{
  return ns == "/" ? "/" + node : ns + "/" + node;
}

bool validate_topic_name(const std::string& name, std::string* error)
{
  auto fail = [&](const std::string& why) {
    return set_error(error, "topic name '" + name + "' " + why);
  };
  if (name.empty())
  {
    return set_error(error, "topic name must not be empty");
  }
  if (std::isdigit(static_cast<unsigned char>(name[0])))
  {
    return fail("must not start with a digit");
  }
  if (name.back() == '/')
  {
    return fail("must not end with '/'");
  }
  bool in_substitution = false;
  for (size_t i = 0; i < name.size(); ++i)
  {
    const char c = name[i];
    if (is_token_char(c))
    {
      if (in_substitution && name[i - 1] == '{' && std::isdigit(static_cast<unsigned char>(c)))
      {
        return fail("has a substitution starting with a digit");
      }
    }
    else if (c == '/' && !in_substitution)
    {
      continue;
    }
    else if (c == '~')
    {
      if (i != 0)
      {
        return fail("has '~' that is not its first character");
      }
    }
    else if (c == '{' && !in_substitution)
    {
      in_substitution = true;
    }
    else if (c == '}')
    {
      if (!in_substitution)
      {
        return fail("has an unmatched '}'");
      }
      in_substitution = false;
    }
    else if (in_substitution)
    {
      return fail(
        "has '" + std::string(1, c) + "' inside a substitution (allowed: letters, digits and '_')");
    }
    else
    {
      return fail("contains '" + std::string(1, c) +
        "' (allowed: letters, digits, '_', '/', '~', '{' and '}')");
    }
  }
  if (in_substitution)
  {
    return fail("has an unmatched '{'");
  }
  // As rcl: a token after '/' must not start with a digit, and '~' must be followed by '/'.
  // rcl checks the latter only when a third character exists, so "~x" stays valid (-> /node_fqnx).
  for (size_t i = 0; i + 1 < name.size(); ++i)
  {
    if (name[i] == '/')
    {
      if (std::isdigit(static_cast<unsigned char>(name[i + 1])))
      {
        return fail("has a token starting with a digit");
      }
    }
    else if (i == 1 && name[0] == '~')
    {
      return fail("has '~' not followed by '/'");
    }
  }
  return true;
}

bool expand_topic_name(const std::string& name, const std::string& node_name, const std::string& ns,
  std::string& expanded, std::string* error)
{
  if (!validate_topic_name(name, error))
  {
    return false;
  }
  // rcl_expand_topic_name: '~' (first character only) becomes the node's fully qualified name,
  // then every {substitution} is replaced, then a still-relative name goes under the namespace.
  std::string result;
  size_t i = 0;
  if (name[0] == '~')
  {
    result = fully_qualified_node_name(ns, node_name);
    i = 1;
  }
  while (i < name.size())
  {
    if (name[i] != '{')
    {
      result += name[i++];
      continue;
    }
    const size_t close = name.find('}', i); // validate_topic_name guarantees it exists
    const std::string key = name.substr(i + 1, close - i - 1);
    if (key == "node")
    {
      result += node_name;
    }
    else if (key == "ns" || key == "namespace")
    {
      result += ns;
    }
    else
    {
      return set_error(error,
        "topic name '" + name + "': unknown substitution {" + key +
          "} (known: {node}, {ns}, {namespace})");
    }
    i = close + 1;
  }
  if (result[0] != '/')
  {
    result = ns == "/" ? "/" + result : ns + "/" + result;
  }
  if (!validate_fully_qualified(result, false, "topic name", topic_name_max_length, error))
  {
    if (error && result != name)
    {
      *error +=
        " (expanded from '" + name + "' by node '" + node_name + "' in namespace '" + ns + "')";
    }
    return false;
  }
  expanded = result;
  return true;
}

std::string topic_to_dds(const std::string& ros_topic)
{
  return "rt" + ros_topic;
}

std::string service_request_to_dds(const std::string& ros_service)
{
  return "rq" + ros_service + "Request";
}

std::string service_reply_to_dds(const std::string& ros_service)
{
  return "rr" + ros_service + "Reply";
}

bool dds_to_topic(const std::string& dds_topic, std::string& ros_topic)
{
  if (dds_topic.size() < 3 || dds_topic.compare(0, 3, "rt/") != 0)
  {
    return false;
  }
  ros_topic = dds_topic.substr(2);
  return true;
}

std::string dds_type_to_ros(const std::string& dds_type)
{
  const std::string marker = "dds_::";
  const size_t pos = dds_type.find(marker);
  if (pos == std::string::npos || dds_type.empty() || dds_type.back() != '_')
  {
    return dds_type;
  }
  std::string prefix = dds_type.substr(0, pos);
  std::string result;
  for (size_t i = 0; i < prefix.size(); ++i)
  {
    if (prefix.compare(i, 2, "::") == 0)
    {
      result += '/';
      ++i;
    }
    else
    {
      result += prefix[i];
    }
  }
  return result + dds_type.substr(pos + marker.size(), dds_type.size() - pos - marker.size() - 1);
}

} // namespace wire
} // namespace ros2vtk
