#pragma once
// Runs work over 0..count-1 in chunks on several threads, reporting progress from the calling
// thread. The offline table builds use it; nothing on the hot path does.

#include <cstddef>
#include <functional>

namespace safecell {

// Called with the share done (0..1) about ten times a second, and with 1 at the end.
using ProgressCallback = std::function<void(double fraction_done)>;

// threads: 0 = one per hardware thread. work(chunk index, begin, end) handles items begin..end-1;
// chunks are `chunk_size` items (the last may be shorter) and may run in any order, on any
// thread. The first exception a chunk throws stops the others and is rethrown here.
void parallel_chunks(std::size_t count, std::size_t chunk_size, unsigned threads,
                     const std::function<void(std::size_t, std::size_t, std::size_t)>& work,
                     const ProgressCallback& progress = {});

}  // namespace safecell
