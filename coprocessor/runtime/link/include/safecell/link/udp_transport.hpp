#pragma once
// UDP on Boost.Asio: the coprocessor's transport to the controller (cyclic traffic over UDP, one
// frame per datagram, as ABB EGM and KUKA RSI do: a TCP retransmission stall would trip the
// watchdog). Binds a local address, talks to one peer; datagrams from anyone else are dropped
// before the safety layer sees them (it would refuse them anyway).

#include <cstdint>
#include <memory>
#include <string>

#include "safecell/link/datagram_transport.hpp"

namespace safecell {

struct UdpEndpoint {
  std::string address = "127.0.0.1";
  unsigned short port = 0;  // 0 when binding: any free port
};

class UdpTransport final : public DatagramTransport {
 public:
  // Throws LinkSetupError naming the address when it cannot bind or resolve.
  UdpTransport(const UdpEndpoint& local, const UdpEndpoint& peer);
  ~UdpTransport() override;

  bool send(std::span<const std::uint8_t> datagram) override;
  std::optional<std::size_t> receive(std::span<std::uint8_t> buffer,
                                     std::chrono::microseconds timeout) override;

  // The port bound (useful with port 0).
  unsigned short local_port() const;
  void set_peer(const UdpEndpoint& peer);
  // Datagrams sent, and received from the peer (a driver in simulated time waits on these).
  std::uint64_t datagrams_sent() const;
  std::uint64_t datagrams_received() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace safecell
