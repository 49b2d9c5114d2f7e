#pragma once
// The Linux controller module's LinkPort: a non-blocking POSIX UDP socket bound to a local
// address, talking to one peer (the coprocessor, or a proxy in between). Datagrams from any other
// address are dropped before the safety layer sees them.
// Thread context: the controller's cycle task. Hosted code (controller/host/ is not freestanding).

#include <cstddef>
#include <cstdint>
#include <string>

#include "safecell/controller/link_port.hpp"

namespace safecell {

struct UdpAddress {
  std::string ip = "127.0.0.1";  // IPv4
  std::uint16_t port = 0;        // 0 when binding: any free port
};

class UdpLinkPort final : public LinkPort {
 public:
  // Throws std::runtime_error naming the address when the socket cannot be made or bound.
  UdpLinkPort(const UdpAddress& local, const UdpAddress& peer);
  ~UdpLinkPort();
  UdpLinkPort(const UdpLinkPort&) = delete;
  UdpLinkPort& operator=(const UdpLinkPort&) = delete;

  bool send(const std::uint8_t* data, std::size_t size) noexcept override;
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override;

  std::uint16_t local_port() const;
  // Talks to another peer from now on (throws like the constructor for a bad address).
  void set_peer(const UdpAddress& peer);
  // Waits up to timeout_us for a datagram to arrive (for host loops that would otherwise spin).
  bool wait_readable(int timeout_us) const noexcept;

  std::uint64_t dropped_foreign() const noexcept { return dropped_foreign_; }
  // Datagrams sent, and received from the peer (a driver in simulated time waits on these).
  std::uint64_t datagrams_sent() const noexcept { return sent_; }
  std::uint64_t datagrams_received() const noexcept { return received_; }
  int socket_fd() const noexcept { return socket_; }

 private:
  int socket_ = -1;
  std::uint32_t peer_ip_ = 0;    // network byte order
  std::uint16_t peer_port_ = 0;  // network byte order
  std::uint64_t dropped_foreign_ = 0;
  std::uint64_t sent_ = 0;
  std::uint64_t received_ = 0;
};

}  // namespace safecell
