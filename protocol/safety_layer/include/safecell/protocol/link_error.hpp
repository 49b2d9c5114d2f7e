#pragma once
// What the safety layer detects, named after the communication errors of IEC 61784-3 (the list of
// ../shared/SAFETY.md), plus the arrival watchdog. Every refusal of a frame carries one of these
// and a detail value (the version, id or age that was wrong), for the stop report and the log.

#include <cstdint>

namespace safecell {

enum class LinkError : std::uint8_t {
  kNone = 0,
  kCorruption,          // bad length, bad CRC, reserved bits set
  kRepetition,          // a sequence number already seen (duplicate or replay)
  kIncorrectSequence,   // a sequence number behind the last one (reordered), or time running back
  kLoss,                // sequence numbers skipped: frames lost (the frame itself is accepted)
  kDelay,               // data older than the maximum age, or stamped in the future
  kInsertion,           // a frame from a source this end does not talk to
  kMasquerade,          // a frame of another session (a stale or foreign sender)
  kAddressing,          // a frame for another destination
  kWrongConfiguration,  // an unknown protocol version or a different fingerprint
  kTimeout,             // no valid frame within the arrival watchdog T_wd
};

inline constexpr int kLinkErrorCount = 11;

// A stable name ("corruption", "repetition", ...). Never null.
const char* to_string(LinkError error) noexcept;

// A detected error: what, and the value that gave it away (meaning per error: the version read,
// the id or session seen, the data age in ns, the frames lost, the sequence number seen).
struct LinkFault {
  LinkError error = LinkError::kNone;
  std::uint64_t detail = 0;
};

}  // namespace safecell
