// ros2vtk — the ROS graph (ros_discovery_info + DDS discovery).
#include "GraphCache.hpp"

#include "ParticipantImpl.hpp"
#include "ShippedTypes.hpp"
#include "TypeAdapter.hpp"
#include "ros2vtk/rmw_dds_common/msg/participant_entities_info.hpp"
#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/Names.hpp"

#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include <algorithm>
#include <cstring>

namespace ros2vtk {
namespace wire {

namespace dds = eprosima::fastdds::dds;
using ParticipantEntitiesInfo = ros2vtk::rmw_dds_common::msg::ParticipantEntitiesInfo;
using NodeEntitiesInfo = ros2vtk::rmw_dds_common::msg::NodeEntitiesInfo;

Gid to_gid(const eprosima::fastrtps::rtps::GUID_t& guid)
{
  Gid gid{};
  std::memcpy(gid.data(), guid.guidPrefix.value, 12);
  std::memcpy(gid.data() + 12, guid.entityId.value, 4);
  return gid;
}

bool GraphCache::init(dds::DomainParticipant* participant, dds::Publisher* publisher,
  dds::Subscriber* subscriber, dds::Topic* topic, const std::string& node_namespace,
  const std::string& node_name, std::string* error)
{
  info_type_ = &shipped_message_type("rmw_dds_common/msg/ParticipantEntitiesInfo");
  publisher_ = publisher;
  subscriber_ = subscriber;
  own_gid_ = to_gid(participant->guid());
  node_namespace_ = node_namespace;
  node_name_ = node_name;

  dds::DataWriterQos writer_qos = make_writer_qos(QoS::transient_local(1), "");
  writer_ = publisher->create_datawriter(topic, writer_qos);
  QoS reader_profile = QoS::transient_local(1);
  reader_profile.history = QoS::History::KeepAll;
  dds::DataReaderQos reader_qos = make_reader_qos(reader_profile, "");
  reader_qos.reliable_reader_qos().times.initialAcknackDelay =
    eprosima::fastrtps::Duration_t(0, 5000000);
  reader_ = subscriber->create_datareader(topic, reader_qos, this);
  if (!writer_ || !reader_)
  {
    if (error)
    {
      *error = "could not create the ros_discovery_info endpoints";
    }
    return false;
  }
  publish();
  return true;
}

void GraphCache::shutdown()
{
  if (reader_)
  {
    reader_->set_listener(nullptr);
    subscriber_->delete_datareader(reader_);
    reader_ = nullptr;
  }
  std::lock_guard<std::mutex> publish_lock(publish_mutex_);
  if (writer_)
  {
    publisher_->delete_datawriter(writer_);
    writer_ = nullptr;
  }
}

void GraphCache::add_local_endpoint(
  const Gid& gid, bool is_writer, const std::string& dds_topic, const std::string& dds_type)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    local_endpoints_[gid] = Endpoint{ is_writer, dds_topic, dds_type, std::string() };
  }
  publish();
}

void GraphCache::remove_local_endpoint(const Gid& gid)
{
  bool removed = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    removed = local_endpoints_.erase(gid) > 0;
  }
  if (removed)
  {
    publish();
  }
}

void GraphCache::add_remote_endpoint(const Gid& gid, bool is_writer, const std::string& dds_topic,
  const std::string& dds_type, const std::string& type_hash)
{
  std::lock_guard<std::mutex> lock(mutex_);
  remote_endpoints_[gid] = Endpoint{ is_writer, dds_topic, dds_type, type_hash };
}

void GraphCache::remove_remote_endpoint(const Gid& gid)
{
  std::lock_guard<std::mutex> lock(mutex_);
  remote_endpoints_.erase(gid);
}

void GraphCache::remove_remote_participant(const Gid& participant_gid)
{
  std::lock_guard<std::mutex> lock(mutex_);
  remote_nodes_.erase(participant_gid);
  // Endpoints of that participant share its 12-byte GUID prefix.
  for (auto it = remote_endpoints_.begin(); it != remote_endpoints_.end();)
  {
    if (std::equal(participant_gid.begin(), participant_gid.begin() + 12, it->first.begin()))
    {
      it = remote_endpoints_.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

void GraphCache::publish()
{
  // write() runs while mutex_ is free: with intraprocess delivery it takes the DDS locks of
  // every reader in this process, ours included, and a DDS thread holding such a lock may be
  // inside on_data_available waiting for mutex_. publish_mutex_ only keeps announcements in
  // order (the last one written is the newest state); no DDS thread ever takes it.
  std::lock_guard<std::mutex> publish_lock(publish_mutex_);
  if (!writer_)
  {
    return;
  }
  ParticipantEntitiesInfo info;
  std::copy(own_gid_.begin(), own_gid_.end(), info.gid.data.begin());
  NodeEntitiesInfo node;
  node.node_namespace = node_namespace_;
  node.node_name = node_name_;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& entry : local_endpoints_)
    {
      ros2vtk::rmw_dds_common::msg::Gid gid;
      std::copy(entry.first.begin(), entry.first.end(), gid.data.begin());
      (entry.second.is_writer ? node.writer_gid_seq : node.reader_gid_seq).push_back(gid);
    }
  }
  info.node_entities_info_seq.push_back(node);
  writer_->write(&info);
}

void GraphCache::record_announcement(const ParticipantEntitiesInfo& info)
{
  Gid participant_gid{};
  std::copy(info.gid.data.begin(), info.gid.data.end(), participant_gid.begin());
  if (participant_gid == own_gid_)
  {
    return;
  }
  const auto gids_of = [](const auto& sequence) {
    std::vector<Gid> gids(sequence.size());
    for (size_t i = 0; i < sequence.size(); ++i)
    {
      std::copy(sequence[i].data.begin(), sequence[i].data.end(), gids[i].begin());
    }
    return gids;
  };
  std::vector<NodeInfo> nodes;
  for (const auto& node : info.node_entities_info_seq)
  {
    nodes.push_back(NodeInfo{ node.node_namespace, node.node_name, gids_of(node.writer_gid_seq),
      gids_of(node.reader_gid_seq) });
  }
  std::lock_guard<std::mutex> lock(mutex_);
  remote_nodes_[participant_gid] = std::move(nodes);
}

void GraphCache::on_data_available(dds::DataReader* reader)
{
  ReceivedSample sample;
  dds::SampleInfo sample_info;
  while (reader->take_next_sample(&sample, &sample_info) == ReturnCode_t::RETCODE_OK)
  {
    if (sample_info.valid_data && sample.valid)
    {
      record_announcement(*static_cast<const ParticipantEntitiesInfo*>(sample.message));
    }
  }
  if (sample.message)
  {
    info_type_->destroy(sample.message);
  }
}

std::vector<std::pair<std::string, std::string>> GraphCache::node_names_and_namespaces() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::pair<std::string, std::string>> result;
  result.emplace_back(node_name_, node_namespace_);
  for (const auto& participant : remote_nodes_)
  {
    for (const auto& node : participant.second)
    {
      result.emplace_back(node.node_name, node.node_namespace);
    }
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<TopicInfo> GraphCache::topic_names_and_types() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, std::set<std::string>> topics;
  for (const auto* endpoints : { &local_endpoints_, &remote_endpoints_ })
  {
    for (const auto& entry : *endpoints)
    {
      std::string ros_topic;
      if (dds_to_topic(entry.second.dds_topic, ros_topic))
      {
        topics[ros_topic].insert(dds_type_to_ros(entry.second.dds_type));
      }
    }
  }
  std::vector<TopicInfo> result;
  for (const auto& topic : topics)
  {
    result.push_back(
      TopicInfo{ topic.first, std::vector<std::string>(topic.second.begin(), topic.second.end()) });
  }
  return result;
}

size_t GraphCache::count_endpoints(const std::string& dds_topic, bool writers) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  size_t count = 0;
  for (const auto* endpoints : { &local_endpoints_, &remote_endpoints_ })
  {
    for (const auto& entry : *endpoints)
    {
      if (entry.second.is_writer == writers && entry.second.dds_topic == dds_topic)
      {
        ++count;
      }
    }
  }
  return count;
}

std::vector<EndpointInfo> GraphCache::remote_endpoints(
  const std::string& dds_topic, bool writers) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<EndpointInfo> result;
  for (const auto& entry : remote_endpoints_)
  {
    if (entry.second.is_writer != writers || entry.second.dds_topic != dds_topic)
    {
      continue;
    }
    EndpointInfo info;
    info.ros_type = dds_type_to_ros(entry.second.dds_type);
    info.type_hash = entry.second.type_hash;
    if (const NodeInfo* node = remote_node_of_endpoint_locked(entry.first, writers))
    {
      info.node_name = node->node_name;
      info.node_namespace = node->node_namespace;
    }
    result.push_back(std::move(info));
  }
  return result;
}

namespace {
std::string full_node_name(const std::string& ns, const std::string& name)
{
  return ns == "/" || ns.empty() ? "/" + name : ns + "/" + name;
}
} // namespace

const GraphCache::NodeInfo* GraphCache::remote_node_of_endpoint_locked(
  const Gid& gid, bool writer) const
{
  for (const auto& participant : remote_nodes_)
  {
    for (const auto& node : participant.second)
    {
      const std::vector<Gid>& gids = writer ? node.writers : node.readers;
      if (std::find(gids.begin(), gids.end(), gid) != gids.end())
        return &node;
    }
  }
  return nullptr;
}

std::string GraphCache::node_of_writer_locked(const Gid& gid) const
{
  const auto local = local_endpoints_.find(gid);
  if (local != local_endpoints_.end() && local->second.is_writer)
    return full_node_name(node_namespace_, node_name_);
  const NodeInfo* node = remote_node_of_endpoint_locked(gid, true);
  return node ? full_node_name(node->node_namespace, node->node_name) : std::string();
}

std::string GraphCache::node_of_writer(const Gid& gid) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return node_of_writer_locked(gid);
}

std::vector<std::string> GraphCache::publisher_nodes(const std::string& dds_topic) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::set<std::string> names;
  for (const auto* endpoints : { &local_endpoints_, &remote_endpoints_ })
  {
    for (const auto& entry : *endpoints)
    {
      if (entry.second.is_writer && entry.second.dds_topic == dds_topic)
      {
        const std::string owner = node_of_writer_locked(entry.first);
        names.insert(owner.empty() ? "?" : owner);
      }
    }
  }
  return std::vector<std::string>(names.begin(), names.end());
}

} // namespace wire
} // namespace ros2vtk
