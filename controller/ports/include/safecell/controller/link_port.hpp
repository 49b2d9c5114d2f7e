#pragma once
// The controller core's port to the network: datagrams in and out, one safety-layer frame each.
// Backends: controller/host/ (POSIX UDP sockets on Linux), a robot controller's own stack on a
// target. The core never blocks on it: receive() returns at once when nothing is waiting.
// Thread context: the controller's cycle (or link) task only.

#include <cstddef>
#include <cstdint>

namespace safecell {

class LinkPort {
 public:
  LinkPort() = default;
  LinkPort(const LinkPort&) = delete;
  LinkPort& operator=(const LinkPort&) = delete;

  // Sends one datagram. False when the transport refused it (the peer's watchdog sees the gap).
  virtual bool send(const std::uint8_t* data, std::size_t size) noexcept = 0;
  // Takes one waiting datagram into buffer[0..capacity) and returns its size; 0 when none waits.
  // A datagram longer than `capacity` returns capacity + 1 (and is dropped): the caller refuses
  // it as corrupt without reading past the buffer.
  virtual std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept = 0;

 protected:
  // Not deleted through the port: no virtual destructor, so no operator delete on bare metal.
  ~LinkPort() = default;
};

}  // namespace safecell
