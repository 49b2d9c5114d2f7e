#pragma once
// RingQueue: a first-in first-out queue of fixed capacity (RingQueue<T, N>) behind a
// capacity-erased base (RingQueue<T>). Pushing into a full queue is refused, never overwrites.
// Not thread-safe: one owner pushes and pops.

#include <cstddef>
#include <type_traits>

#include "safecell/base/assert.hpp"

namespace safecell {

template <typename T, std::size_t kCapacity = 0>
class RingQueue;

template <typename T>
class RingQueue<T, 0> {
  static_assert(std::is_trivially_copyable_v<T>, "RingQueue holds plain values");

 public:
  RingQueue(const RingQueue&) = delete;
  RingQueue& operator=(const RingQueue&) = delete;

  std::size_t size() const noexcept { return size_; }
  std::size_t capacity() const noexcept { return capacity_; }
  bool empty() const noexcept { return size_ == 0; }
  bool full() const noexcept { return size_ == capacity_; }

  [[nodiscard]] bool try_push(const T& value) noexcept {
    if (full()) return false;
    slots_[(head_ + size_) % capacity_] = value;
    ++size_;
    return true;
  }
  [[nodiscard]] bool try_pop(T& out) noexcept {
    if (empty()) return false;
    out = slots_[head_];
    head_ = (head_ + 1) % capacity_;
    --size_;
    return true;
  }
  // Precondition: index < size(); index 0 is the oldest element. Checked.
  const T& operator[](std::size_t index) const {
    SAFECELL_ASSERT(index < size_);
    return slots_[(head_ + index) % capacity_];
  }
  void clear() noexcept {
    head_ = 0;
    size_ = 0;
  }

 protected:
  RingQueue(T* slots, std::size_t capacity) noexcept : slots_(slots), capacity_(capacity) {}
  ~RingQueue() = default;

 private:
  T* slots_;
  std::size_t capacity_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

template <typename T, std::size_t kCapacity>
class RingQueue : public RingQueue<T, 0> {
  static_assert(kCapacity > 0, "a RingQueue needs room for at least one element");

 public:
  RingQueue() noexcept : RingQueue<T, 0>(slots_, kCapacity) {}

 private:
  T slots_[kCapacity]{};
};

}  // namespace safecell
