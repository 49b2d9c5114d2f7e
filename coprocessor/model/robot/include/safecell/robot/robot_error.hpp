#pragma once
// The exception of robot descriptions: a one-line message naming the file and what is wrong.

#include <stdexcept>

#include "safecell/errors/input_error.hpp"

namespace safecell {

class RobotError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace safecell
