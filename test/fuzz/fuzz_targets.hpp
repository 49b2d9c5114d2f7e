#pragma once
// The libFuzzer targets of the link's hostile-input paths and of the file loaders (the files an
// integrator writes: cell, URDF, calibration, controller; and the LUT files). Each is a plain
// function here so that test_fuzz_corpus replays the kept corpora with the normal tests; the fuzz
// preset builds each into a libFuzzer program (SAFECELL_FUZZ_ENTRY selects the one). A target
// returns 0 and aborts (SAFECELL_ASSERT, or a sanitizer) when an invariant breaks.

#include <cstddef>
#include <cstdint>

namespace safecell::fuzz {

// The safety layer's receiving checks on any datagram.
int frame_checker(const std::uint8_t* data, std::size_t size);
// The controller's nanopb decode of any payload, and the re-encoding of what it accepts.
int nanopb_decode(const std::uint8_t* data, std::size_t size);
// Map chunks (keyframes, deltas, any header) applied by the controller's assembler.
int map_chunk_apply(const std::uint8_t* data, std::size_t size);

// The file loaders (coprocessor builds only): any bytes as the file; a refusal is the loader's
// own error type, anything else is a finding.
int cell_file(const std::uint8_t* data, std::size_t size);
int urdf(const std::uint8_t* data, std::size_t size);
int calibration(const std::uint8_t* data, std::size_t size);
int controller_config(const std::uint8_t* data, std::size_t size);
// A LUT file (`luts info`'s summary and the service's load); mode byte 1 seals it (see the file).
int lut_file(const std::uint8_t* data, std::size_t size);
// An image folder's frame_times.csv (the folder opened as a replayed camera).
int frame_times(const std::uint8_t* data, std::size_t size);

}  // namespace safecell::fuzz

// Defines LLVMFuzzerTestOneInput for `target` in the libFuzzer build of its file.
#ifdef SAFECELL_FUZZ_ENTRY
#define SAFECELL_FUZZ_ENTRY_POINT(target)                                             \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return safecell::fuzz::target(data, size);                                        \
  }
#else
#define SAFECELL_FUZZ_ENTRY_POINT(target)
#endif
