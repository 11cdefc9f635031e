// ros2vtk — OpenIGTLink TCP endpoint (Endpoint.hpp): POSIX non-blocking sockets and poll(2), so
// the owner's spin never waits on a peer. Writes use MSG_NOSIGNAL (a vanished peer is an error
// line, not a SIGPIPE).
#include "ros2vtk/igtl/Endpoint.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>

namespace ros2vtk {
namespace igtl {

namespace {

double now_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool set_non_blocking(int fd)
{
  const int flags = fcntl(fd, F_GETFL, 0);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

void tune_socket(int fd)
{
  int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
  setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &one, sizeof(one));
}

bool resolve(const std::string& host, int port, sockaddr_in& address, std::string& error)
{
  std::memset(&address, 0, sizeof(address));
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (inet_pton(AF_INET, host.c_str(), &address.sin_addr) == 1)
  {
    return true;
  }
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), nullptr, &hints, &found) != 0 || !found)
  {
    error = "cannot resolve host '" + host + "'";
    return false;
  }
  address.sin_addr = reinterpret_cast<sockaddr_in*>(found->ai_addr)->sin_addr;
  freeaddrinfo(found);
  return true;
}

} // namespace

struct Endpoint::Peer
{
  int fd = -1;
  int id = 0;
  std::string who;
  FrameReader reader;
  std::deque<std::pair<std::string, Bytes>> queue;
  std::size_t queued_bytes = 0;
  std::size_t written = 0; ///< bytes of queue.front() already on the socket
  explicit Peer(std::size_t max_body)
    : reader(max_body)
  {
  }
};

Endpoint::Endpoint() = default;

Endpoint::~Endpoint()
{
  this->stop();
}

bool Endpoint::start(const Options& options, std::string& error)
{
  this->stop();
  if (options.port <= 0 || options.port > 65535)
  {
    error = "port " + std::to_string(options.port) + " is not a TCP port";
    return false;
  }
  this->Opts = options;
  if (options.client)
  {
    this->Started = true;
    this->NextConnectTime = 0.0;
    return true;
  }
  sockaddr_in address;
  if (!resolve(options.host, options.port, address, error))
  {
    return false;
  }
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0)
  {
    error = std::string("socket: ") + std::strerror(errno);
    return false;
  }
  int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 || listen(fd, 8) != 0 ||
    !set_non_blocking(fd))
  {
    error = "cannot listen on " + options.host + ":" + std::to_string(options.port) + ": " +
      std::strerror(errno);
    close(fd);
    return false;
  }
  this->ListenFd = fd;
  this->Started = true;
  this->event("listening on " + options.host + ":" + std::to_string(options.port));
  return true;
}

void Endpoint::stop()
{
  while (!this->Peers.empty())
  {
    this->close_peer(this->Peers.size() - 1, "stopped");
  }
  if (this->ListenFd >= 0)
  {
    close(this->ListenFd);
    this->ListenFd = -1;
  }
  if (this->ConnectingFd >= 0)
  {
    close(this->ConnectingFd);
    this->ConnectingFd = -1;
  }
  this->Started = false;
}

bool Endpoint::is_started() const
{
  return this->Started;
}

std::size_t Endpoint::peer_count() const
{
  return this->Peers.size();
}

std::vector<Endpoint::Event> Endpoint::take_events()
{
  std::vector<Event> out;
  out.swap(this->Events);
  return out;
}

void Endpoint::event(const std::string& line, bool problem)
{
  if (this->Events.size() < 1000) // the owner drains them every spin; bounded if it does not
  {
    this->Events.push_back({ line, problem });
  }
}

void Endpoint::add_peer(int fd, const std::string& who)
{
  set_non_blocking(fd);
  tune_socket(fd);
  auto peer = std::make_unique<Peer>(this->Opts.max_body_size);
  peer->fd = fd;
  peer->id = this->NextPeerId++;
  peer->who = who;
  for (const auto& kv : this->Retained)
  {
    this->enqueue(*peer, kv.first, kv.second);
  }
  this->event("peer " + std::to_string(peer->id) + " connected (" + who + ")");
  this->Peers.push_back(std::move(peer));
}

void Endpoint::close_peer(std::size_t index, const std::string& reason)
{
  Peer& peer = *this->Peers[index];
  close(peer.fd);
  // A peer leaving between messages (FIN, or a reset as a closing Slicer may send) is traffic.
  const bool plain = reason == "disconnected" || reason == "stopped" ||
    (reason.rfind("connection lost", 0) == 0 && reason.find("middle") == std::string::npos);
  this->event("peer " + std::to_string(peer.id) + " (" + peer.who + ") closed: " + reason, !plain);
  this->Peers.erase(this->Peers.begin() + static_cast<long>(index));
  if (this->Opts.client)
  {
    this->NextConnectTime = now_seconds() + this->Opts.reconnect_interval;
  }
}

void Endpoint::accept_peers()
{
  for (int i = 0; i < 16; ++i) // bounded: the rest waits for the next poll
  {
    sockaddr_in from{};
    socklen_t size = sizeof(from);
    const int fd = accept(this->ListenFd, reinterpret_cast<sockaddr*>(&from), &size);
    if (fd < 0)
    {
      return;
    }
    char text[INET_ADDRSTRLEN] = "?";
    inet_ntop(AF_INET, &from.sin_addr, text, sizeof(text));
    this->add_peer(fd, std::string(text) + ":" + std::to_string(ntohs(from.sin_port)));
  }
}

void Endpoint::try_connect()
{
  const std::string where = this->Opts.host + ":" + std::to_string(this->Opts.port);
  if (this->ConnectingFd >= 0)
  {
    pollfd p{ this->ConnectingFd, POLLOUT, 0 };
    if (::poll(&p, 1, 0) <= 0)
    {
      return; // still connecting
    }
    int soerr = 0;
    socklen_t len = sizeof(soerr);
    getsockopt(this->ConnectingFd, SOL_SOCKET, SO_ERROR, &soerr, &len);
    const int fd = this->ConnectingFd;
    this->ConnectingFd = -1;
    if (soerr != 0)
    {
      close(fd);
      this->NextConnectTime = now_seconds() + this->Opts.reconnect_interval;
      return;
    }
    this->add_peer(fd, where);
    return;
  }
  if (now_seconds() < this->NextConnectTime)
  {
    return;
  }
  std::string error;
  sockaddr_in address;
  if (!resolve(this->Opts.host, this->Opts.port, address, error))
  {
    this->event(error, true);
    this->NextConnectTime = now_seconds() + this->Opts.reconnect_interval;
    return;
  }
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0 || !set_non_blocking(fd))
  {
    if (fd >= 0)
    {
      close(fd);
    }
    return;
  }
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0)
  {
    this->add_peer(fd, where);
  }
  else if (errno == EINPROGRESS)
  {
    this->ConnectingFd = fd;
  }
  else
  {
    close(fd);
    this->NextConnectTime = now_seconds() + this->Opts.reconnect_interval;
  }
}

void Endpoint::poll(std::vector<Received>& received)
{
  if (!this->Started)
  {
    return;
  }
  if (this->Opts.client)
  {
    if (this->Peers.empty())
    {
      this->try_connect();
    }
  }
  else
  {
    this->accept_peers();
  }
  for (std::size_t i = 0; i < this->Peers.size();)
  {
    std::string error;
    if (!this->read(*this->Peers[i], received, error) || !this->flush(*this->Peers[i], error))
    {
      this->close_peer(i, error);
      continue;
    }
    ++i;
  }
}

bool Endpoint::read(Peer& peer, std::vector<Received>& received, std::string& error)
{
  std::uint8_t buffer[65536];
  for (int round = 0; round < 64;
       ++round) // bounded per poll: one flooding peer cannot starve the rest
  {
    const ssize_t n = recv(peer.fd, buffer, sizeof(buffer), MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR))
    {
      break;
    }
    if (n <= 0)
    {
      error =
        n == 0 ? "disconnected" : std::string("connection lost (") + std::strerror(errno) + ")";
      if (peer.reader.buffered() > 0)
      {
        error += " in the middle of a message (" + std::to_string(peer.reader.buffered()) +
          " bytes of it read)";
      }
      return false;
    }
    peer.reader.feed(buffer, static_cast<std::size_t>(n));
    if (static_cast<std::size_t>(n) < sizeof(buffer))
    {
      break;
    }
  }
  for (;;)
  {
    Received item;
    item.peer = peer.id;
    std::string why;
    const FrameReader::Result result = peer.reader.next(item.frame, why);
    if (result == FrameReader::Result::NeedMore)
    {
      return true;
    }
    if (result == FrameReader::Result::Frame)
    {
      received.push_back(std::move(item));
      continue;
    }
    ++this->Bad;
    if (result == FrameReader::Result::Fatal)
    {
      error = why;
      return false;
    }
    this->event("peer " + std::to_string(peer.id) + ": " + why, true);
  }
}

void Endpoint::enqueue(Peer& peer, const std::string& key, const Bytes& bytes)
{
  // Latest-only: replace a queued message with the same key, unless it is being written.
  for (std::size_t i = peer.written > 0 ? 1 : 0; i < peer.queue.size(); ++i)
  {
    if (peer.queue[i].first == key)
    {
      peer.queued_bytes -= peer.queue[i].second->size();
      peer.queue[i].second = bytes;
      peer.queued_bytes += bytes->size();
      return;
    }
  }
  peer.queue.emplace_back(key, bytes);
  peer.queued_bytes += bytes->size();
  const std::size_t keep = peer.written > 0 ? 1 : 0;
  while (peer.queue.size() > keep + 1 &&
    (peer.queue.size() > this->Opts.max_queued_messages ||
      peer.queued_bytes > this->Opts.max_queued_bytes))
  {
    auto victim = peer.queue.begin() + static_cast<long>(keep);
    peer.queued_bytes -= victim->second->size();
    peer.queue.erase(victim);
    ++this->Dropped;
  }
}

bool Endpoint::flush(Peer& peer, std::string& error)
{
  while (!peer.queue.empty())
  {
    const std::vector<std::uint8_t>& bytes = *peer.queue.front().second;
    const ssize_t n = ::send(peer.fd, bytes.data() + peer.written, bytes.size() - peer.written,
      MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0)
    {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)
      {
        return true; // the peer is slow: the queue keeps the newest per key
      }
      error = std::string("send failed: ") + std::strerror(errno);
      return false;
    }
    peer.written += static_cast<std::size_t>(n);
    if (peer.written == bytes.size())
    {
      peer.queued_bytes -= bytes.size();
      peer.queue.pop_front();
      peer.written = 0;
      ++this->Sent;
    }
  }
  return true;
}

void Endpoint::send(const std::string& key, std::vector<std::uint8_t> bytes, bool retain)
{
  auto shared = std::make_shared<const std::vector<std::uint8_t>>(std::move(bytes));
  if (retain)
  {
    this->Retained[key] = shared;
  }
  for (auto& peer : this->Peers)
  {
    this->enqueue(*peer, key, shared);
  }
}

void Endpoint::flush()
{
  for (std::size_t i = 0; i < this->Peers.size();)
  {
    std::string error;
    if (!this->flush(*this->Peers[i], error))
    {
      this->close_peer(i, error);
      continue;
    }
    ++i;
  }
}

void Endpoint::forget(const std::string& key)
{
  this->Retained.erase(key);
}

} // namespace igtl
} // namespace ros2vtk
