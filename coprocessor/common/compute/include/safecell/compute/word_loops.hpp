#pragma once
// The loops over whole arrays of 64-bit words that fusion runs each cycle, written for the
// vectoriser: blocks of four words whose inner loop has a trip count known at compile time (which
// GCC's -O2 cost model needs), then the rest one by one; compiled for AVX2 too (cpu_clones.hpp).
// __restrict (a GCC and Clang extension) says the arrays do not overlap.

#include <cstddef>
#include <cstdint>

namespace safecell {

// to[w] |= from[w] for w < count.
void or_words(std::uint64_t* __restrict to, const std::uint64_t* __restrict from,
              std::size_t count);
// to[w] |= a[w] & b[w] for w < count.
void or_and_words(std::uint64_t* __restrict to, const std::uint64_t* __restrict a,
                  const std::uint64_t* __restrict b, std::size_t count);
// to[w] &= from[w] for w < count.
void and_words(std::uint64_t* __restrict to, const std::uint64_t* __restrict from,
               std::size_t count);
// to[w] |= from[w] for w < count; returns whether some from[w] has a bit.
bool or_words_any(std::uint64_t* __restrict to, const std::uint64_t* __restrict from,
                  std::size_t count);
// Whether some w < count has a bit of subset[w] that set[w] lacks.
[[nodiscard]] bool any_missing(const std::uint64_t* set, const std::uint64_t* subset,
                               std::size_t count);

}  // namespace safecell
