#pragma once
// The receiving end of one direction of one session: every frame is checked against the session
// (ids, sequence, data age) before its payload is trusted; the arrival watchdog reports silence.
//
// Clocks: `now_ns` arguments are the receiver's estimate of the *sender's* clock at arrival (its
// own clock plus the offset from clock synchronisation); max_clock_lead_ns must cover that
// estimate's uncertainty, or honest frames are refused as stamped in the future.
// Thread context: one receiving thread (or the controller cycle); not synchronised.
// Real-time safe: no allocation, O(frame size).

#include <cstddef>
#include <cstdint>

#include "safecell/base/result.hpp"
#include "safecell/protocol/frame.hpp"
#include "safecell/protocol/link_error.hpp"

namespace safecell {

struct LinkEndpoints {
  std::uint32_t own_id = 0;
  std::uint32_t peer_id = 0;
  std::uint64_t session_id = 0;
  std::uint64_t configuration_fingerprint = 0;  // enters every CRC (frame.hpp)
};

struct ArrivalLimits {
  std::uint64_t max_data_age_ns = 0;    // capture to arrival; older data is refused
  std::uint64_t max_clock_lead_ns = 0;  // how far a capture may seem to lie ahead of now
  std::uint64_t watchdog_ns = 0;        // T_wd: no accepted frame for longer is a timeout
};

struct AcceptedFrame {
  FrameView frame;
  std::uint64_t lost = 0;         // frames skipped just before this one: report as kLoss
  std::uint64_t data_age_ns = 0;  // now - capture time (0 when the capture seems ahead)
};

class FrameChecker {
 public:
  // The watchdog starts at `now_ns`. The next frame expected has sequence number
  // last_sequence + 1 (a session opened by a handshake frame continues after its number).
  FrameChecker(const LinkEndpoints& endpoints, const ArrivalLimits& limits, std::uint64_t now_ns,
               std::uint64_t last_sequence = 0) noexcept;

  // Checks in this order: length, version, CRC (frame.hpp), destination (kAddressing), source
  // (kInsertion), session (kMasquerade), sequence (kRepetition, kIncorrectSequence), send time
  // running back (kIncorrectSequence), data age (kDelay). A frame refused for its age still
  // advances the sequence (it is authentic, only stale), so it does not also count as a loss.
  // Capture time 0 marks a control frame without data (clock echoes before the clock is synced):
  // its age is not checked, so a receiver must refuse data (a map) that comes with capture 0.
  Result<AcceptedFrame, LinkFault> check(const std::uint8_t* frame, std::size_t size,
                                         std::uint64_t now_ns) noexcept;
  // The same for a frame already opened with this session's fingerprint (open_frame): from the
  // destination check on.
  Result<AcceptedFrame, LinkFault> check_opened(const FrameView& frame,
                                                std::uint64_t now_ns) noexcept;

  // kTimeout (detail: ns since the last accepted frame) once the watchdog expired; else kNone.
  LinkFault watchdog(std::uint64_t now_ns) const noexcept;

  std::uint64_t last_sequence() const noexcept { return last_sequence_; }
  const LinkEndpoints& endpoints() const noexcept { return endpoints_; }
  // New limits from the next frame on (the coprocessor tightens them once its clock is synced).
  void set_limits(const ArrivalLimits& limits) noexcept { limits_ = limits; }

 private:
  LinkEndpoints endpoints_;
  ArrivalLimits limits_;
  std::uint64_t last_sequence_ = 0;
  std::uint64_t last_send_time_ns_ = 0;
  std::uint64_t last_accepted_ns_;
};

// The sending end of one direction of one session: numbers and seals frames.
class FrameSealer {
 public:
  explicit FrameSealer(const LinkEndpoints& endpoints) noexcept : endpoints_(endpoints) {}

  const LinkEndpoints& endpoints() const noexcept { return endpoints_; }

  // Writes the next frame (sequence number last + 1) into out[0..capacity); see write_frame.
  // flags: kFrameFlagHandshake for the frames of the handshake.
  Result<std::size_t> seal(const std::uint8_t* payload, std::size_t payload_size,
                           std::uint64_t send_time_ns, std::uint64_t capture_time_ns,
                           std::uint8_t* out, std::size_t capacity,
                           std::uint8_t flags = 0) noexcept;

  std::uint64_t last_sequence() const noexcept { return last_sequence_; }

 private:
  LinkEndpoints endpoints_;
  std::uint64_t last_sequence_ = 0;
};

}  // namespace safecell
