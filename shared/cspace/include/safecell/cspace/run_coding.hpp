#pragma once
// The wire coding of forbidden maps: runs of cells in the grid's linear order.
//
// A run list is a byte string of run records; each record is two unsigned LEB128 varints,
//   gap            cells from the end of the previous run (the list's origin for the first run)
//   length << 1 | value   the run's length (>= 1) and the value its cells take (1 = forbidden)
// so a run covers [previous end + gap, previous end + gap + length) and sets or clears it. The
// coding is canonical: the writer emits maximal runs only (two adjacent runs differ in value), and
// a keyframe's list holds set runs only. Test vectors are in test/cspace/run_coding_test.cpp.
//
// The reader treats its bytes as hostile: a truncated or over-long varint, a zero length or a run
// past the list's limit is an error, never a read or write out of range.
// Real-time safe: no allocation; caller storage only.

#include <cstddef>
#include <cstdint>

#include "safecell/base/result.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

struct CellRun {
  CellIndex begin = 0;
  CellIndex end = 0;  // one past the last cell; end > begin
  bool value = true;  // true: the cells become forbidden; false: free
};

// The most bytes one run record takes (two varints of up to 33 bits).
inline constexpr std::size_t kMaxRunRecordBytes = 10;

class RunWriter {
 public:
  // Writes into out[0..capacity); runs are positioned relative to `origin`.
  RunWriter(std::uint8_t* out, std::size_t capacity, CellIndex origin) noexcept
      : out_(out), capacity_(capacity), cursor_(origin) {}

  // Appends a run after the previous one (precondition, checked: run.begin >= the previous end,
  // run.end > run.begin). Returns false, writing nothing, when the record does not fit.
  bool append(const CellRun& run);

  std::size_t size() const noexcept { return size_; }
  CellIndex cursor() const noexcept { return cursor_; }  // the end of the last run written

 private:
  std::uint8_t* out_;
  std::size_t capacity_;
  std::size_t size_ = 0;
  CellIndex cursor_;
};

class RunReader {
 public:
  // Reads in[0..size) as runs from `origin`; every run must end at or before `limit`.
  RunReader(const std::uint8_t* in, std::size_t size, CellIndex origin, CellIndex limit) noexcept
      : in_(in), size_(size), cursor_(origin), limit_(limit) {}

  // The next run; Status::kEmpty after the last one, kInvalidArgument for a malformed record
  // (truncated, over-long varint, zero length), kOutOfRange for a run past the limit.
  Result<CellRun> next() noexcept;

 private:
  Result<std::uint64_t> varint() noexcept;

  const std::uint8_t* in_;
  std::size_t size_;
  std::size_t offset_ = 0;
  CellIndex cursor_;
  CellIndex limit_;
};

}  // namespace safecell
