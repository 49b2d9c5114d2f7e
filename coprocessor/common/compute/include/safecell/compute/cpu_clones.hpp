#pragma once
// Function multi-versioning for the word loops of cell sets and fusion: on x86-64 with GCC or
// Clang a function marked SAFECELL_CPU_CLONES is compiled for the baseline (SSE2, where a
// population count is a library call), for POPCNT and for AVX2, and the loader picks the best
// the CPU has; elsewhere it is compiled once. The bits computed are the same in every version.

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SAFECELL_CPU_CLONES [[gnu::target_clones("avx2", "popcnt", "default")]]
#else
#define SAFECELL_CPU_CLONES
#endif
