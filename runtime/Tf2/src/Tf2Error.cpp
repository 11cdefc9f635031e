#include "ros2vtk/tf2/Tf2Error.hpp"

namespace ros2vtk {
namespace tf2 {

const char* to_string(Tf2Error error)
{
  switch (error)
  {
    case Tf2Error::NoError:
      return "TF2_NO_ERROR";
    case Tf2Error::Lookup:
      return "TF2_LOOKUP_ERROR";
    case Tf2Error::Connectivity:
      return "TF2_CONNECTIVITY_ERROR";
    case Tf2Error::Extrapolation:
      return "TF2_EXTRAPOLATION_ERROR";
    case Tf2Error::InvalidArgument:
      return "TF2_INVALID_ARGUMENT_ERROR";
    case Tf2Error::Timeout:
      return "TF2_TIMEOUT_ERROR";
    case Tf2Error::Transform:
      return "TF2_TRANSFORM_ERROR";
    case Tf2Error::BackwardExtrapolation:
      return "TF2_BACKWARD_EXTRAPOLATION_ERROR";
    case Tf2Error::ForwardExtrapolation:
      return "TF2_FORWARD_EXTRAPOLATION_ERROR";
    case Tf2Error::NoDataForExtrapolation:
      return "TF2_NO_DATA_FOR_EXTRAPOLATION_ERROR";
  }
  return "TF2_UNKNOWN_ERROR";
}

bool is_extrapolation(Tf2Error error)
{
  return error == Tf2Error::Extrapolation || error == Tf2Error::BackwardExtrapolation ||
    error == Tf2Error::ForwardExtrapolation || error == Tf2Error::NoDataForExtrapolation;
}

} // namespace tf2
} // namespace ros2vtk
