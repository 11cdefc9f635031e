// ros2vtk — VTK's output window that also publishes warnings and errors on /rosout.
#include "vtkROS2OutputWindow.h"

#include "ros2vtk/wire/Rosout.hpp"

#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <cstdlib>
#include <string>

vtkStandardNewMacro(vtkROS2OutputWindow);

namespace {
// Publishing could itself report a problem through VTK; that report must not publish again.
thread_local bool Publishing = false;
}

//------------------------------------------------------------------------------
vtkROS2OutputWindow::vtkROS2OutputWindow() = default;
vtkROS2OutputWindow::~vtkROS2OutputWindow() = default;

//------------------------------------------------------------------------------
void vtkROS2OutputWindow::Install()
{
  vtkOutputWindow* current = vtkOutputWindow::GetInstance();
  if (vtkROS2OutputWindow::SafeDownCast(current))
  {
    return;
  }
  vtkNew<vtkROS2OutputWindow> window;
  window->Previous = current;
  vtkOutputWindow::SetInstance(window);
}

//------------------------------------------------------------------------------
void vtkROS2OutputWindow::ParseVTKMessage(
  const char* text, std::string& file, int& line, std::string& function, std::string& message)
{
  file.clear();
  function.clear();
  line = 0;
  std::string rest = text ? text : "";
  // "Warning: In FILE, line N\n" / "ERROR: In FILE, line N\n"
  const size_t in = rest.find("In ");
  const size_t newline = rest.find('\n');
  if (in != std::string::npos && newline != std::string::npos && in < newline)
  {
    const std::string where = rest.substr(in + 3, newline - in - 3);
    const size_t comma = where.rfind(", line ");
    if (comma != std::string::npos)
    {
      file = where.substr(0, comma);
      line = std::atoi(where.c_str() + comma + 7);
    }
    rest = rest.substr(newline + 1);
  }
  // "vtkROS2SubscriberNode (0x55d0c8e0): message"
  const size_t open = rest.find(" (");
  const size_t close = rest.find("): ");
  if (open != std::string::npos && close != std::string::npos && open < close &&
    rest.find(' ') == open)
  {
    function = rest.substr(0, open);
    rest = rest.substr(close + 3);
  }
  while (!rest.empty() && (rest.back() == '\n' || rest.back() == ' '))
  {
    rest.pop_back();
  }
  message = rest;
}

//------------------------------------------------------------------------------
void vtkROS2OutputWindow::Publish(int severity, const char* text)
{
  if (Publishing)
  {
    return;
  }
  Publishing = true;
  std::string file, function, message;
  int line = 0;
  ParseVTKMessage(text, file, line, function, message);
  ros2vtk::wire::Rosout::log(static_cast<ros2vtk::wire::LogSeverity>(severity), message, file,
    function, static_cast<uint32_t>(line > 0 ? line : 0));
  Publishing = false;
}

//------------------------------------------------------------------------------
void vtkROS2OutputWindow::DisplayErrorText(const char* text)
{
  this->Publish(static_cast<int>(ros2vtk::wire::LogSeverity::Error), text);
  if (this->Previous)
  {
    this->Previous->DisplayErrorText(text);
  }
}

void vtkROS2OutputWindow::DisplayWarningText(const char* text)
{
  this->Publish(static_cast<int>(ros2vtk::wire::LogSeverity::Warn), text);
  if (this->Previous)
  {
    this->Previous->DisplayWarningText(text);
  }
}

void vtkROS2OutputWindow::DisplayGenericWarningText(const char* text)
{
  this->Publish(static_cast<int>(ros2vtk::wire::LogSeverity::Warn), text);
  if (this->Previous)
  {
    this->Previous->DisplayGenericWarningText(text);
  }
}

void vtkROS2OutputWindow::DisplayDebugText(const char* text)
{
  this->Publish(static_cast<int>(ros2vtk::wire::LogSeverity::Debug), text);
  if (this->Previous)
  {
    this->Previous->DisplayDebugText(text);
  }
}

void vtkROS2OutputWindow::DisplayText(const char* text)
{
  if (this->Previous)
  {
    this->Previous->DisplayText(text);
  }
}

//------------------------------------------------------------------------------
void vtkROS2OutputWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Previous: " << (this->Previous ? this->Previous->GetClassName() : "(none)")
     << "\n";
}
