#include "safecell/protocol/nanopb_codec.hpp"

#include "pb_decode.h"
#include "pb_encode.h"

namespace safecell {

Status decode_message(const std::uint8_t* payload, std::size_t size,
                      safecell_v1_Message& message) noexcept {
  if (payload == nullptr && size != 0) return Status::kInvalidArgument;
  message = safecell_v1_Message_init_zero;
  pb_istream_t stream = pb_istream_from_buffer(payload, size);
  return pb_decode(&stream, safecell_v1_Message_fields, &message) ? Status::kOk
                                                                  : Status::kInvalidArgument;
}

Result<std::size_t> encode_message(const safecell_v1_Message& message, std::uint8_t* out,
                                   std::size_t capacity) noexcept {
  std::size_t needed = 0;
  if (!pb_get_encoded_size(&needed, safecell_v1_Message_fields, &message)) {
    return Status::kInvalidArgument;
  }
  if (needed > capacity) return Status::kCapacityExceeded;
  pb_ostream_t stream = pb_ostream_from_buffer(out, capacity);
  if (!pb_encode(&stream, safecell_v1_Message_fields, &message)) return Status::kInvalidArgument;
  return stream.bytes_written;
}

}  // namespace safecell
