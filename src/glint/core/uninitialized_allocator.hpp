// An allocator for std::vector whose resize() leaves new elements default-initialised: for a trivial
// type, not written at all. A mesh allocates hundreds of megabytes of triangle blocks and fills them in
// parallel; value-initialising them first would zero them all on one thread.
#pragma once

#include <memory>
#include <new>
#include <utility>

namespace glint {

template <class T>
struct UninitializedAllocator : std::allocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <class U>
    explicit UninitializedAllocator(const UninitializedAllocator<U>& /*other*/) {}

    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0) {
            ::new (static_cast<void*>(p)) U;  // default-initialisation: no zeroing
        } else {
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
        }
    }
};

}  // namespace glint
