#pragma once
// The exception of robot descriptions: a one-line message naming the file and what is wrong.

#include <stdexcept>

namespace safecell {

class RobotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace safecell
