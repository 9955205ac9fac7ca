// A vector of at most N elements, held in place (on the stack): for the render loop's per-pixel buffers,
// where a std::array<T, N> would construct, and so zero, all N elements for every pixel and pass, and a
// std::array of std::optional<T> was zeroed whole as well (750 instructions a call for 16 paths). Here
// an element is constructed only when it is added, where it stays (a PathIntegrator path refers into
// itself), and nothing is done for the slots never used.
#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <span>
#include <type_traits>
#include <utility>

namespace glint {

template <class T, std::size_t N>
class FixedVector {
    // Elements are never destroyed one by one: the buffers hold plain values.
    static_assert(std::is_trivially_destructible_v<T>);

  public:
    FixedVector() {}  // leaves the slots unconstructed (`= default` would not, for some T)
    FixedVector(const FixedVector&) = delete;
    FixedVector& operator=(const FixedVector&) = delete;

    // Constructs an element at the end, in place; at most N of them.
    template <class... Args>
    T& emplace_back(Args&&... args) {
        assert(size_ < N);
        return *std::construct_at(&items_[size_++], std::forward<Args>(args)...);
    }

    std::size_t size() const { return size_; }
    T& operator[](std::size_t i) { return items_[i]; }
    const T& operator[](std::size_t i) const { return items_[i]; }
    std::span<T> span() { return {items_, size_}; }
    std::span<const T> span() const { return {items_, size_}; }

  private:
    union {
        T items_[N];
    };
    std::size_t size_ = 0;
};

}  // namespace glint
