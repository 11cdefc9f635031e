// ros2vtk — the OpenIGTLink socket side: a TCP server accepting several clients, or a client that
// reconnects, driven by poll() from the owner's spin (never a thread, never blocking).
//
// Outgoing messages go into one queue per peer. A message with a key already queued replaces it
// in place (latest-only: a slow Slicer gets the newest transform, not a backlog), and a full queue
// drops its oldest entry instead of blocking the spin. Retained messages (meshes, other static
// content) are queued again for every peer that connects later. Bad input from one peer closes
// or skips only that peer's stream; every event is kept as a line for the owner to show.
#ifndef ros2vtk_igtl_Endpoint_hpp
#define ros2vtk_igtl_Endpoint_hpp

#include "ros2vtk/igtl/Frame.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ros2vtk {
namespace igtl {

class Endpoint
{
public:
  struct Options
  {
    bool client = false;            ///< false: listen on host:port; true: connect to it
    std::string host = "127.0.0.1"; ///< server: address to bind; client: address to reach
    int port = 18944;               ///< Slicer's default
    std::size_t max_body_size = 64u * 1024u * 1024u;
    std::size_t max_queued_messages = 256; ///< per peer, oldest dropped beyond
    std::size_t max_queued_bytes = 256u * 1024u * 1024u;
    double reconnect_interval = 0.5; ///< client mode, seconds
  };

  /// A log line; `problem` when it reports bad input or a failure rather than normal traffic.
  struct Event
  {
    std::string text;
    bool problem = false;
  };

  struct Received
  {
    int peer = 0; ///< which connection sent it
    Frame frame;
  };

  Endpoint();
  ~Endpoint();
  Endpoint(const Endpoint&) = delete;
  Endpoint& operator=(const Endpoint&) = delete;

  /// Server: binds and listens. Client: connects on the next poll. False with `error`.
  bool start(const Options& options, std::string& error);
  void stop();
  bool is_started() const;
  bool is_client() const { return this->Opts.client; }

  /// Accepts, reads and writes without blocking; appends the frames read to `received`.
  void poll(std::vector<Received>& received);

  /// Queues `bytes` (an encoded frame) for every connected peer under `key` (latest-only).
  /// `retain`: also queued for peers that connect later (until forgotten or replaced).
  void send(const std::string& key, std::vector<std::uint8_t> bytes, bool retain = false);
  void forget(const std::string& key);
  /// Writes what the peers' sockets take now (poll does too); never blocks.
  void flush();

  std::size_t peer_count() const;
  /// Log lines since the last call (connections, disconnections, bad input with the reason).
  std::vector<Event> take_events();
  std::uint64_t messages_sent() const { return this->Sent; }
  std::uint64_t messages_dropped() const { return this->Dropped; }
  std::uint64_t bad_messages() const { return this->Bad; }

private:
  struct Peer;
  using Bytes = std::shared_ptr<const std::vector<std::uint8_t>>;
  void accept_peers();
  void try_connect();
  void add_peer(int fd, const std::string& who);
  void close_peer(std::size_t index, const std::string& reason);
  void enqueue(Peer& peer, const std::string& key, const Bytes& bytes);
  bool flush(Peer& peer, std::string& error);
  bool read(Peer& peer, std::vector<Received>& received, std::string& error);
  void event(const std::string& line, bool problem = false);

  Options Opts;
  int ListenFd = -1;
  int ConnectingFd = -1;
  double NextConnectTime = 0.0;
  int NextPeerId = 1;
  bool Started = false;
  std::vector<std::unique_ptr<Peer>> Peers;
  std::map<std::string, Bytes> Retained;
  std::vector<Event> Events;
  std::uint64_t Sent = 0;
  std::uint64_t Dropped = 0;
  std::uint64_t Bad = 0;
};

} // namespace igtl
} // namespace ros2vtk

#endif
