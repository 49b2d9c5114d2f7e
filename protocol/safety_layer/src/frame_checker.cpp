#include "safecell/protocol/frame_checker.hpp"

namespace safecell {

FrameChecker::FrameChecker(const LinkEndpoints& endpoints, const ArrivalLimits& limits,
                           std::uint64_t now_ns, std::uint64_t last_sequence) noexcept
    : endpoints_(endpoints),
      limits_(limits),
      last_sequence_(last_sequence),
      last_accepted_ns_(now_ns) {}

Result<AcceptedFrame, LinkFault> FrameChecker::check(const std::uint8_t* frame, std::size_t size,
                                                     std::uint64_t now_ns) noexcept {
  const Result<FrameView, LinkFault> opened =
      open_frame(frame, size, endpoints_.configuration_fingerprint);
  if (!opened.ok()) return opened.error();
  return check_opened(opened.value(), now_ns);
}

Result<AcceptedFrame, LinkFault> FrameChecker::check_opened(const FrameView& frame,
                                                            std::uint64_t now_ns) noexcept {
  const FrameHeader& header = frame.header;
  if (header.destination_id != endpoints_.own_id) {
    return LinkFault{LinkError::kAddressing, header.destination_id};
  }
  if (header.source_id != endpoints_.peer_id) {
    return LinkFault{LinkError::kInsertion, header.source_id};
  }
  if (header.session_id != endpoints_.session_id) {
    return LinkFault{LinkError::kMasquerade, header.session_id};
  }
  if (header.sequence == last_sequence_) return LinkFault{LinkError::kRepetition, header.sequence};
  if (header.sequence < last_sequence_) {
    return LinkFault{LinkError::kIncorrectSequence, header.sequence};
  }
  if (header.send_time_ns < last_send_time_ns_ || header.capture_time_ns > header.send_time_ns) {
    return LinkFault{LinkError::kIncorrectSequence, header.sequence};
  }
  // Authentic and in order from here on: it moves the sequence even when it is too old.
  AcceptedFrame accepted;
  accepted.frame = frame;
  accepted.lost = header.sequence - last_sequence_ - 1;
  last_sequence_ = header.sequence;
  last_send_time_ns_ = header.send_time_ns;
  if (header.capture_time_ns == 0) {
    // A control frame without data (handshake answers, clock echoes): nothing ages.
  } else if (header.capture_time_ns > now_ns) {
    const std::uint64_t lead = header.capture_time_ns - now_ns;
    if (lead > limits_.max_clock_lead_ns) return LinkFault{LinkError::kDelay, lead};
  } else {
    accepted.data_age_ns = now_ns - header.capture_time_ns;
    if (accepted.data_age_ns > limits_.max_data_age_ns) {
      return LinkFault{LinkError::kDelay, accepted.data_age_ns};
    }
  }
  last_accepted_ns_ = now_ns;
  return accepted;
}

LinkFault FrameChecker::watchdog(std::uint64_t now_ns) const noexcept {
  if (now_ns <= last_accepted_ns_) return {};
  const std::uint64_t silent = now_ns - last_accepted_ns_;
  if (silent > limits_.watchdog_ns) return LinkFault{LinkError::kTimeout, silent};
  return {};
}

Result<std::size_t> FrameSealer::seal(const std::uint8_t* payload, std::size_t payload_size,
                                      std::uint64_t send_time_ns, std::uint64_t capture_time_ns,
                                      std::uint8_t* out, std::size_t capacity,
                                      std::uint8_t flags) noexcept {
  FrameHeader header;
  header.flags = flags;
  header.source_id = endpoints_.own_id;
  header.destination_id = endpoints_.peer_id;
  header.session_id = endpoints_.session_id;
  header.sequence = last_sequence_ + 1;
  header.send_time_ns = send_time_ns;
  header.capture_time_ns = capture_time_ns;
  const Result<std::size_t> written = write_frame(header, endpoints_.configuration_fingerprint,
                                                  payload, payload_size, out, capacity);
  if (written.ok()) last_sequence_ = header.sequence;
  return written;
}

}  // namespace safecell
