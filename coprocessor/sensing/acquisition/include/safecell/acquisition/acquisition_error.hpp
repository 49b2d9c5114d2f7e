#pragma once
// The exception of unusable acquisition set-ups (a malformed sidecar CSV, an image folder whose
// files and time stamps disagree). Its message is one line naming the file, the line, the field
// and the value where it can, as a CellError's does; the CLI prints it as it is. Faults of a
// running camera are not exceptions: they are fault reports (camera_source.hpp).

#include <filesystem>
#include <stdexcept>
#include <string>

#include "safecell/errors/input_error.hpp"

namespace safecell {

class AcquisitionError : public InputError {
 public:
  using InputError::InputError;
};

// Throws "file:line: field: problem" ("file: field: problem" for line 0).
[[noreturn]] void throw_acquisition_error(const std::filesystem::path& file, int line,
                                          const std::string& field, const std::string& problem);

}  // namespace safecell
