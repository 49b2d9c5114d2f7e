#pragma once
// Errors of the coprocessor's link that a user must act on (an address that cannot be bound, a
// controller that refuses the session and why, one that does not answer): each names what was
// expected and what was found.

#include <stdexcept>

#include "safecell/errors/input_error.hpp"

namespace safecell {

class LinkSetupError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace safecell
