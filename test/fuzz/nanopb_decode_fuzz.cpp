// Any payload through the controller's nanopb decode: never a write outside the static struct,
// and what it accepts encodes again within one frame and decodes to the same encoding.

#include <cstring>

#include "fuzz_targets.hpp"
#include "safecell/base/assert.hpp"
#include "safecell/protocol/nanopb_codec.hpp"

namespace safecell::fuzz {

int nanopb_decode(const std::uint8_t* data, std::size_t size) {
  static safecell_v1_Message message;
  static safecell_v1_Message again;
  static std::uint8_t encoded[kMaxPayloadBytes];
  static std::uint8_t reencoded[kMaxPayloadBytes];
  if (decode_message(data, size, message) != Status::kOk) return 0;
  const Result<std::size_t> first = encode_message(message, encoded, sizeof encoded);
  SAFECELL_ASSERT(first.ok());
  SAFECELL_ASSERT(decode_message(encoded, first.value(), again) == Status::kOk);
  const Result<std::size_t> second = encode_message(again, reencoded, sizeof reencoded);
  SAFECELL_ASSERT(second.ok() && second.value() == first.value());
  SAFECELL_ASSERT(std::memcmp(encoded, reencoded, first.value()) == 0);
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(nanopb_decode)
