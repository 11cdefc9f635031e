// ros2vtk — every ros2vtk::convert helper in one include, for generated converter files.
#ifndef ros2vtk_convert_Convert_hpp
#define ros2vtk_convert_Convert_hpp

#include "ros2vtk/convert/Arrays.hpp"
#include "ros2vtk/convert/CompressedImage.hpp"
#include "ros2vtk/convert/Image.hpp"
#include "ros2vtk/convert/JointState.hpp"
#include "ros2vtk/convert/Marker.hpp"
#include "ros2vtk/convert/MultiArray.hpp"
#include "ros2vtk/convert/PointCloud2.hpp"
#include "ros2vtk/convert/Points.hpp"
#include "ros2vtk/convert/Polyline.hpp"
#include "ros2vtk/convert/RigidTransform.hpp"
#include "ros2vtk/convert/Stamp.hpp"
#include "ros2vtk/convert/Units.hpp"
#include "ros2vtk/convert/Values.hpp"

#endif
