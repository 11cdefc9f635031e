// ros2vtk — serves the scene to an unmodified 3D Slicer (OpenIGTLinkIF) over OpenIGTLink, and
// brings Slicer's transforms, points, images and text back into the scene and onto ROS.
//
//   connector = vtkROS2IGTLConnectorNode::New(); scene->AddNode(connector);
//   connector->SetPort(18944);            // server on 127.0.0.1 by default (Slicer's default)
//   connector->Start(rosNode);            // from then on every spin of rosNode serves it
//   connector->MapDeviceToTf("Target", "world", "target");
//
// Out (scene → Slicer): transform nodes (tf lookups, robot links) as TRANSFORM every spin, model
// nodes (robot visuals) as POLYDATA when they change (baked in world coordinates by default, or
// link-local with metadata "ros.parent" naming the link for a Slicer-side snippet to parent),
// subscribers' images as IMAGE with their pose, point clouds as POLYDATA points, strings as
// STRING, pose arrays as TDATA (elements <device>_<i>, posed by the tf lookup of their frame) and
// as a POINT list (Slicer: a markups point list). WriteSlicerScene writes a .mrml that puts the
// link-local models under their link transforms in a stock Slicer. Device name = node name
// (≤ 20 bytes). Units: the scene's millimetres. Coordinates:
// the matrix WorldToSlicer (identity by default: ROS x, y, z become Slicer R, A, S) is applied to
// everything sent and inverted for everything received; it is never implicit.
// In (Slicer → scene): TRANSFORM/POSITION become transform nodes, TDATA one transform node per
// element (as Slicer does; each element mappable by its name) and a PoseArray when mapped, POINT a
// model node of points,
// IMAGE and STRING are kept by device; mapped devices are also published (tf or a topic).
#ifndef vtkROS2IGTLConnectorNode_h
#define vtkROS2IGTLConnectorNode_h

#include "ros2vtkIGTLConnectorModule.h" // for export macro
#include "vtkROS2SceneNode.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkImageData;
class vtkMatrix4x4;
class vtkROS2NodeNode;
class vtkXMLDataElement;

class ROS2VTKIGTLCONNECTOR_EXPORT vtkROS2IGTLConnectorNode : public vtkROS2SceneNode
{
public:
  static vtkROS2IGTLConnectorNode* New();
  vtkTypeMacro(vtkROS2IGTLConnectorNode, vtkROS2SceneNode);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Fired when a message from Slicer changed the scene (call data: const char* device name).
  enum
  {
    ReceivedEvent = 16000
  };

  /// Server (default: Slicer connects to us) or client (we connect to a Slicer server).
  void SetTypeToServer() { this->SetClient(false); }
  void SetTypeToClient() { this->SetClient(true); }
  vtkSetMacro(Client, bool);
  vtkGetMacro(Client, bool);
  /// Server: address to bind (127.0.0.1 by default; anything else is a warning, since it exposes
  /// the scene to the network). Client: address of the Slicer to reach.
  void SetHostname(const char* host);
  const char* GetHostname() const;
  vtkSetClampMacro(Port, int, 1, 65535);
  vtkGetMacro(Port, int);

  /// Starts serving; every Spin of `rosNode` then runs Update. False (GetLastError) on failure.
  bool Start(vtkROS2NodeNode* rosNode);
  void Stop();
  /// One round: read peers, handle what came in, send the scene. Called from the ROS node's
  /// spin after Start; call it yourself to drive the connector without one.
  int Update();

  /// "off", "listening", "connecting", "connected" or "error".
  const char* GetState() const;
  const char* GetLastError() const;
  int GetNumberOfClients() const;
  vtkTypeInt64 GetNumberOfMessagesSent() const;
  vtkTypeInt64 GetNumberOfMessagesReceived() const { return this->MessagesReceived; }
  /// Messages dropped as malformed: header, size limit, CRC, v2 sections, or a body unfit for its
  /// type.
  vtkTypeInt64 GetNumberOfBadMessages() const;
  vtkTypeInt64 GetNumberOfDroppedMessages() const;
  /// Recent events (connections, disconnections, bad input and why), newest last.
  std::string GetEventLog() const;

  /// Which nodes are sent: all transform, model and subscriber nodes (default), or only those
  /// added by ID.
  vtkSetMacro(MirrorAllNodes, bool);
  vtkGetMacro(MirrorAllNodes, bool);
  vtkBooleanMacro(MirrorAllNodes, bool);
  void AddMirroredNodeID(const char* nodeID);
  void RemoveMirroredNodeID(const char* nodeID);
  bool IsMirrored(vtkROS2SceneNode* node) const;

  /// Scene world (ROS, REP 103, mm) → Slicer RAS (mm). Identity by default.
  void SetWorldToSlicer(vtkMatrix4x4* matrix);
  vtkMatrix4x4* GetWorldToSlicer();

  /// On (default): models sent in world coordinates, again whenever they or their link move.
  /// Off: sent once in link-local coordinates with metadata ros.parent = the link's device name.
  vtkSetMacro(ModelsInWorld, bool);
  vtkGetMacro(ModelsInWorld, bool);
  vtkBooleanMacro(ModelsInWorld, bool);

  /// Writes a 3D Slicer scene file (.mrml) for a stock Slicer with SlicerOpenIGTLink, opened by
  /// drag and drop (or File → Add Data): an OpenIGTLinkIF connector to this one, persistent and
  /// active, so it connects as soon as the file is loaded; and for every mirrored model node under
  /// a transform node, a linear transform named as that transform's device with a model named as
  /// the model's device under it (with its colour). OpenIGTLinkIF fills an existing node of the
  /// device's name and class instead of creating one, and keeps its parent, so the link TRANSFORMs
  /// and (with ModelsInWorld off) the link-local POLYDATA land in this hierarchy: the robot's
  /// models under their link transforms, each mesh sent once per connection (with ModelsInWorld
  /// on, the models are written at the scene root, as their meshes are then baked). Returns the
  /// number of models written, or -1 (GetLastError) when the file cannot be written.
  int WriteSlicerScene(const char* path);

  /// Slicer → ROS. Device names are Slicer node names. `type` for a topic: a publisher short
  /// name whose VTK value matches the message (PoseStamped / TransformStamped for TRANSFORM,
  /// PointCloud for POINT, PoseArray for TDATA, Image for IMAGE, String for STRING).
  bool MapDeviceToTf(const char* device, const char* parentFrame, const char* childFrame);
  bool MapDeviceToTopic(const char* device, const char* topic, const char* type);
  /// The mapping of `device` as the CLI spells it ("tf:PARENT:CHILD", "topic:TOPIC:TYPE"), or "".
  std::string GetDeviceMap(const char* device) const;

  /// The device name a node is sent under: its name when it fits OpenIGTLink's 20 bytes, else
  /// without the robot prefix ("arm:needle_guide_link" -> "needle_guide_link"), else 16 bytes +
  /// '~' + 3 hex digits of a hash of the whole name.
  static std::string MakeDeviceName(const std::string& nodeName);

  /// Scene files keep the settings (type, host, port, mirrored nodes, device mappings,
  /// WorldToSlicer, ModelsInWorld) and whether it was started, with which ROS node: a restored
  /// connector that was serving serves again (OnSceneRestored). What came in is not saved.
  void WriteXML(vtkXMLDataElement* element) override;
  bool ReadXML(vtkXMLDataElement* element) override;
  void OnSceneRestored() override;
  /// Node reference roles: the mirrored nodes, and the ROS node it was started with.
  static const char* const MirroredNodeReferenceRole;
  static const char* const StartedROS2NodeReferenceRole;
  /// The ROS node of the last Start (kept through a save and restore), or nullptr.
  vtkROS2NodeNode* GetStartedROS2Node() const;

  /// What came in by device (nullptr / "" before the first).
  vtkImageData* GetReceivedImage(const char* device);
  std::string GetReceivedString(const char* device);
  /// TRANSFORM, POSITION or POINT device that came in, as the scene node it became.
  vtkROS2SceneNode* GetReceivedNode(const char* device);

protected:
  vtkROS2IGTLConnectorNode();
  ~vtkROS2IGTLConnectorNode() override;
  void OnRemovedFromScene() override;

  bool Client = false;
  int Port = 18944;
  bool MirrorAllNodes = true;
  bool ModelsInWorld = true;
  bool StartRequested = false; // from a scene file: Start again in OnSceneRestored
  vtkTypeInt64 MessagesReceived = 0;

private:
  vtkROS2IGTLConnectorNode(const vtkROS2IGTLConnectorNode&) = delete;
  void operator=(const vtkROS2IGTLConnectorNode&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
