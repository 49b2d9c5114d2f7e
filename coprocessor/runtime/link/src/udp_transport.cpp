#include "safecell/link/udp_transport.hpp"

#include <fcntl.h>

// <utility> before Asio: Boost 1.74's coroutine header uses std::exchange without including it
// (a compile error with GCC 12 in C++20).
#include <utility>
// clang-format off
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/udp.hpp>
// clang-format on
#include <string>

#include "safecell/link/link_errors.hpp"

namespace safecell {

namespace asio = boost::asio;
using asio::ip::udp;

struct UdpTransport::State {
  asio::io_context io;
  udp::socket socket{io};
  udp::endpoint peer;
  std::uint64_t sent = 0;
  std::uint64_t received = 0;  // from the peer
};

namespace {

udp::endpoint endpoint_of(const UdpEndpoint& endpoint, const char* what) {
  boost::system::error_code error;
  const auto address = asio::ip::make_address(endpoint.address, error);
  if (error) {
    throw LinkSetupError(std::string("link: ") + what + " address '" + endpoint.address +
                         "' is not an IPv4 or IPv6 address (" + error.message() + ")");
  }
  return {address, endpoint.port};
}

}  // namespace

UdpTransport::UdpTransport(const UdpEndpoint& local, const UdpEndpoint& peer)
    : state_(std::make_unique<State>()) {
  const udp::endpoint bind_to = endpoint_of(local, "local");
  state_->peer = endpoint_of(peer, "peer");
  boost::system::error_code error;
  state_->socket.open(bind_to.protocol(), error);
  // Not inherited by programs this process starts (the controller in a closed loop).
  if (!error) (void)::fcntl(state_->socket.native_handle(), F_SETFD, FD_CLOEXEC);
  if (!error) state_->socket.bind(bind_to, error);
  if (error) {
    throw LinkSetupError("link: cannot bind UDP " + local.address + ":" +
                         std::to_string(local.port) + " (" + error.message() + ")");
  }
}

UdpTransport::~UdpTransport() = default;

unsigned short UdpTransport::local_port() const { return state_->socket.local_endpoint().port(); }

std::uint64_t UdpTransport::datagrams_sent() const { return state_->sent; }
std::uint64_t UdpTransport::datagrams_received() const { return state_->received; }

void UdpTransport::set_peer(const UdpEndpoint& peer) { state_->peer = endpoint_of(peer, "peer"); }

bool UdpTransport::send(std::span<const std::uint8_t> datagram) {
  boost::system::error_code error;
  state_->socket.send_to(asio::buffer(datagram.data(), datagram.size()), state_->peer, 0, error);
  if (error) return false;
  ++state_->sent;
  return true;
}

std::optional<std::size_t> UdpTransport::receive(std::span<std::uint8_t> buffer,
                                                 std::chrono::microseconds timeout) {
  // One byte more than the caller's buffer: a datagram that fills it all was too long.
  std::optional<std::size_t> received;
  udp::endpoint sender;
  if (timeout <= std::chrono::microseconds(0)) {
    // Only what is waiting now (the asynchronous read below would need time to run its handler,
    // and a deadline already passed gives it none): a datagram waits when bytes are available,
    // and then the blocking read returns at once.
    while (!received) {
      boost::system::error_code error;
      if (state_->socket.available(error) == 0 || error) return std::nullopt;
      std::size_t size =
          state_->socket.receive_from(asio::buffer(buffer.data(), buffer.size()), sender, 0, error);
      if (error == asio::error::message_size) {
        size = buffer.size() + 1;
        error = {};
      }
      if (error) return std::nullopt;
      if (sender == state_->peer) received = size;
    }
    ++state_->received;
    return received;
  }
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!received) {
    bool done = false;
    std::size_t size = 0;
    boost::system::error_code error;
    state_->socket.async_receive_from(asio::buffer(buffer.data(), buffer.size()), sender,
                                      [&](const boost::system::error_code& e, std::size_t n) {
                                        done = true;
                                        error = e;
                                        size = n;
                                      });
    state_->io.restart();
    state_->io.run_until(deadline);
    if (!done) {
      state_->socket.cancel();
      state_->io.restart();
      state_->io.run();  // completes the cancelled operation
      return std::nullopt;
    }
    if (error == asio::error::message_size) {
      size = buffer.size() + 1;
      error = {};
    }
    if (error) return std::nullopt;
    if (sender == state_->peer) received = size;  // from anyone else: dropped, keep waiting
  }
  ++state_->received;
  return received;
}

}  // namespace safecell
