// A vector of at most N elements, held in place (on the stack): for the render loop's per-pixel buffers,
// where a std::array<T, N> would construct, and so zero, all N elements for every pixel and pass (and
// GCC 12 zeroed a std::array of 16 std::optional paths whole: 750 instructions a call). Here an
// element is constructed only when it is added, where it stays (a PathIntegrator path refers into
// itself), and nothing is done for the slots never used.
#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <new>
#include <span>
#include <type_traits>
#include <utility>

namespace glint {

template <class T, std::size_t N>
class FixedVector {
    // Elements are never destroyed one by one: the buffers hold plain values.
    static_assert(std::is_trivially_destructible_v<T>);

  public:
    FixedVector() = default;
    FixedVector(const FixedVector&) = delete;
    FixedVector& operator=(const FixedVector&) = delete;

    // Constructs an element at the end, in place; at most N of them.
    template <class... Args>
    T& emplace_back(Args&&... args) {
        assert(size_ < N);
        return *std::construct_at(items() + size_++, std::forward<Args>(args)...);
    }

    std::size_t size() const { return size_; }
    // Forgets every element (plain values: nothing to destroy); their slots are reused.
    void clear() { size_ = 0; }
    T& operator[](std::size_t i) {
        assert(i < size_);
        return items()[i];
    }
    const T& operator[](std::size_t i) const {
        assert(i < size_);
        return items()[i];
    }
    std::span<T> span() { return {items(), size_}; }
    std::span<const T> span() const { return {items(), size_}; }

  private:
    // Raw bytes, in which the elements are constructed one by one (not a T[N], whose elements would all
    // be constructed with it).
    T* items() { return std::launder(reinterpret_cast<T*>(storage_)); }
    const T* items() const { return std::launder(reinterpret_cast<const T*>(storage_)); }

    alignas(T) std::byte storage_[N * sizeof(T)];
    std::size_t size_ = 0;
};

}  // namespace glint
