#pragma once
// The coprocessor's side of the link, scripted with the controller's own encoder (nanopb, the
// safety layer), and datagrams in memory: for the controller tests, which run under qemu-aarch64
// too and so use no coprocessor code.

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include "safecell/controller/host/scripted_coprocessor.hpp"
#include "safecell/controller/link_port.hpp"

namespace safecell::test {

using Bytes = std::vector<std::uint8_t>;

// Datagrams in memory: what the test puts in, the link receives; what the link sends, the test
// reads.
class MemoryPort final : public LinkPort {
 public:
  bool send(const std::uint8_t* data, std::size_t size) noexcept override {
    sent.emplace_back(data, data + size);
    if (on_send) on_send();
    return true;
  }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    if (inbox.empty()) return 0;
    const Bytes next = inbox.front();
    inbox.pop_front();
    if (next.size() > capacity) return capacity + 1;
    for (std::size_t i = 0; i < next.size(); ++i) buffer[i] = next[i];
    return next.size();
  }
  std::deque<Bytes> inbox;
  std::vector<Bytes> sent;
  std::function<void()> on_send;  // e.g. a send that keeps the thread (time passes)
};

// The coprocessor's side (controller/host's ScriptedCoprocessor) for the grids of the controller
// tests, which are small enough for an update in one frame.
class ScriptedCoprocessor {
 public:
  static constexpr std::uint32_t kCameras = safecell::ScriptedCoprocessor::kCameras;

  ScriptedCoprocessor(std::uint64_t grid_fingerprint, std::uint64_t lut_fingerprint,
                      std::uint64_t session, CellIndex cells)
      : sender_(grid_fingerprint, lut_fingerprint, session, cells) {}

  Bytes handshake(std::uint64_t now) { return sender_.handshake(now); }
  // The answer to the challenge in the controller's reply to the opening; the frames after it
  // are the session's.
  Bytes answer(const Bytes& controller_reply, std::uint64_t now) {
    return sender_.answer(safecell::ScriptedCoprocessor::challenge_in(controller_reply), now);
  }
  // The same for a challenge known beforehand (a test that preloads every frame).
  Bytes answer_to(std::uint64_t challenge, std::uint64_t now) {
    return sender_.answer(challenge, now);
  }
  std::uint64_t session() const { return sender_.session(); }
  // The update in one frame. wrong_hash: the hash of another map (a sender fault the receiver
  // must catch).
  Bytes update(const std::vector<std::uint64_t>* base, std::uint64_t base_version,
               const std::vector<std::uint64_t>& target, std::uint64_t version,
               std::uint64_t capture, std::uint64_t now, bool wrong_hash = false) {
    std::vector<Bytes> frames =
        sender_.update(base != nullptr ? base->data() : nullptr, base_version, target.data(),
                       version, capture, now, wrong_hash);
    EXPECT_EQ(frames.size(), 1U) << "the test's grid is too large for an update in one frame";
    return frames.front();
  }
  void set_speed_reduction_permille(std::uint32_t permille) {
    sender_.set_speed_reduction_permille(permille);
  }
  void set_healthy_cameras(std::uint32_t healthy) { sender_.set_healthy_cameras(healthy); }
  Bytes seal_payload(const Bytes& payload, std::uint64_t capture, std::uint64_t now) {
    return sender_.seal_payload(payload.data(), payload.size(), now, capture);
  }

 private:
  safecell::ScriptedCoprocessor sender_;
};

}  // namespace safecell::test
