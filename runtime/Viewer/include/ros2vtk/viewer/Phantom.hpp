// ros2vtk — a CT-like phantom made on the spot (no download): the set-up of the SlicerROS2
// paper's motion-planning experiment, a gel block holding a tongue-like soft-tissue shape with
// a denser pseudotumour inside and fiducial beads on its surface, in Hounsfield-like units.
#ifndef ros2vtk_viewer_Phantom_hpp
#define ros2vtk_viewer_Phantom_hpp

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkImageData;

namespace ros2vtk {
namespace viewer {

struct PhantomOptions
{
  std::array<int, 3> dimensions{ 160, 128, 96 }; ///< voxels
  double spacing = 1.0;                          ///< mm, isotropic
  unsigned seed = 7;                             ///< noise is deterministic
};

/// What is where, in the image's own frame (mm), for examples and tests.
struct PhantomLayout
{
  std::array<double, 3> block_min{}; ///< gel block corners
  std::array<double, 3> block_max{};
  std::array<double, 3> tissue_center{};
  std::array<double, 3> tissue_radii{}; ///< half-axes of the tongue-like ellipsoid
  std::array<double, 3> tumor_center{};
  double tumor_radius = 0.0;
  std::vector<std::array<double, 3>> fiducials;
  double fiducial_radius = 0.0;
};

/// Hounsfield-like values used, so a standard soft-tissue window (W 400 / L 40) shows it.
struct PhantomValues
{
  static constexpr short kAir = -1000;
  static constexpr short kGel = 10;
  static constexpr short kTissue = 60;
  static constexpr short kTumor = 160;
  static constexpr short kFiducial = 1500;
};

/// Builds the volume (signed short scalars, origin at 0). `layout` may be null.
vtkSmartPointer<vtkImageData> make_phantom(const PhantomOptions& options, PhantomLayout* layout);

/// Writes it as MetaImage (.mha, what Slicer and VTK read); false + message on failure.
bool write_phantom(vtkImageData* image, const std::string& path, std::string* error);

} // namespace viewer
} // namespace ros2vtk

#endif
