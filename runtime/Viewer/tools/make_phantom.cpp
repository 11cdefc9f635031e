// ros2vtk-make-phantom OUT.mha — writes the demo's CT-like phantom and prints where things are.
#include "ros2vtk/viewer/Phantom.hpp"

#include <vtkImageData.h>

#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: ros2vtk-make-phantom OUT.mha\n";
    return 2;
  }
  ros2vtk::viewer::PhantomLayout layout;
  auto image = ros2vtk::viewer::make_phantom({}, &layout);
  std::string error;
  if (!ros2vtk::viewer::write_phantom(image, argv[1], &error))
  {
    std::cerr << "ros2vtk-make-phantom: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << argv[1] << ": tumour at (" << layout.tumor_center[0] << ", "
            << layout.tumor_center[1] << ", " << layout.tumor_center[2] << ") mm, radius "
            << layout.tumor_radius << " mm, " << layout.fiducials.size() << " fiducials\n";
  return 0;
}
