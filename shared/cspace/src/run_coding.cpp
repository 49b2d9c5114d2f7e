#include "safecell/cspace/run_coding.hpp"

namespace safecell {
namespace {

constexpr unsigned kMaxVarintBytes = 5;  // 35 bits: enough for a 33-bit length-and-value field

std::size_t varint_size(std::uint64_t value) noexcept {
  std::size_t size = 1;
  while (value >= 0x80) {
    value >>= 7;
    ++size;
  }
  return size;
}

std::size_t put_varint(std::uint8_t* out, std::uint64_t value) noexcept {
  std::size_t size = 0;
  while (value >= 0x80) {
    out[size++] = static_cast<std::uint8_t>(value | 0x80);
    value >>= 7;
  }
  out[size++] = static_cast<std::uint8_t>(value);
  return size;
}

}  // namespace

bool RunWriter::append(const CellRun& run) {
  SAFECELL_ASSERT(run.begin >= cursor_ && run.end > run.begin);
  const std::uint64_t gap = run.begin - cursor_;
  const std::uint64_t length_and_value =
      (std::uint64_t{run.end - run.begin} << 1) | (run.value ? 1U : 0U);
  if (size_ + varint_size(gap) + varint_size(length_and_value) > capacity_) return false;
  size_ += put_varint(out_ + size_, gap);
  size_ += put_varint(out_ + size_, length_and_value);
  cursor_ = run.end;
  return true;
}

Result<std::uint64_t> RunReader::varint() noexcept {
  std::uint64_t value = 0;
  for (unsigned byte = 0; byte < kMaxVarintBytes; ++byte) {
    if (offset_ >= size_) return Status::kInvalidArgument;  // truncated
    const std::uint8_t next = in_[offset_++];
    value |= std::uint64_t{next & 0x7FU} << (7 * byte);
    if ((next & 0x80U) == 0) return value;
  }
  return Status::kInvalidArgument;  // longer than any field of this coding
}

Result<CellRun> RunReader::next() noexcept {
  if (offset_ == size_) return Status::kEmpty;
  SAFECELL_TRY_ASSIGN(const std::uint64_t gap, varint());
  SAFECELL_TRY_ASSIGN(const std::uint64_t length_and_value, varint());
  const std::uint64_t length = length_and_value >> 1;
  if (length == 0) return Status::kInvalidArgument;
  const std::uint64_t begin = std::uint64_t{cursor_} + gap;
  const std::uint64_t end = begin + length;
  if (end > limit_) return Status::kOutOfRange;
  cursor_ = static_cast<CellIndex>(end);
  return CellRun{static_cast<CellIndex>(begin), static_cast<CellIndex>(end),
                 (length_and_value & 1U) != 0};
}

}  // namespace safecell
