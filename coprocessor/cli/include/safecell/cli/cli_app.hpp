#pragma once
// The safecell command line. Exit codes: 0 success, 2 bad input (a cell file, an option),
// 3 a run whose evidence (incidents, summary, report) could not all be written, 70 internal
// error; CLI11's own codes for --help (0) and unparsable options (non-zero).

#include <ostream>

namespace safecell {

inline constexpr int kExitBadInput = 2;
inline constexpr int kExitEvidenceNotWritten = 3;
inline constexpr int kExitInternalError = 70;

// Runs `safecell <argv...>`, writing results to `out` and one-line errors to `err`.
int run_safecell(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace safecell
