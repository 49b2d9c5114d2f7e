#pragma once
// FixedVector: a vector whose capacity is fixed at compile time and whose storage lives inside
// the object. No heap, ever.
//
// FixedVector<T, N> owns the storage; FixedVector<T> is the capacity-erased base that functions
// take by reference, so code that fills a vector need not know its capacity (as in ETL and
// Pigweed). Adding to a full vector is refused (try_push_back returns false), never undefined.

#include <cstddef>
#include <new>
#include <type_traits>

#include "safecell/base/assert.hpp"

namespace safecell {

template <typename T, std::size_t kCapacity = 0>
class FixedVector;

template <typename T>
class FixedVector<T, 0> {
 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  // Copies go through the owning FixedVector<T, N>, whose capacity is known; between
  // capacity-erased vectors use assign(), which reports truncation.
  FixedVector(const FixedVector&) = delete;
  FixedVector& operator=(const FixedVector&) = delete;

  std::size_t size() const noexcept { return size_; }
  std::size_t capacity() const noexcept { return capacity_; }
  bool empty() const noexcept { return size_ == 0; }
  bool full() const noexcept { return size_ == capacity_; }

  T* data() noexcept { return data_; }
  const T* data() const noexcept { return data_; }
  iterator begin() noexcept { return data_; }
  iterator end() noexcept { return data_ + size_; }
  const_iterator begin() const noexcept { return data_; }
  const_iterator end() const noexcept { return data_ + size_; }

  // Precondition: index < size(). Checked.
  T& operator[](std::size_t index) {
    SAFECELL_ASSERT(index < size_);
    return data_[index];
  }
  const T& operator[](std::size_t index) const {
    SAFECELL_ASSERT(index < size_);
    return data_[index];
  }
  // Precondition: !empty(). Checked.
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }

  [[nodiscard]] bool try_push_back(const T& value) {
    if (full()) return false;
    new (data_ + size_) T(value);
    ++size_;
    return true;
  }
  // Precondition: !empty(). Checked.
  void pop_back() {
    SAFECELL_ASSERT(size_ > 0);
    --size_;
    data_[size_].~T();
  }
  void clear() noexcept {
    while (size_ > 0) {
      --size_;
      data_[size_].~T();
    }
  }
  // Replaces the contents; returns false (and keeps the first capacity() elements) when the
  // range is longer than the capacity.
  [[nodiscard]] bool assign(const T* first, const T* last) {
    clear();
    for (; first != last; ++first) {
      if (!try_push_back(*first)) return false;
    }
    return true;
  }

 protected:
  FixedVector(T* data, std::size_t capacity) noexcept : data_(data), capacity_(capacity) {}
  ~FixedVector() = default;  // the owner destroys the elements while its storage still lives

 private:
  T* data_;
  std::size_t size_ = 0;
  std::size_t capacity_;
};

template <typename T, std::size_t kCapacity>
class FixedVector : public FixedVector<T, 0> {
  static_assert(kCapacity > 0, "a FixedVector needs room for at least one element");
  using Base = FixedVector<T, 0>;

 public:
  FixedVector() noexcept : Base(slots(), kCapacity) {}
  FixedVector(const FixedVector& other) : Base(slots(), kCapacity) {
    static_cast<void>(Base::assign(other.begin(), other.end()));
  }
  FixedVector& operator=(const FixedVector& other) {
    // Same capacity on both sides: assign() cannot truncate.
    if (this != &other) static_cast<void>(Base::assign(other.begin(), other.end()));
    return *this;
  }
  ~FixedVector() { Base::clear(); }

 private:
  T* slots() noexcept { return std::launder(reinterpret_cast<T*>(storage_)); }

  alignas(T) unsigned char storage_[sizeof(T) * kCapacity];
};

}  // namespace safecell
