// ros2vtk — xacro expansion through the xacro program (see the header for why a child process).
#include "ros2vtk/robot/XacroProcessor.hpp"

#include <vtksys/Process.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>
#include <system_error>

namespace ros2vtk {
namespace robot {
namespace {

bool is_executable(const std::filesystem::path& path)
{
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(status))
    return false;
  using std::filesystem::perms;
  return (status.permissions() & (perms::owner_exec | perms::group_exec | perms::others_exec)) !=
    perms::none;
}

std::string on_path(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':'))
  {
    if (!folder.empty() && is_executable(std::filesystem::path(folder) / program))
      return (std::filesystem::path(folder) / program).string();
  }
  return "";
}

// The last lines of xacro's error output, on one line: its message is at the end, after any
// traceback.
std::string last_lines(const std::string& text, size_t count, size_t max_chars)
{
  std::vector<std::string> lines;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      lines.push_back(line);
  }
  std::string tail;
  for (size_t i = lines.size() > count ? lines.size() - count : 0; i < lines.size(); ++i)
    tail += (tail.empty() ? "" : " ") + lines[i];
  if (tail.size() > max_chars)
    tail = "..." + tail.substr(tail.size() - max_chars);
  return tail;
}

struct ProcessDeleter
{
  void operator()(vtksysProcess* process) const { vtksysProcess_Delete(process); }
};

} // namespace

bool XacroProcessor::is_xacro_file(const std::string& path)
{
  const std::string suffix = ".xacro";
  if (path.size() < suffix.size())
    return false;
  std::string end = path.substr(path.size() - suffix.size());
  std::transform(
    end.begin(), end.end(), end.begin(), [](unsigned char c) { return std::tolower(c); });
  return end == suffix;
}

bool XacroProcessor::set_arguments(const std::string& arguments, std::string* error)
{
  std::vector<std::string> parsed;
  std::stringstream items(arguments);
  std::string item;
  while (items >> item)
  {
    const size_t assign = item.find(":=");
    if (assign == std::string::npos || assign == 0)
    {
      if (error)
        *error = "xacro argument '" + item + "' is not name:=value";
      return false;
    }
    parsed.push_back(item);
  }
  arguments_ = std::move(parsed);
  return true;
}

std::string XacroProcessor::find_command(std::string* searched) const
{
  std::vector<std::string> looked;
  if (!command_.empty())
  {
    const bool found = command_.find('/') == std::string::npos ? !on_path(command_).empty()
                                                               : is_executable(command_);
    if (found)
      return command_.find('/') == std::string::npos ? on_path(command_) : command_;
    looked.push_back("the command set on the robot ('" + command_ + "')");
  }
  else
  {
    if (const char* variable = std::getenv("ROS2VTK_XACRO"); variable && *variable)
    {
      if (is_executable(variable))
        return variable;
      looked.push_back(std::string("$ROS2VTK_XACRO ('") + variable + "')");
    }
    const std::string found = on_path("xacro");
    if (!found.empty())
      return found;
    looked.push_back("'xacro' on PATH");
    if (const char* venv = std::getenv("ROS2VTK_VENV"); venv && *venv)
    {
      const auto candidate = std::filesystem::path(venv) / "bin" / "xacro";
      if (is_executable(candidate))
        return candidate.string();
      looked.push_back(candidate.string());
    }
  }
  if (searched)
  {
    std::string joined;
    for (const auto& place : looked)
      joined += (joined.empty() ? "" : ", ") + place;
    *searched = joined;
  }
  return "";
}

bool XacroProcessor::expand(
  const std::string& path, size_t max_bytes, std::string* urdf, std::string* error) const
{
  auto fail = [&](const std::string& why) {
    if (error)
      *error = "cannot expand the xacro file '" + path + "': " + why;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return fail("no such file");
  std::string searched;
  const std::string command = find_command(&searched);
  if (command.empty())
    return fail("no xacro processor found (looked for " + searched +
      "); install it into the Python environment ros2vtk runs in: pip install xacro");

  std::vector<std::string> words{ command, path };
  words.insert(words.end(), arguments_.begin(), arguments_.end());
  std::vector<const char*> argv;
  for (const auto& word : words)
    argv.push_back(word.c_str());
  argv.push_back(nullptr);

  std::unique_ptr<vtksysProcess, ProcessDeleter> process(vtksysProcess_New());
  vtksysProcess_SetCommand(process.get(), argv.data());
  vtksysProcess_SetTimeout(process.get(), timeout_);
  vtksysProcess_Execute(process.get());
  std::string out, err;
  bool too_large = false;
  char* data = nullptr;
  int length = 0;
  int pipe;
  while ((pipe = vtksysProcess_WaitForData(process.get(), &data, &length, nullptr)) !=
    vtksysProcess_Pipe_None)
  {
    std::string& target = pipe == vtksysProcess_Pipe_STDOUT ? out : err;
    if (pipe == vtksysProcess_Pipe_STDOUT || pipe == vtksysProcess_Pipe_STDERR)
    {
      if (target.size() + static_cast<size_t>(length) > max_bytes)
      {
        too_large = true;
        vtksysProcess_Kill(process.get());
        continue;
      }
      target.append(data, static_cast<size_t>(length));
    }
  }
  vtksysProcess_WaitForExit(process.get(), nullptr);
  if (too_large)
    return fail("its output is over the limit of " + std::to_string(max_bytes) + " bytes");
  switch (vtksysProcess_GetState(process.get()))
  {
    case vtksysProcess_State_Exited:
      break;
    case vtksysProcess_State_Expired:
      return fail(
        command + " did not finish in " + std::to_string(static_cast<int>(timeout_)) + " s");
    case vtksysProcess_State_Exception:
      return fail(command + " crashed: " + vtksysProcess_GetExceptionString(process.get()));
    case vtksysProcess_State_Error:
      return fail("cannot run " + command + ": " + vtksysProcess_GetErrorString(process.get()));
    default:
      return fail(command + " was stopped");
  }
  const int status = vtksysProcess_GetExitValue(process.get());
  if (status != 0)
    return fail("xacro failed (exit " + std::to_string(status) + "): " + last_lines(err, 3, 600));
  if (out.find_first_not_of(" \t\r\n") == std::string::npos)
    return fail("xacro wrote no URDF");
  *urdf = std::move(out);
  return true;
}

} // namespace robot
} // namespace ros2vtk
