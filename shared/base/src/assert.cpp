#include "safecell/base/assert.hpp"

namespace safecell {
namespace {
AssertHandler g_assert_handler = nullptr;
}  // namespace

void set_assert_handler(AssertHandler handler) noexcept { g_assert_handler = handler; }

void assert_failed(const char* file, int line, const char* expression) {
  if (g_assert_handler != nullptr) {
    g_assert_handler(file, line, expression);
  }
  __builtin_trap();
}

}  // namespace safecell
