#pragma once
// Result<T, E>: a value or an error, for code that may not throw.

#include <new>
#include <type_traits>

#include "safecell/base/assert.hpp"
#include "safecell/base/status.hpp"

namespace safecell {

template <typename T, typename E = Status>
class [[nodiscard]] Result {
  static_assert(std::is_trivially_destructible_v<E>, "error types are plain values");

 public:
  // Implicit on purpose: `return value;` and `return Status::kOutOfRange;` both read naturally.
  Result(const T& value) : has_value_(true) {
    new (&value_) T(value);
  }  // NOLINT(google-explicit-constructor)
  Result(T&& value) : has_value_(true) { new (&value_) T(static_cast<T&&>(value)); }  // NOLINT
  Result(E error) : has_value_(false), error_(error) {}                               // NOLINT

  Result(const Result& other) : has_value_(other.has_value_) { copy_from(other); }
  Result& operator=(const Result& other) {
    if (this != &other) {
      destroy();
      has_value_ = other.has_value_;
      copy_from(other);
    }
    return *this;
  }
  ~Result() { destroy(); }

  bool ok() const noexcept { return has_value_; }
  explicit operator bool() const noexcept { return has_value_; }

  // Precondition for value(): ok(). For error(): !ok(). Both are checked.
  const T& value() const& {
    SAFECELL_ASSERT(has_value_);
    return value_;
  }
  T& value() & {
    SAFECELL_ASSERT(has_value_);
    return value_;
  }
  E error() const {
    SAFECELL_ASSERT(!has_value_);
    return error_;
  }
  T value_or(const T& fallback) const { return has_value_ ? value_ : fallback; }

 private:
  void copy_from(const Result& other) {
    if (other.has_value_) {
      new (&value_) T(other.value_);
    } else {
      error_ = other.error_;
    }
  }
  void destroy() {
    if (has_value_) value_.~T();
  }

  bool has_value_;
  union {
    T value_;
    E error_;
  };
};

}  // namespace safecell

// SAFECELL_TRY(expr): evaluates an expression returning Status; returns it from the enclosing
// function unless it is kOk.
#define SAFECELL_TRY(expr)                                  \
  do {                                                      \
    const ::safecell::Status safecell_try_status_ = (expr); \
    if (safecell_try_status_ != ::safecell::Status::kOk) {  \
      return safecell_try_status_;                          \
    }                                                       \
  } while (false)

#define SAFECELL_CONCAT_INNER(a, b) a##b
#define SAFECELL_CONCAT(a, b) SAFECELL_CONCAT_INNER(a, b)

// SAFECELL_TRY_ASSIGN(lhs, expr): evaluates an expression returning Result<T, E>; returns its
// error from the enclosing function, otherwise assigns the value to lhs (which may be a
// declaration such as `const auto index`).
#define SAFECELL_TRY_ASSIGN(lhs, expr) \
  SAFECELL_TRY_ASSIGN_IMPL(SAFECELL_CONCAT(safecell_try_result_, __LINE__), lhs, expr)
// NOLINTBEGIN(bugprone-macro-parentheses): lhs is a declaration and result a name.
#define SAFECELL_TRY_ASSIGN_IMPL(result, lhs, expr) \
  auto result = (expr);                             \
  if (!result.ok()) return result.error();          \
  lhs = result.value()
// NOLINTEND(bugprone-macro-parentheses)
