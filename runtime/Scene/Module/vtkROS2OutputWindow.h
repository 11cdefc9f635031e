// ros2vtk — VTK's output window that also tells ROS: the warnings and errors our scene nodes
// report (rejected messages, failed lookups, robot load problems) are published on /rosout of
// the process's ROS nodes as rcl_interfaces/msg/Log, besides being shown as before.
//
// vtkROS2Logic installs it (Install() is idempotent) in front of whatever output window was
// current, which keeps displaying every message: a console, Slicer's error log, a test's capture.
#ifndef vtkROS2OutputWindow_h
#define vtkROS2OutputWindow_h

#include "ros2vtkSceneModule.h" // for export macro

#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h" // for the previous window

#include <string> // for ParseVTKMessage

class ROS2VTKSCENE_EXPORT vtkROS2OutputWindow : public vtkOutputWindow
{
public:
  static vtkROS2OutputWindow* New();
  vtkTypeMacro(vtkROS2OutputWindow, vtkOutputWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Makes an instance of this class the output window (once per process), forwarding to the
  /// window that was current.
  static void Install();

  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char* text) override;
  void DisplayText(const char* text) override;

#ifndef __VTK_WRAP__
  /// Splits VTK's "Warning: In FILE, line N\nClass (0x…): message" into its parts (empty /
  /// 0 where the text has no such part). Public for tests.
  static void ParseVTKMessage(
    const char* text, std::string& file, int& line, std::string& function, std::string& message);
#endif

protected:
  vtkROS2OutputWindow();
  ~vtkROS2OutputWindow() override;

private:
  vtkROS2OutputWindow(const vtkROS2OutputWindow&) = delete;
  void operator=(const vtkROS2OutputWindow&) = delete;

  void Publish(int severity, const char* text);

  vtkSmartPointer<vtkOutputWindow> Previous;
};

#endif
