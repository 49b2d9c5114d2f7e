#pragma once
// SAFECELL_ASSERT: the one check for programming errors (never for bad input, which is a Status).
//
// A failed assertion calls the handler installed with set_assert_handler(). The build picks the
// policy by installing the handler at start-up: the controller commands the safe stop, the host
// test runner throws so a test can expect the failure. Without a handler, or if the handler
// returns, the program traps.

namespace safecell {

using AssertHandler = void (*)(const char* file, int line, const char* expression);

// Installs the handler for failed assertions; call once during initialisation. Not thread-safe.
void set_assert_handler(AssertHandler handler) noexcept;

[[noreturn]] void assert_failed(const char* file, int line, const char* expression);

}  // namespace safecell

#define SAFECELL_ASSERT(condition) \
  ((condition) ? static_cast<void>(0) : ::safecell::assert_failed(__FILE__, __LINE__, #condition))
