#include "vtkROS2MarkerSubscriberNode.h"

#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"

#include "ros2vtk/convert/Marker.hpp"
#include "ros2vtk/convert/Units.hpp"

#include "vtkPolyData.h"
#include "vtkXMLDataElement.h"

class vtkROS2MarkerSubscriberNode::vtkInternals
{
public:
  ros2vtk::convert::MarkerSet Markers;        // every received message folded in (OnNewMessages)
  std::vector<ros2vtk::convert::Marker> Read; // one message's markers (kept for its capacity)
  std::string FixedFrame;                     // SetFixedFrame ("" the scene's)
  std::string PlacedIn;        // the effective fixed frame of the latest placement ("" none)
  bool PlaceAll = false;       // every marker is placed again on the next spin
  std::string FoldError;       // what the latest spin's messages could not apply
  std::string WarnedFoldError; // the last reason warned about (once per reason)
};

//------------------------------------------------------------------------------
vtkROS2MarkerSubscriberNode::vtkROS2MarkerSubscriberNode()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkROS2MarkerSubscriberNode::~vtkROS2MarkerSubscriberNode() = default;

//------------------------------------------------------------------------------
void vtkROS2MarkerSubscriberNode::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FixedFrame: " << this->Internals->FixedFrame << "\n";
  os << indent << "KeptMarkers: " << this->Internals->Markers.size() << "\n";
}

//------------------------------------------------------------------------------
void vtkROS2MarkerSubscriberNode::SetFixedFrame(const char* frame)
{
  const std::string value = frame ? frame : "";
  if (value == this->Internals->FixedFrame)
  {
    return;
  }
  this->Internals->FixedFrame = value;
  this->Internals->PlaceAll = true; // placed on the next spin, with the tf it brings
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkROS2MarkerSubscriberNode::GetFixedFrame() const
{
  return this->Internals->FixedFrame.c_str();
}

//------------------------------------------------------------------------------
std::string vtkROS2MarkerSubscriberNode::GetEffectiveFixedFrame() const
{
  if (!this->Internals->FixedFrame.empty())
  {
    return this->Internals->FixedFrame;
  }
  vtkROS2Scene* scene = this->GetScene();
  return scene ? scene->GetFixedFrame() : std::string();
}

//------------------------------------------------------------------------------
std::string vtkROS2MarkerSubscriberNode::GetFrameStatus() const
{
  return this->Internals->Markers.status();
}

//------------------------------------------------------------------------------
int vtkROS2MarkerSubscriberNode::GetNumberOfKeptMarkers() const
{
  return static_cast<int>(this->Internals->Markers.size());
}

//------------------------------------------------------------------------------
void vtkROS2MarkerSubscriberNode::OnNewMessages()
{
  vtkInternals& internals = *this->Internals;
  internals.FoldError.clear();
  internals.Markers.set_time(this->SpinTimeNanoseconds); // what later lifetimes count from
  for (int i = 0; i < this->GetNumberOfNewMessages(); ++i)
  {
    const void* raw = this->GetNewRawMessage(i);
    if (!raw)
    {
      continue;
    }
    internals.Read.clear();
    this->ReadMarkers(raw, &internals.Read);
    std::string error;
    if (!internals.Markers.apply(internals.Read, &error) && internals.FoldError.empty())
    {
      internals.FoldError = error;
    }
  }
  this->LocateKeptMarkers(false); // the new markers, in the fixed frame
  // Once per reason (a publisher may send the same undrawable marker at 10 Hz).
  if (!internals.FoldError.empty() && internals.FoldError != internals.WarnedFoldError)
  {
    vtkWarningMacro(<< this->GetROSType() << " on " << this->GetTopic() << ": "
                    << internals.FoldError);
  }
  if (!internals.FoldError.empty())
  {
    internals.WarnedFoldError = internals.FoldError;
  }
  this->OnKeptMarkersChanged();
}

//------------------------------------------------------------------------------
bool vtkROS2MarkerSubscriberNode::ExpireKeptState(vtkTypeInt64 nowNanoseconds)
{
  bool changed = this->Internals->Markers.expire(nowNanoseconds);
  changed = this->LocateKeptMarkers(false) || changed;
  if (changed)
  {
    this->OnKeptMarkersChanged();
  }
  return changed;
}

//------------------------------------------------------------------------------
bool vtkROS2MarkerSubscriberNode::LocateKeptMarkers(bool all)
{
  vtkInternals& internals = *this->Internals;
  if (!this->PlacesMarkersInFrames)
  {
    return false;
  }
  const std::string fixedFrame = this->GetEffectiveFixedFrame();
  // A new fixed frame (this node's or the scene's) places every marker again.
  all = all || internals.PlaceAll || fixedFrame != internals.PlacedIn;
  internals.PlaceAll = false;
  internals.PlacedIn = fixedFrame;
  if (fixedFrame.empty())
  {
    if (all)
    {
      internals.Markers.unlocate(); // back to every marker at its own pose
    }
    return all;
  }
  vtkROS2NodeNode* rosNode = this->GetROS2Node();
  const auto lookup = [rosNode, &fixedFrame](const std::string& frame, int64_t stamp,
                        ros2vtk::convert::FramePose* pose, std::string* error) {
    if (!rosNode)
    {
      *error = "the subscriber is not on a ROS node (no tf buffer)";
      return false;
    }
    return rosNode->LookupFramePose(fixedFrame, frame, stamp, pose->translation, pose->rotation,
      error, &pose->older_than_history);
  };
  return internals.Markers.locate(lookup, fixedFrame, all);
}

//------------------------------------------------------------------------------
bool vtkROS2MarkerSubscriberNode::DrawKeptMarkers(vtkPolyData* polyData, std::string* status) const
{
  const vtkInternals& internals = *this->Internals;
  std::string error;
  if (!internals.Markers.to_poly_data(this->ScaleLengths ? ros2vtk::convert::kMillimetresPerMetre
                                                         : ros2vtk::convert::kNoLengthScaling,
        polyData, &error))
  {
    *status = error;
    return false;
  }
  // What the latest messages could not apply, then the markers not drawn for want of a frame.
  const std::string unplaced = internals.Markers.status();
  *status = internals.FoldError.empty() || unplaced.empty() ? internals.FoldError + unplaced
                                                            : internals.FoldError + "\n" + unplaced;
  return true;
}

//------------------------------------------------------------------------------
void vtkROS2MarkerSubscriberNode::WriteXML(vtkXMLDataElement* element)
{
  this->Superclass::WriteXML(element);
  if (!this->Internals->FixedFrame
         .empty()) // only when set: files of earlier versions stay as they were
  {
    element->SetAttribute("fixedFrame", this->Internals->FixedFrame.c_str());
  }
}

//------------------------------------------------------------------------------
bool vtkROS2MarkerSubscriberNode::ReadXML(vtkXMLDataElement* element)
{
  if (!this->Superclass::ReadXML(element))
  {
    return false;
  }
  const char* frame = element->GetAttribute("fixedFrame");
  this->SetFixedFrame(frame ? frame : "");
  return true;
}
