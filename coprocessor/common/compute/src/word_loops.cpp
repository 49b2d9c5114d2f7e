#include "safecell/compute/word_loops.hpp"

#include "safecell/compute/cpu_clones.hpp"

namespace safecell {
namespace {

constexpr std::size_t kBlock = 4;

}  // namespace

SAFECELL_CPU_CLONES void or_words(std::uint64_t* __restrict to,
                                  const std::uint64_t* __restrict from, std::size_t count) {
  std::size_t w = 0;
  for (; w + kBlock <= count; w += kBlock) {
    for (std::size_t k = 0; k < kBlock; ++k) to[w + k] |= from[w + k];
  }
  for (; w < count; ++w) to[w] |= from[w];
}

SAFECELL_CPU_CLONES void or_and_words(std::uint64_t* __restrict to,
                                      const std::uint64_t* __restrict a,
                                      const std::uint64_t* __restrict b, std::size_t count) {
  std::size_t w = 0;
  for (; w + kBlock <= count; w += kBlock) {
    for (std::size_t k = 0; k < kBlock; ++k) to[w + k] |= a[w + k] & b[w + k];
  }
  for (; w < count; ++w) to[w] |= a[w] & b[w];
}

SAFECELL_CPU_CLONES void and_words(std::uint64_t* __restrict to,
                                   const std::uint64_t* __restrict from, std::size_t count) {
  std::size_t w = 0;
  for (; w + kBlock <= count; w += kBlock) {
    for (std::size_t k = 0; k < kBlock; ++k) to[w + k] &= from[w + k];
  }
  for (; w < count; ++w) to[w] &= from[w];
}

SAFECELL_CPU_CLONES bool or_words_any(std::uint64_t* __restrict to,
                                      const std::uint64_t* __restrict from, std::size_t count) {
  std::uint64_t any[kBlock]{};
  std::size_t w = 0;
  for (; w + kBlock <= count; w += kBlock) {
    for (std::size_t k = 0; k < kBlock; ++k) {
      to[w + k] |= from[w + k];
      any[k] |= from[w + k];
    }
  }
  for (; w < count; ++w) {
    to[w] |= from[w];
    any[0] |= from[w];
  }
  return (any[0] | any[1] | any[2] | any[3]) != 0;
}

SAFECELL_CPU_CLONES bool any_missing(const std::uint64_t* set, const std::uint64_t* subset,
                                     std::size_t count) {
  std::uint64_t missing[kBlock]{};
  std::size_t w = 0;
  for (; w + kBlock <= count; w += kBlock) {
    for (std::size_t k = 0; k < kBlock; ++k) missing[k] |= subset[w + k] & ~set[w + k];
  }
  for (; w < count; ++w) missing[0] |= subset[w] & ~set[w];
  return (missing[0] | missing[1] | missing[2] | missing[3]) != 0;
}

}  // namespace safecell
