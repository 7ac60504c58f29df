#pragma once
// Allocator for the engine's large, randomly accessed arrays: blocks of 2 MiB or more are 2 MiB
// aligned and marked MADV_HUGEPAGE, so that Linux backs them with transparent huge pages where
// it allows them (`madvise` mode, Debian's default). A pair search touches ~40 particles at
// random addresses per collision; with 4 KiB pages a 6.4 MB particle array spans 1600 pages, more
// than the second-level TLB holds, and every candidate risks a page walk. Smaller blocks, and
// systems without madvise, get ordinary memory; the contents and results are the same either way.
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace coldblast::md {

inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  static bool huge(std::size_t bytes) { return bytes >= huge_page_bytes; }

  T* allocate(std::size_t count) {
    if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = count * sizeof(T);
    if (!huge(bytes)) return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    const std::size_t rounded = (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
    void* p = std::aligned_alloc(huge_page_bytes, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure leaves ordinary pages
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t count) noexcept {
    if (!huge(count * sizeof(T)))
      ::operator delete(p, std::align_val_t(alignof(T)));
    else
      std::free(p);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept {
    return false;
  }
};

/// A vector whose large buffers live on huge pages.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace coldblast::md
