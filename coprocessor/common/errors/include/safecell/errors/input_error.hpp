#pragma once
// The base of every error a user can fix: a file, a field, an option, a device or a peer that is
// not what it must be, the message naming it, the value found and what was expected. The command
// line turns these into exit status 2 (cli_app.hpp); any other exception that reaches it is a
// broken precondition, a bug, exit status 70. Code that checks its caller's arguments throws
// std::invalid_argument or std::logic_error, not this: a value a user typed is checked where it
// comes in.

#include <stdexcept>
#include <string>

namespace safecell {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  InputError(const InputError&) = default;
  InputError& operator=(const InputError&) = default;
  ~InputError() override;
};

}  // namespace safecell
