#pragma once
// The exception of unusable acquisition set-ups (a malformed sidecar CSV, an image folder whose
// files and time stamps disagree). Its message is one line naming the file, the line, the field
// and the value where it can, as a CellError's does; the CLI prints it as it is. Faults of a
// running camera are not exceptions: they are fault reports (camera_source.hpp).

#include <stdexcept>

namespace safecell {

class AcquisitionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace safecell
