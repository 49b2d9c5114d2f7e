#pragma once
// The controller's payload codec: a safety-layer frame's payload <-> one safecell_v1_Message, a
// static struct whose bounds come from the .options files (protocol/proto/safecell/v1/). Call it
// only on payloads the safety layer accepted; it still treats them as hostile: any decode error,
// an oversize field or count among them, is a refusal, never a truncated message.
// Real-time safe: no allocation (nanopb without PB_ENABLE_MALLOC), bounded by the payload size.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "safecell/base/result.hpp"
#include "safecell/protocol/frame.hpp"
#include "safecell/v1/message.nanopb.h"

namespace safecell {

static_assert(
    safecell_v1_Message_size <= kMaxPayloadBytes,
    "the largest safecell.v1 Message must fit one frame; lower a max_size in the .options");

// kInvalidArgument for a payload that is not a valid Message within the bounds.
Status decode_message(const std::uint8_t* payload, std::size_t size,
                      safecell_v1_Message& message) noexcept;

// The number an enum field of a decoded message holds. nanopb stores whatever number came on the
// wire, also one the enum does not name; loading that as the enum type is undefined behaviour, so
// the field's bytes are read as its integer and compared against the enum's values.
template <typename Enum>
std::underlying_type_t<Enum> wire_enum(const Enum& field) noexcept {
  std::underlying_type_t<Enum> number{};
  __builtin_memcpy(&number, &field, sizeof number);  // bytes, not a load of the enum type
  return number;
}

// kCapacityExceeded when the encoding does not fit out[0..capacity); kInvalidArgument when the
// message breaks its own bounds (a count above max_count). Returns the bytes written.
Result<std::size_t> encode_message(const safecell_v1_Message& message, std::uint8_t* out,
                                   std::size_t capacity) noexcept;

}  // namespace safecell
