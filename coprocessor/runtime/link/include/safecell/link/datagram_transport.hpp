#pragma once
// How the coprocessor's link sends and receives datagrams (one safety-layer frame each). The
// safety layer does not depend on it; UdpTransport is the product's, tests may use others.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace safecell {

class DatagramTransport {
 public:
  DatagramTransport() = default;
  DatagramTransport(const DatagramTransport&) = delete;
  DatagramTransport& operator=(const DatagramTransport&) = delete;
  virtual ~DatagramTransport() = default;

  // Sends one datagram to the peer; false when the network refused it (counted by the caller).
  virtual bool send(std::span<const std::uint8_t> datagram) = 0;
  // Waits up to `timeout` for one datagram; its size (which may exceed buffer.size(): the rest
  // was dropped), or nothing when none arrived in time.
  virtual std::optional<std::size_t> receive(std::span<std::uint8_t> buffer,
                                             std::chrono::microseconds timeout) = 0;
};

}  // namespace safecell
