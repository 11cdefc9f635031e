// ros2vtk — the ROS graph of one participant: what we announce on `ros_discovery_info` and
// what we learn from DDS discovery and from other participants' announcements.
//
// This is protocol, not a message mapping: rmw itself speaks rmw_dds_common's
// ParticipantEntitiesInfo on this topic, so the wire layer uses that generated type directly.
#ifndef ros2vtk_wire_GraphCache_hpp
#define ros2vtk_wire_GraphCache_hpp

#include "ros2vtk/wire/Participant.hpp"

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/rtps/common/Guid.h>

#include <array>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ros2vtk {
namespace rmw_dds_common {
namespace msg {
struct ParticipantEntitiesInfo;
} // namespace msg
} // namespace rmw_dds_common

namespace wire {

struct MessageTypeSupport;

using Gid = std::array<uint8_t, 16>;
Gid to_gid(const eprosima::fastrtps::rtps::GUID_t& guid);

class GraphCache : public eprosima::fastdds::dds::DataReaderListener
{
public:
  GraphCache() = default;
  ~GraphCache() override = default;

  /// Creates the ros_discovery_info writer (keep last 1, reliable, transient local) and reader
  /// (keep all, reliable, transient local) as rmw does (WIRE_NOTES §3.2).
  bool init(eprosima::fastdds::dds::DomainParticipant* participant,
    eprosima::fastdds::dds::Publisher* publisher, eprosima::fastdds::dds::Subscriber* subscriber,
    eprosima::fastdds::dds::Topic* topic, const std::string& node_namespace,
    const std::string& node_name, std::string* error);
  /// Deletes the graph endpoints (before the participant's entities are deleted).
  void shutdown();

  void add_local_endpoint(
    const Gid& gid, bool is_writer, const std::string& dds_topic, const std::string& dds_type);
  void remove_local_endpoint(const Gid& gid);

  /// `type_hash`: the RIHS01 hash of the endpoint's USER_DATA (`typehash=...;`), "" when none.
  void add_remote_endpoint(const Gid& gid, bool is_writer, const std::string& dds_topic,
    const std::string& dds_type, const std::string& type_hash = std::string());
  void remove_remote_endpoint(const Gid& gid);
  void remove_remote_participant(const Gid& participant_gid);

  std::vector<std::pair<std::string, std::string>> node_names_and_namespaces() const;
  std::vector<TopicInfo> topic_names_and_types() const;
  size_t count_endpoints(const std::string& dds_topic, bool writers) const;
  /// The remote writers (`writers`) or readers of a DDS topic with their node (from
  /// ros_discovery_info; empty names while that node's announcement has not arrived) and type
  /// hash.
  std::vector<EndpointInfo> remote_endpoints(const std::string& dds_topic, bool writers) const;
  std::vector<PublisherInfo> remote_publishers(const std::string& dds_topic) const
  {
    return remote_endpoints(dds_topic, true);
  }
  /// The nodes ("/ns/name") whose writers publish `dds_topic` (as `ros2 topic info -v` names
  /// them: a writer is matched to the node whose ros_discovery_info announcement lists its gid;
  /// "?" for writers no announcement lists, e.g. before it arrives or from non-ROS DDS), sorted,
  /// one entry per node.
  std::vector<std::string> publisher_nodes(const std::string& dds_topic) const;
  /// The node whose announcement lists writer `gid` ("/ns/name"; ours for our writers), or "".
  std::string node_of_writer(const Gid& gid) const;

  /// Records another participant's announcement: its nodes and the writers each lists,
  /// replacing that participant's previous one (ours is ignored). on_data_available calls it for
  /// every ros_discovery_info sample.
  void record_announcement(const rmw_dds_common::msg::ParticipantEntitiesInfo& info);

  // DataReaderListener: ParticipantEntitiesInfo samples from other participants.
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override;

private:
  struct Endpoint
  {
    bool is_writer = false;
    std::string dds_topic;
    std::string dds_type;
    std::string type_hash;
  };
  struct NodeInfo
  {
    std::string node_namespace;
    std::string node_name;
    std::vector<Gid> writers; ///< the writer gids its announcement lists
    std::vector<Gid> readers; ///< the reader gids its announcement lists
  };

  /// Announces the local endpoints on ros_discovery_info. Lock order: publish_mutex_, then
  /// DDS; mutex_ is never held while calling into DDS, because DDS threads call
  /// on_data_available (which takes mutex_) with their reader's lock held.
  void publish();

  const MessageTypeSupport* info_type_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
  eprosima::fastdds::dds::DataWriter* writer_ = nullptr;
  eprosima::fastdds::dds::DataReader* reader_ = nullptr;
  Gid own_gid_{};
  std::string node_namespace_;
  std::string node_name_;

  std::mutex
    publish_mutex_; ///< serializes publish() and guards writer_; never taken by DDS threads
  mutable std::mutex mutex_; ///< the maps below; never held while calling into DDS
  std::map<Gid, Endpoint> local_endpoints_;
  std::map<Gid, Endpoint> remote_endpoints_;
  std::map<Gid, std::vector<NodeInfo>> remote_nodes_; ///< by participant gid

  /// The remote node whose announcement lists writer (`writer`) or reader `gid`, or nullptr. The
  /// one search both remote_endpoints and node_of_writer make. Caller holds mutex_.
  const NodeInfo* remote_node_of_endpoint_locked(const Gid& gid, bool writer) const;
  /// "/ns/name" of the node owning writer `gid` (ours or a remote one), or "". Caller holds mutex_.
  std::string node_of_writer_locked(const Gid& gid) const;
};

} // namespace wire
} // namespace ros2vtk

#endif
