#include "safecell/faultproxy/fault_proxy.hpp"

// <utility> before Asio: Boost 1.74's coroutine header uses std::exchange without including it.
#include <utility>
// clang-format off
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
// clang-format on
#include <array>
#include <future>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "safecell/protocol/frame.hpp"

namespace safecell {

namespace asio = boost::asio;
using asio::ip::udp;
using Datagram = std::vector<std::uint8_t>;

namespace {

// One direction: datagrams received on `in` go out of `out` to `*to`; their sender is learnt
// into `*from` (the other direction's destination) when not configured.
struct Direction {
  FaultRates rates;
  udp::socket* in = nullptr;
  udp::socket* out = nullptr;
  std::optional<udp::endpoint>* to = nullptr;
  std::optional<udp::endpoint>* from = nullptr;
  std::array<std::uint8_t, 65536> buffer{};
  udp::endpoint sender;
  std::optional<Datagram> held;  // reordering: sent after the next datagram
  FaultCounts counts;
};

nlohmann::json json_of(const FaultCounts& c) {
  return {{"received", c.received},
          {"forwarded", c.forwarded},
          {"dropped", c.dropped},
          {"duplicated", c.duplicated},
          {"reordered", c.reordered},
          {"delayed", c.delayed},
          {"flipped", c.flipped},
          {"inserted", c.inserted},
          {"foreign_session", c.foreign_session},
          {"resealed_flipped", c.resealed_flipped},
          {"cut", c.cut}};
}

udp::socket bound_socket(asio::io_context& io, const std::string& ip, std::uint16_t port) {
  boost::system::error_code error;
  const auto address = asio::ip::make_address(ip, error);
  if (error) throw std::runtime_error("fault proxy: '" + ip + "' is not an IP address");
  udp::socket socket(io);
  socket.open(udp::endpoint(address, port).protocol(), error);
  if (!error) socket.bind(udp::endpoint(address, port), error);
  if (error) {
    throw std::runtime_error("fault proxy: cannot bind UDP " + ip + ":" + std::to_string(port) +
                             " (" + error.message() + ")");
  }
  return socket;
}

}  // namespace

struct FaultProxy::State {
  explicit State(const FaultProxySettings& s)
      : settings(s),
        socket_a(bound_socket(io, s.ip, s.listen_a)),
        socket_b(bound_socket(io, s.ip, s.listen_b)),
        rng(s.seed) {
    const auto address = asio::ip::make_address(s.ip);
    if (s.peer_a != 0) peer_a = udp::endpoint(address, s.peer_a);
    if (s.peer_b != 0) peer_b = udp::endpoint(address, s.peer_b);
    a_to_b = {s.a_to_b, &socket_a, &socket_b, &peer_b, &peer_a, {}, {}, {}, {}};
    b_to_a = {s.b_to_a, &socket_b, &socket_a, &peer_a, &peer_b, {}, {}, {}, {}};
  }

  FaultProxySettings settings;
  asio::io_context io;
  udp::socket socket_a;
  udp::socket socket_b;
  std::optional<udp::endpoint> peer_a, peer_b;
  Direction a_to_b, b_to_a;
  std::mt19937_64 rng;
  std::chrono::steady_clock::time_point started;
  std::thread thread;
  mutable std::mutex counts_mutex;  // counts change on the proxy thread and are read anywhere

  double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

  void count(std::uint64_t FaultCounts::*field, Direction& d) {
    const std::lock_guard lock(counts_mutex);
    ++(d.counts.*field);
  }

  void send(Direction& d, const Datagram& datagram) {
    if (!d.to->has_value()) return;
    boost::system::error_code ignored;
    d.out->send_to(asio::buffer(datagram), **d.to, 0, ignored);
    count(&FaultCounts::forwarded, d);
  }

  // A frame shaped like the link's that belongs to no session of it.
  Datagram foreign_frame() {
    FrameHeader header;
    header.source_id = static_cast<std::uint32_t>(rng());
    header.destination_id = static_cast<std::uint32_t>(rng());
    header.session_id = rng();
    header.sequence = rng() % 1000;
    Datagram payload(rng() % 200);
    for (auto& byte : payload) byte = static_cast<std::uint8_t>(rng());
    Datagram frame(kMaxFrameBytes);
    const auto size =
        write_frame(header, rng(), payload.data(), payload.size(), frame.data(), frame.size());
    frame.resize(size.value_or(0));
    return frame;
  }

  // `datagram` again under another session, sealed as its sender would; empty when it does not
  // open with the session's fingerprint (a handshake, or the fingerprint not given).
  Datagram in_foreign_session(const Datagram& datagram) {
    return resealed(datagram, [this](FrameHeader& header, Datagram&) {
      header.session_id ^= 0x5A5A5A5A00000000ull | (rng() & 0xFFFFFFFFull) | 1U;
    });
  }

  // `datagram` with 1..max_flipped_bits bits of its payload flipped, sealed again (empty: as
  // above).
  Datagram with_payload_flipped(const Datagram& datagram, int max_flipped_bits) {
    return resealed(datagram, [this, max_flipped_bits](FrameHeader&, Datagram& payload) {
      if (payload.empty()) return;
      const auto bits = 1 + rng() % static_cast<std::uint64_t>(std::max(1, max_flipped_bits));
      for (std::uint64_t b = 0; b < bits; ++b) {
        const std::size_t bit = rng() % (payload.size() * 8);
        payload[bit / 8] ^= static_cast<std::uint8_t>(1U << (bit % 8));
      }
    });
  }

  // A data frame of the session opened, its header and payload changed by `change`, and sealed
  // with a valid CRC; empty when it does not open with the session's fingerprint (a handshake,
  // or the fingerprint not given).
  template <typename Change>
  Datagram resealed(const Datagram& datagram, Change change) {
    const std::uint64_t fingerprint = settings.configuration_fingerprint;
    if (fingerprint == 0) return {};
    const auto view = open_frame(datagram.data(), datagram.size(), fingerprint);
    if (!view.ok() || view.value().is_handshake()) return {};
    FrameHeader header = view.value().header;
    Datagram payload(view.value().payload, view.value().payload + view.value().payload_size);
    change(header, payload);
    Datagram frame(kMaxFrameBytes);
    const auto size = write_frame(header, fingerprint, payload.data(), payload.size(), frame.data(),
                                  frame.size());
    if (!size.ok()) return {};
    frame.resize(size.value());
    return frame;
  }

  void forward(Direction& d, Datagram datagram) {
    const FaultRates& r = d.rates;
    count(&FaultCounts::received, d);
    const auto since_start = std::chrono::steady_clock::now() - started;
    if (r.cut_for.count() > 0 && since_start >= r.cut_after &&
        since_start < r.cut_after + r.cut_for) {
      count(&FaultCounts::cut, d);
      return;
    }
    if (uniform() < r.drop) {
      count(&FaultCounts::dropped, d);
      return;
    }
    if (uniform() < r.insert) {
      count(&FaultCounts::inserted, d);
      send(d, foreign_frame());
    }
    if (uniform() < r.foreign_session) {
      const Datagram foreign = in_foreign_session(datagram);
      if (!foreign.empty()) {
        count(&FaultCounts::foreign_session, d);
        send(d, foreign);
      }
    }
    if (uniform() < r.resealed_flip) {
      Datagram flipped = with_payload_flipped(datagram, r.max_flipped_bits);
      if (!flipped.empty()) {
        count(&FaultCounts::resealed_flipped, d);
        datagram = std::move(flipped);
      }
    }
    if (uniform() < r.flip && !datagram.empty()) {
      count(&FaultCounts::flipped, d);
      const auto bits = 1 + rng() % static_cast<std::uint64_t>(std::max(1, r.max_flipped_bits));
      for (std::uint64_t b = 0; b < bits; ++b) {
        const std::size_t bit = rng() % (datagram.size() * 8);
        datagram[bit / 8] ^= static_cast<std::uint8_t>(1U << (bit % 8));
      }
    }
    const bool slow_stretch = r.delay_for.count() > 0 && since_start >= r.delay_after &&
                              since_start < r.delay_after + r.delay_for;
    if (slow_stretch || uniform() < r.delay) {
      count(&FaultCounts::delayed, d);
      auto timer = std::make_shared<asio::steady_timer>(io, r.delay_by);
      timer->async_wait([this, &d, timer, datagram](const boost::system::error_code& e) {
        if (!e) send(d, datagram);
      });
      return;
    }
    if (uniform() < r.duplicate) {
      count(&FaultCounts::duplicated, d);
      send(d, datagram);
    }
    if (!d.held && uniform() < r.reorder) {
      count(&FaultCounts::reordered, d);
      d.held = std::move(datagram);
      return;
    }
    send(d, datagram);
    if (d.held) {
      send(d, *d.held);
      d.held.reset();
    }
  }

  void receive(Direction& d) {
    d.in->async_receive_from(
        asio::buffer(d.buffer), d.sender,
        [this, &d](const boost::system::error_code& error, std::size_t size) {
          if (error == asio::error::operation_aborted) return;
          if (!error) {
            if (!d.from->has_value()) *d.from = d.sender;
            if (d.sender == **d.from) {
              forward(d, Datagram(d.buffer.begin(),
                                  d.buffer.begin() + static_cast<std::ptrdiff_t>(size)));
            }
          }
          receive(d);
        });
  }
};

FaultProxy::FaultProxy(const FaultProxySettings& settings)
    : state_(std::make_unique<State>(settings)) {}

FaultProxy::~FaultProxy() { stop(); }

void FaultProxy::start() {
  if (state_->thread.joinable()) return;
  state_->started = std::chrono::steady_clock::now();
  state_->receive(state_->a_to_b);
  state_->receive(state_->b_to_a);
  state_->thread = std::thread([this] { state_->io.run(); });
}

void FaultProxy::stop() {
  if (!state_->thread.joinable()) return;
  state_->io.stop();
  state_->thread.join();
}

void FaultProxy::set_rates(const FaultRates& a_to_b, const FaultRates& b_to_a) {
  if (!state_->thread.joinable()) {
    state_->a_to_b.rates = a_to_b;
    state_->b_to_a.rates = b_to_a;
    return;
  }
  // On the proxy's thread, which reads the rates; waited for, so the caller's time is the switch.
  std::promise<void> done;
  asio::post(state_->io, [this, a_to_b, b_to_a, &done] {
    state_->a_to_b.rates = a_to_b;
    state_->b_to_a.rates = b_to_a;
    done.set_value();
  });
  done.get_future().wait();
}

std::uint16_t FaultProxy::port_a() const { return state_->socket_a.local_endpoint().port(); }
std::uint16_t FaultProxy::port_b() const { return state_->socket_b.local_endpoint().port(); }

FaultCounts FaultProxy::counts_a_to_b() const {
  const std::lock_guard lock(state_->counts_mutex);
  return state_->a_to_b.counts;
}

FaultCounts FaultProxy::counts_b_to_a() const {
  const std::lock_guard lock(state_->counts_mutex);
  return state_->b_to_a.counts;
}

std::string FaultProxy::report_json() const {
  const nlohmann::json report = {{"seed", state_->settings.seed},
                                 {"a_to_b", json_of(counts_a_to_b())},
                                 {"b_to_a", json_of(counts_b_to_a())}};
  return report.dump();
}

}  // namespace safecell
