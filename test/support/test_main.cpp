#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <string_view>

#include "safecell/base/assert.hpp"
#include "safecell/test/property.hpp"

namespace {

void throw_on_assert(const char* file, int line, const char* expression) {
  throw safecell::test::AssertFailure(std::string(file) + ":" + std::to_string(line) +
                                      ": SAFECELL_ASSERT(" + expression + ") failed");
}

// Reads --name=value from the arguments (removing it) or, failing that, the environment.
bool take_setting(int& argc, char** argv, std::string_view name, const char* env,
                  std::string& value) {
  const std::string prefix = "--" + std::string(name) + "=";
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument.substr(0, prefix.size()) == prefix) {
      value = argument.substr(prefix.size());
      for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      return true;
    }
  }
  if (const char* from_env = std::getenv(env)) {
    value = from_env;
    return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  safecell::set_assert_handler(&throw_on_assert);
  auto& settings = safecell::test::property_settings();
  std::string value;
  try {
    settings.seed = take_setting(argc, argv, "seed", "SAFECELL_SEED", value)
                        ? std::stoull(value)
                        : std::random_device{}();
    if (take_setting(argc, argv, "iterations", "SAFECELL_ITERATIONS", value)) {
      settings.iterations = std::stoi(value);
    }
  } catch (const std::exception&) {
    std::cerr << "bad --seed or --iterations value '" << value << "'\n";
    return 2;
  }
  std::cout << "property tests: seed=" << settings.seed << '\n';
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
