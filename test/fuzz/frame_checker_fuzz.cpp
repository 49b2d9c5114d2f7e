// Any datagram through the safety layer's checks: never a read outside it, and whatever is
// accepted lies inside it and belongs to the session.

#include "fuzz_targets.hpp"
#include "safecell/base/assert.hpp"
#include "safecell/protocol/frame_checker.hpp"

namespace safecell::fuzz {

int frame_checker(const std::uint8_t* data, std::size_t size) {
  constexpr LinkEndpoints kReceiver{2, 1, 0x5AFEC0DE00000001ull, 0x0123456789ABCDEFull};
  constexpr ArrivalLimits kLimits{150'000'000, 5'000'000, 100'000'000};
  FrameChecker checker(kReceiver, kLimits, 0);
  // Mode byte 1: the rest gets a right length field and CRC, so the checks behind the CRC (ids,
  // sequence, times) are explored too; any other mode: the bytes as they are.
  static std::uint8_t sealed[kMaxFrameBytes + 8];
  if (size > kFrameOverheadBytes && size <= kMaxFrameBytes + 1 && data[0] == 1) {
    for (std::size_t i = 1; i < size; ++i) sealed[i - 1] = data[i];
    const std::size_t length = size - 1;
    sealed[0] = static_cast<std::uint8_t>(length);
    sealed[1] = static_cast<std::uint8_t>(length >> 8);
    const std::uint32_t crc = frame_crc(sealed, length, kReceiver.configuration_fingerprint);
    for (std::size_t k = 0; k < 4; ++k) {
      sealed[length - 4 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
    }
    data = sealed;
    size = length;
  }
  // The same bytes twice: the second is a repetition whatever the first was.
  for (int pass = 0; pass < 2; ++pass) {
    const Result<AcceptedFrame, LinkFault> result = checker.check(data, size, 1'000'000'000);
    if (!result.ok()) {
      SAFECELL_ASSERT(result.error().error != LinkError::kNone);
      continue;
    }
    SAFECELL_ASSERT(pass == 0);
    const FrameView& frame = result.value().frame;
    SAFECELL_ASSERT(frame.payload >= data && frame.payload + frame.payload_size <= data + size);
    SAFECELL_ASSERT(frame.header.session_id == kReceiver.session_id);
    SAFECELL_ASSERT(frame.header.destination_id == kReceiver.own_id);
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(frame_checker)
