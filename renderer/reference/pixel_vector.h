#pragma once
// A per-pixel buffer of a 1920x1080 view holds 2 M entries. std::vector value-initializes what resize() adds, on one
// thread, and that first write of fresh memory is where the OS maps it (a page fault per 4 KiB page): the G-buffer's
// 126 MB took longer than rebuilding its surface. PixelVector leaves what resize() adds uninitialized (trivial
// types; the parallel loop that fills a buffer is then the first to touch it, on every core) and asks the OS for
// transparent huge pages for large blocks (512 times fewer faults where THP is "madvise"). assign() and push_back()
// initialize as std::vector's do.
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadowlab {

template <class T>
struct UninitializedAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;

    UninitializedAllocator() = default;
    template <class U>
    UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes));
        const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* p = std::aligned_alloc(kHugePage, rounded);
        if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (n * sizeof(T) < kHugePage)
            ::operator delete(p);
        else
            std::free(p);
    }

    // No arguments: default-initialization (nothing written for a trivial type); otherwise as std::allocator.
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0)
            ::new (static_cast<void*>(p)) U;
        else
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <class U>
    bool operator==(const UninitializedAllocator<U>&) const noexcept {
        return true;
    }
};

template <class T>
using PixelVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace shadowlab
