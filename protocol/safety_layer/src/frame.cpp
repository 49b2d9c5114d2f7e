#include "safecell/protocol/frame.hpp"

#include "safecell/base/crc32.hpp"
#include "safecell/base/fnv1a.hpp"

namespace safecell {
namespace {

// Little-endian field access; the frame's layout is fixed, whatever the host's byte order.
void put(std::uint8_t* at, std::uint64_t value, int bytes) noexcept {
  for (int i = 0; i < bytes; ++i) at[i] = static_cast<std::uint8_t>(value >> (8 * i));
}
std::uint64_t get(const std::uint8_t* at, int bytes) noexcept {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= std::uint64_t{at[i]} << (8 * i);
  return value;
}

}  // namespace

std::uint64_t configuration_fingerprint(std::uint64_t grid_fingerprint,
                                        std::uint64_t lut_fingerprint) noexcept {
  Fnv1a64 hash;
  hash.add_u64(grid_fingerprint);
  hash.add_u64(lut_fingerprint);
  return hash.value();
}

std::uint32_t frame_crc(const std::uint8_t* frame, std::size_t size,
                        std::uint64_t configuration_fingerprint) noexcept {
  const bool handshake = size > 3 && (frame[3] & kFrameFlagHandshake) != 0;
  std::uint8_t implicit[8];
  put(implicit, handshake ? 0 : configuration_fingerprint, 8);
  SafetyCrc32 crc;
  crc.update(implicit, sizeof implicit);
  crc.update(frame, size - kFrameCrcBytes);
  return crc.value();
}

Result<std::size_t> write_frame(const FrameHeader& header, std::uint64_t configuration_fingerprint,
                                const std::uint8_t* payload, std::size_t payload_size,
                                std::uint8_t* out, std::size_t capacity) noexcept {
  if (payload_size > kMaxPayloadBytes) return Status::kCapacityExceeded;
  const std::size_t size = kFrameOverheadBytes + payload_size;
  if (size > capacity) return Status::kCapacityExceeded;
  if (payload_size > 0 && payload == nullptr) return Status::kInvalidArgument;
  if ((header.flags & ~kFrameFlagHandshake) != 0) return Status::kInvalidArgument;
  put(out + 0, size, 2);
  out[2] = header.version;
  out[3] = header.flags;
  put(out + 4, header.source_id, 4);
  put(out + 8, header.destination_id, 4);
  put(out + 12, header.session_id, 8);
  put(out + 20, header.sequence, 8);
  put(out + 28, header.send_time_ns, 8);
  put(out + 36, header.capture_time_ns, 8);
  for (std::size_t i = 0; i < payload_size; ++i) out[kFrameHeaderBytes + i] = payload[i];
  put(out + size - kFrameCrcBytes, frame_crc(out, size, configuration_fingerprint), 4);
  return size;
}

Result<FrameView, LinkFault> open_frame(const std::uint8_t* frame, std::size_t size,
                                        std::uint64_t configuration_fingerprint) noexcept {
  if (frame == nullptr || size < kFrameOverheadBytes || size > kMaxFrameBytes) {
    return LinkFault{LinkError::kCorruption, size};
  }
  const std::uint64_t length = get(frame, 2);
  if (length != size) return LinkFault{LinkError::kCorruption, length};
  if (frame[2] != kProtocolVersion) return LinkFault{LinkError::kWrongConfiguration, frame[2]};
  if (get(frame + size - kFrameCrcBytes, 4) != frame_crc(frame, size, configuration_fingerprint)) {
    return LinkFault{LinkError::kCorruption, 0};
  }
  if ((frame[3] & ~kFrameFlagHandshake) != 0) return LinkFault{LinkError::kCorruption, 0};
  FrameView view;
  view.header.version = frame[2];
  view.header.flags = frame[3];
  view.header.source_id = static_cast<std::uint32_t>(get(frame + 4, 4));
  view.header.destination_id = static_cast<std::uint32_t>(get(frame + 8, 4));
  view.header.session_id = get(frame + 12, 8);
  view.header.sequence = get(frame + 20, 8);
  view.header.send_time_ns = get(frame + 28, 8);
  view.header.capture_time_ns = get(frame + 36, 8);
  view.payload = frame + kFrameHeaderBytes;
  view.payload_size = size - kFrameOverheadBytes;
  return view;
}

}  // namespace safecell
