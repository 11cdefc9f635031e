// ros2vtk — what the scene's C++ tests share: an output window that keeps what VTK reported
// (tests assert on the wording of errors and warnings) and a spin loop with a timeout (tests
// wait for discovery and messages by spinning, never by sleeping a fixed time). Header-only,
// target ros2vtk_test_support (tests/CMakeLists.txt).
#ifndef ros2vtk_test_SceneTestSupport_hpp
#define ros2vtk_test_SceneTestSupport_hpp

#include "vtkROS2Logic.h"

#include "vtkOutputWindow.h"

#include <chrono>
#include <functional>
#include <string>
#include <thread>

namespace ros2vtk_test {

/// Install with vtkOutputWindow::SetInstance in SetUp, reset to nullptr in TearDown.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  // Not vtkStandardNewMacro: this header is included by several files of one test program.
  static CapturingOutputWindow* New()
  {
    auto* window = new CapturingOutputWindow;
    window->InitializeObjectBase();
    return window;
  }
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override { this->Errors += text; }
  void DisplayWarningText(const char* text) override
  {
    ++this->NumberOfWarnings;
    this->Warnings += text;
  }
  void DisplayText(const char* text) override { this->Text += text; }

  int NumberOfWarnings = 0;
  std::string Errors;
  std::string Warnings;
  std::string Text;
};

/// Spins `logic` until `done` or `seconds`; true when done.
inline bool SpinUntil(vtkROS2Logic* logic, const std::function<bool()>& done, double seconds = 10.0)
{
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end)
  {
    logic->Spin();
    if (done())
    {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return done();
}

} // namespace ros2vtk_test

#endif
