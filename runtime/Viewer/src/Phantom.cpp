// ros2vtk — CT-like phantom: gel block, tongue-like tissue, pseudotumour, fiducial beads.
#include "ros2vtk/viewer/Phantom.hpp"

#include <vtkImageData.h>
#include <vtkMetaImageWriter.h>
#include <vtkNew.h>

#include <cmath>
#include <random>

namespace ros2vtk {
namespace viewer {

vtkSmartPointer<vtkImageData> make_phantom(const PhantomOptions& options, PhantomLayout* layout_out)
{
  const auto& dim = options.dimensions;
  const double s = options.spacing;
  const double ex = dim[0] * s, ey = dim[1] * s, ez = dim[2] * s;

  PhantomLayout layout;
  layout.block_min = { 0.1 * ex, 0.1 * ey, 0.1 * ez };
  layout.block_max = { 0.9 * ex, 0.9 * ey, 0.75 * ez };
  // The tongue: an elongated ellipsoid lying in the gel, its top flattened by the block surface.
  layout.tissue_center = { 0.5 * ex, 0.5 * ey, 0.45 * ez };
  layout.tissue_radii = { 0.32 * ex, 0.22 * ey, 0.22 * ez };
  layout.tumor_center = { 0.58 * ex, 0.46 * ey, 0.42 * ez };
  layout.tumor_radius = 0.06 * std::min(ex, std::min(ey, ez)) + 3.0;
  layout.fiducial_radius = 2.0 * s;
  // Beads on the top surface of the block, around the tissue (registration landmarks).
  const double top = layout.block_max[2];
  for (const auto& xy : { std::array<double, 2>{ 0.2, 0.2 }, std::array<double, 2>{ 0.8, 0.2 },
         std::array<double, 2>{ 0.8, 0.8 }, std::array<double, 2>{ 0.2, 0.8 },
         std::array<double, 2>{ 0.5, 0.15 }, std::array<double, 2>{ 0.35, 0.85 } })
  {
    layout.fiducials.push_back({ xy[0] * ex, xy[1] * ey, top });
  }

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dim[0], dim[1], dim[2]);
  image->SetSpacing(s, s, s);
  image->SetOrigin(0, 0, 0);
  image->AllocateScalars(VTK_SHORT, 1);
  short* voxels = static_cast<short*>(image->GetScalarPointer());

  std::mt19937 random(options.seed);
  std::normal_distribution<double> noise(0.0, 6.0);
  const auto& c = layout.tissue_center;
  const auto& r = layout.tissue_radii;
  size_t index = 0;
  for (int k = 0; k < dim[2]; ++k)
  {
    const double z = k * s;
    for (int j = 0; j < dim[1]; ++j)
    {
      const double y = j * s;
      for (int i = 0; i < dim[0]; ++i, ++index)
      {
        const double x = i * s;
        double value = PhantomValues::kAir;
        const bool in_block = x >= layout.block_min[0] && x <= layout.block_max[0] &&
          y >= layout.block_min[1] && y <= layout.block_max[1] && z >= layout.block_min[2] &&
          z <= layout.block_max[2];
        if (in_block)
        {
          value = PhantomValues::kGel;
          // Tongue-like: the ellipsoid narrows towards its tip (+x) and has a median groove.
          const double u = (x - c[0]) / r[0];
          const double taper = 1.0 - 0.35 * std::max(0.0, u);
          const double v = (y - c[1]) / (r[1] * taper);
          const double w = (z - c[2]) / (r[2] * taper);
          const double groove = 0.12 * std::exp(-v * v * 40.0) * (w > 0 ? 1.0 : 0.0);
          if (u * u + v * v + w * w <= 1.0 - groove)
          {
            value = PhantomValues::kTissue;
          }
          const double dx = x - layout.tumor_center[0], dy = y - layout.tumor_center[1],
                       dz = z - layout.tumor_center[2];
          // A slightly lobulated pseudotumour.
          const double lobes = 1.0 + 0.15 * std::sin(3.0 * std::atan2(dy, dx));
          if (std::sqrt(dx * dx + dy * dy + dz * dz) <= layout.tumor_radius * lobes)
          {
            value = PhantomValues::kTumor;
          }
          value += noise(random);
        }
        for (const auto& f : layout.fiducials)
        {
          const double fx = x - f[0], fy = y - f[1], fz = z - f[2];
          if (fx * fx + fy * fy + fz * fz <= layout.fiducial_radius * layout.fiducial_radius)
          {
            value = PhantomValues::kFiducial;
          }
        }
        voxels[index] = static_cast<short>(std::lround(value));
      }
    }
  }
  if (layout_out)
  {
    *layout_out = layout;
  }
  return image;
}

bool write_phantom(vtkImageData* image, const std::string& path, std::string* error)
{
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetCompression(true);
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    if (error)
      *error = "could not write the phantom to " + path;
    return false;
  }
  return true;
}

} // namespace viewer
} // namespace ros2vtk
