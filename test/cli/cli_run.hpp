#pragma once
// Runs the safecell command line in-process, as a user would type it, for the CLI tests.

#include <sstream>
#include <string>
#include <vector>

#include "safecell/cli/cli_app.hpp"

namespace safecell::test {

struct CliRun {
  int exit_code;
  std::string out;
  std::string err;
};

// `safecell <arguments...>`.
inline CliRun safecell_cli(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), "safecell");
  std::vector<const char*> argv;
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  std::ostringstream out, err;
  const int code = run_safecell(static_cast<int>(argv.size()), argv.data(), out, err);
  return CliRun{code, out.str(), err.str()};
}

}  // namespace safecell::test
