#pragma once
// The safety layer's frame (black channel: the transport below may do anything to it).
//
//   offset  bytes  field (little-endian)
//   0       2      frame length L, the whole frame: 48 + payload, at most 1500
//   2       1      protocol version (kProtocolVersion)
//   3       1      flags: bit 0 = handshake frame (kFrameFlagHandshake); the others are 0
//   4       4      source id
//   8       4      destination id
//   12      8      session id (the handshake's opening number; the session's frames carry it
//                  XOR the controller's challenge)
//   20      8      sequence number (1, 2, ... per session and direction)
//   28      8      send time, ns in the sender's clock
//   36      8      capture time of the data, ns in the sender's clock (exposure for a map,
//                  the joint read for a joint state)
//   44      L-48   payload: one safecell.v1.Message
//   L-4     4      CRC-32/AUTOSAR (shared/base/crc32.hpp) over the implicit configuration
//                  fingerprint (8 bytes, little-endian, never sent) and bytes 0..L-5
//
// The configuration fingerprint (grid and LUT fingerprints from the handshake) enters every CRC
// without being sent, so a frame of a differently configured sender fails the CRC. Handshake
// frames (flag bit 0) use fingerprint 0 instead, whatever the caller passes, and carry the
// fingerprints in their payload, so a receiver can name a configuration that differs.
// Real-time safe: no allocation, caller storage only.

#include <cstddef>
#include <cstdint>

#include "safecell/base/result.hpp"
#include "safecell/protocol/link_error.hpp"

namespace safecell {

// 2: the session start answers the controller's challenge (handshake.proto). 1 is refused.
inline constexpr std::uint8_t kProtocolVersion = 2;
inline constexpr std::size_t kFrameHeaderBytes = 44;
inline constexpr std::size_t kFrameCrcBytes = 4;
inline constexpr std::size_t kFrameOverheadBytes = kFrameHeaderBytes + kFrameCrcBytes;
inline constexpr std::size_t kMaxFrameBytes = 1500;
inline constexpr std::size_t kMaxPayloadBytes = kMaxFrameBytes - kFrameOverheadBytes;
inline constexpr std::uint8_t kFrameFlagHandshake = 0x01;

struct FrameHeader {
  std::uint8_t version = kProtocolVersion;
  std::uint8_t flags = 0;
  std::uint32_t source_id = 0;
  std::uint32_t destination_id = 0;
  std::uint64_t session_id = 0;
  std::uint64_t sequence = 0;
  std::uint64_t send_time_ns = 0;
  std::uint64_t capture_time_ns = 0;
};

// The implicit fingerprint of a session: the grid's and the LUTs' fingerprints, combined.
std::uint64_t configuration_fingerprint(std::uint64_t grid_fingerprint,
                                        std::uint64_t lut_fingerprint) noexcept;

// Writes a frame into out[0..capacity). kCapacityExceeded when the payload is over
// kMaxPayloadBytes or the frame does not fit `capacity`. Returns the frame's length.
Result<std::size_t> write_frame(const FrameHeader& header, std::uint64_t configuration_fingerprint,
                                const std::uint8_t* payload, std::size_t payload_size,
                                std::uint8_t* out, std::size_t capacity) noexcept;

// The CRC a frame of `size` bytes must end with, for a given implicit fingerprint (0 for a
// handshake frame, whatever is passed).
std::uint32_t frame_crc(const std::uint8_t* frame, std::size_t size,
                        std::uint64_t configuration_fingerprint) noexcept;

// A frame whose length and CRC are right, split into its parts. Its header is not yet checked
// against the session (frame_checker.hpp does that).
struct FrameView {
  FrameHeader header;
  const std::uint8_t* payload = nullptr;
  std::size_t payload_size = 0;

  bool is_handshake() const noexcept { return (header.flags & kFrameFlagHandshake) != 0; }
};

// Checks the length field, the version, the CRC and the reserved flag bits, in that order, and
// splits the frame. Refusals: kCorruption (detail: the length read, or 0 for a bad CRC or flags),
// kWrongConfiguration (detail: the version read). Reads nothing outside frame[0..size).
Result<FrameView, LinkFault> open_frame(const std::uint8_t* frame, std::size_t size,
                                        std::uint64_t configuration_fingerprint) noexcept;

}  // namespace safecell
