#pragma once
// Errors of the coprocessor's link that a user must act on (an address that cannot be bound, a
// controller that refuses the session and why, one that does not answer): each names what was
// expected and what was found.

#include <stdexcept>

namespace safecell {

class LinkSetupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace safecell
