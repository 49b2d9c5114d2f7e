#include "safecell/controller/host/udp_link_port.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace safecell {
namespace {

sockaddr_in address_of(const UdpAddress& address, const char* what) {
  sockaddr_in out{};
  out.sin_family = AF_INET;
  out.sin_port = htons(address.port);
  if (inet_pton(AF_INET, address.ip.c_str(), &out.sin_addr) != 1) {
    throw std::runtime_error(std::string("controller link: ") + what + " address '" + address.ip +
                             "' is not an IPv4 address");
  }
  return out;
}

}  // namespace

UdpLinkPort::UdpLinkPort(const UdpAddress& local, const UdpAddress& peer) {
  const sockaddr_in bind_to = address_of(local, "local");
  const sockaddr_in peer_address = address_of(peer, "peer");
  peer_ip_ = peer_address.sin_addr.s_addr;
  peer_port_ = peer_address.sin_port;
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (socket_ < 0) {
    throw std::runtime_error(std::string("controller link: socket(): ") + std::strerror(errno));
  }
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API takes sockaddr.
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&bind_to), sizeof bind_to) != 0) {
    const int error = errno;
    ::close(socket_);
    throw std::runtime_error("controller link: cannot bind UDP " + local.ip + ":" +
                             std::to_string(local.port) + " (" + std::strerror(error) + ")");
  }
}

void UdpLinkPort::set_peer(const UdpAddress& peer) {
  const sockaddr_in address = address_of(peer, "peer");
  peer_ip_ = address.sin_addr.s_addr;
  peer_port_ = address.sin_port;
}

UdpLinkPort::~UdpLinkPort() {
  if (socket_ >= 0) ::close(socket_);
}

std::uint16_t UdpLinkPort::local_port() const {
  sockaddr_in bound{};
  socklen_t size = sizeof bound;
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API takes sockaddr.
  ::getsockname(socket_, reinterpret_cast<sockaddr*>(&bound), &size);
  return ntohs(bound.sin_port);
}

bool UdpLinkPort::send(const std::uint8_t* data, std::size_t size) noexcept {
  sockaddr_in peer{};
  peer.sin_family = AF_INET;
  peer.sin_addr.s_addr = peer_ip_;
  peer.sin_port = peer_port_;
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API takes sockaddr.
  const ssize_t sent =
      ::sendto(socket_, data, size, 0, reinterpret_cast<const sockaddr*>(&peer), sizeof peer);
  if (sent != static_cast<ssize_t>(size)) return false;
  ++sent_;
  return true;
}

std::size_t UdpLinkPort::receive(std::uint8_t* buffer, std::size_t capacity) noexcept {
  for (;;) {
    sockaddr_in sender{};
    socklen_t sender_size = sizeof sender;
    // MSG_TRUNC: the return value is the datagram's real length, so an oversize one is seen.
    const ssize_t received =
        // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): sockets take sockaddr.
        ::recvfrom(socket_, buffer, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&sender),
                   &sender_size);
    if (received <= 0) return 0;  // nothing waiting (EAGAIN), or an empty datagram
    if (sender.sin_addr.s_addr != peer_ip_ || sender.sin_port != peer_port_) {
      ++dropped_foreign_;
      continue;
    }
    ++received_;
    const auto size = static_cast<std::size_t>(received);
    return size > capacity ? capacity + 1 : size;
  }
}

bool UdpLinkPort::wait_readable(int timeout_us) const noexcept {
  pollfd waiting{socket_, POLLIN, 0};
  timespec timeout{timeout_us / 1'000'000, static_cast<long>(timeout_us % 1'000'000) * 1000};
  return ::ppoll(&waiting, 1, &timeout, nullptr) > 0;
}

}  // namespace safecell
