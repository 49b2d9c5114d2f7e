#include "safecell/cspace/map_chunk.hpp"

#include "safecell/base/assert.hpp"
#include "safecell/cspace/cell_bits.hpp"

namespace safecell {
namespace {

// Appends the runs of `value` cells of target within [from, to) to the writer; returns where it
// stopped: `to`, or the start of the first run that did not fit.
template <typename WordOf>
CellIndex append_runs(WordOf target_word, CellIndex from, CellIndex to, bool value,
                      RunWriter& writer) {
  const auto value_word = [&](std::uint32_t w) { return value ? target_word(w) : ~target_word(w); };
  const auto other_word = [&](std::uint32_t w) { return value ? ~target_word(w) : target_word(w); };
  CellIndex at = from;
  while (at < to) {
    const CellIndex begin = cell_bits::next_set_in(value_word, at, to);
    if (begin == to) break;
    const CellIndex end = cell_bits::next_set_in(other_word, begin, to);
    if (!writer.append(CellRun{begin, end, value})) return begin;
    at = end;
  }
  return to;
}

}  // namespace

CellIndex encode_keyframe_chunk(const std::uint64_t* target, CellIndex cell_count, CellIndex from,
                                std::uint8_t* out, std::size_t capacity, std::size_t& out_size) {
  SAFECELL_ASSERT(capacity >= kMaxRunRecordBytes && from <= cell_count);
  RunWriter writer(out, capacity, from);
  const CellIndex end =
      append_runs([target](std::uint32_t w) { return target[w]; }, from, cell_count, true, writer);
  out_size = writer.size();
  return end;
}

CellIndex encode_delta_chunk(const std::uint64_t* base, const std::uint64_t* target,
                             CellIndex cell_count, CellIndex from, std::uint8_t* out,
                             std::size_t capacity, std::size_t& out_size) {
  SAFECELL_ASSERT(capacity >= kMaxRunRecordBytes && from <= cell_count);
  RunWriter writer(out, capacity, from);
  const auto changed = [base, target](std::uint32_t w) { return base[w] ^ target[w]; };
  const auto target_word = [target](std::uint32_t w) { return target[w]; };
  CellIndex at = from;
  while (at < cell_count) {
    // One stretch of changed cells, cut into runs where the target's value changes.
    const CellIndex begin = cell_bits::next_set_in(changed, at, cell_count);
    if (begin == cell_count) break;
    const CellIndex end =
        cell_bits::next_set_in([&](std::uint32_t w) { return ~changed(w); }, begin, cell_count);
    CellIndex run_begin = begin;
    while (run_begin < end) {
      const bool value = cell_bits::test(target, run_begin);
      const auto differs = [&](std::uint32_t w) {
        return value ? ~target_word(w) : target_word(w);
      };
      const CellIndex run_end = cell_bits::next_set_in(differs, run_begin, end);
      if (!writer.append(CellRun{run_begin, run_end, value})) {
        out_size = writer.size();
        return run_begin;
      }
      run_begin = run_end;
    }
    at = end;
  }
  out_size = writer.size();
  return cell_count;
}

Status check_map_chunk(const MapChunkView& chunk, CellIndex cell_count, CellSpan* changed) {
  if (chunk.first_cell > chunk.end_cell || chunk.end_cell > cell_count) return Status::kOutOfRange;
  if (chunk.runs == nullptr && chunk.runs_size != 0) return Status::kInvalidArgument;
  const bool keyframe = chunk.kind == MapChunkKind::kKeyframe;
  RunReader check(chunk.runs, chunk.runs_size, chunk.first_cell, chunk.end_cell);
  CellSpan span{chunk.first_cell, chunk.first_cell};
  for (;;) {
    const Result<CellRun> run = check.next();
    if (!run.ok()) {
      if (run.error() == Status::kEmpty) break;
      return run.error();
    }
    if (keyframe && !run.value().value) return Status::kInvalidArgument;
    if (span.begin == span.end) span.begin = run.value().begin;
    span.end = run.value().end;
  }
  if (keyframe) span = {chunk.first_cell, chunk.end_cell};
  if (changed != nullptr) *changed = span;
  return Status::kOk;
}

Status apply_map_chunk(const MapChunkView& chunk, std::uint64_t* words, CellIndex cell_count,
                       CellSpan* changed) {
  // Pass 1: the whole run list is valid for this chunk.
  const Status checked = check_map_chunk(chunk, cell_count, changed);
  if (checked != Status::kOk) return checked;
  const bool keyframe = chunk.kind == MapChunkKind::kKeyframe;
  // Pass 2: apply.
  if (keyframe) cell_bits::clear_range(words, chunk.first_cell, chunk.end_cell);
  RunReader apply(chunk.runs, chunk.runs_size, chunk.first_cell, chunk.end_cell);
  for (Result<CellRun> run = apply.next(); run.ok(); run = apply.next()) {
    if (run.value().value) {
      cell_bits::set_range(words, run.value().begin, run.value().end);
    } else {
      cell_bits::clear_range(words, run.value().begin, run.value().end);
    }
  }
  return Status::kOk;
}

}  // namespace safecell
