// Replacement global allocator that counts every allocation (see allocation_counter.hpp).
//
// The blocks themselves come from glibc's allocator through its exported __libc_* entry points,
// so memory obtained through any path (operator new, malloc, a library's internal malloc) can be
// released through any other matching path. Counting uses relaxed atomics: each allocation adds
// one to a process-wide counter, which is all the scopes need.
#include "support/allocation_counter.hpp"

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <new>

// Sanitizers interpose malloc themselves; under them only operator new is counted.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define TOLIP_UNDER_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TOLIP_UNDER_SANITIZER 1
#endif

#if defined(__GLIBC__) && !defined(TOLIP_UNDER_SANITIZER)
#include <malloc.h>
#define TOLIP_COUNT_MALLOC_FAMILY 1
extern "C" {
void* __libc_malloc(std::size_t size) noexcept;
void* __libc_calloc(std::size_t count, std::size_t size) noexcept;
void* __libc_realloc(void* pointer, std::size_t size) noexcept;
void __libc_free(void* pointer) noexcept;
void* __libc_memalign(std::size_t alignment, std::size_t size) noexcept;
void* __libc_valloc(std::size_t size) noexcept;
void* __libc_pvalloc(std::size_t size) noexcept;
}
#else
#define TOLIP_COUNT_MALLOC_FAMILY 0
#endif

namespace {

// Constant-initialized: valid before any dynamic initializer runs (the loader and the C++
// runtime allocate early).
constinit std::atomic<std::uint64_t> g_allocations{0};
constinit std::atomic<std::uint64_t> g_bytes{0};

inline void record(std::size_t bytes) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  g_bytes.fetch_add(bytes, std::memory_order_relaxed);
}

// Uncounted raw block operations used by operator new/delete.
inline void* raw_malloc(std::size_t size) noexcept {
#if TOLIP_COUNT_MALLOC_FAMILY
  return __libc_malloc(size);
#else
  return std::malloc(size);
#endif
}

inline void* raw_aligned(std::size_t alignment, std::size_t size) noexcept {
#if TOLIP_COUNT_MALLOC_FAMILY
  return __libc_memalign(alignment, size);
#else
  // aligned_alloc wants a size that is a multiple of the alignment.
  const std::size_t rounded = (size + alignment - 1) / alignment * alignment;
  return std::aligned_alloc(alignment, rounded);
#endif
}

inline void raw_free(void* pointer) noexcept {
#if TOLIP_COUNT_MALLOC_FAMILY
  __libc_free(pointer);
#else
  std::free(pointer);
#endif
}

// operator new semantics: size 0 gets a unique block; on failure call the new-handler and retry,
// throw std::bad_alloc when there is none.
void* counted_new(std::size_t size) {
  record(size);
  if (size == 0) size = 1;
  for (;;) {
    if (void* pointer = raw_malloc(size)) return pointer;
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void* counted_new_aligned(std::size_t size, std::align_val_t alignment) {
  record(size);
  if (size == 0) size = 1;
  const auto align = static_cast<std::size_t>(alignment);
  for (;;) {
    if (void* pointer = raw_aligned(align, size)) return pointer;
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

namespace tolip::test {

std::uint64_t total_allocation_count() { return g_allocations.load(std::memory_order_relaxed); }
std::uint64_t total_allocated_bytes() { return g_bytes.load(std::memory_order_relaxed); }
bool counts_malloc_family() { return TOLIP_COUNT_MALLOC_FAMILY != 0; }

AllocationScope::AllocationScope()
    : start_count_(total_allocation_count()), start_bytes_(total_allocated_bytes()) {}

std::uint64_t AllocationScope::count() const { return total_allocation_count() - start_count_; }
std::uint64_t AllocationScope::bytes() const { return total_allocated_bytes() - start_bytes_; }

}  // namespace tolip::test

// ---- operator new / delete ---------------------------------------------------------------------

void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }

void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_new(size);
  } catch (...) {
    return nullptr;
  }
}

void* operator new(std::size_t size, std::align_val_t alignment) {
  return counted_new_aligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return counted_new_aligned(size, alignment);
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  try {
    return counted_new_aligned(size, alignment);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  try {
    return counted_new_aligned(size, alignment);
  } catch (...) {
    return nullptr;
  }
}

void operator delete(void* pointer) noexcept { raw_free(pointer); }
void operator delete[](void* pointer) noexcept { raw_free(pointer); }
void operator delete(void* pointer, std::size_t) noexcept { raw_free(pointer); }
void operator delete[](void* pointer, std::size_t) noexcept { raw_free(pointer); }
void operator delete(void* pointer, const std::nothrow_t&) noexcept { raw_free(pointer); }
void operator delete[](void* pointer, const std::nothrow_t&) noexcept { raw_free(pointer); }
void operator delete(void* pointer, std::align_val_t) noexcept { raw_free(pointer); }
void operator delete[](void* pointer, std::align_val_t) noexcept { raw_free(pointer); }
void operator delete(void* pointer, std::size_t, std::align_val_t) noexcept { raw_free(pointer); }
void operator delete[](void* pointer, std::size_t, std::align_val_t) noexcept { raw_free(pointer); }
void operator delete(void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { raw_free(pointer); }
void operator delete[](void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { raw_free(pointer); }

// ---- malloc family (glibc: interposed for the executable and every shared library) -------------

#if TOLIP_COUNT_MALLOC_FAMILY
extern "C" {

void* malloc(std::size_t size) noexcept {
  record(size);
  return __libc_malloc(size);
}

void* calloc(std::size_t count, std::size_t size) noexcept {
  std::size_t bytes = 0;
  record(__builtin_mul_overflow(count, size, &bytes) ? SIZE_MAX : bytes);
  return __libc_calloc(count, size);
}

void* realloc(void* pointer, std::size_t size) noexcept {
  // realloc(p, 0) frees; every other call may allocate a new block.
  if (pointer == nullptr || size != 0) record(size);
  return __libc_realloc(pointer, size);
}

void* reallocarray(void* pointer, std::size_t count, std::size_t size) noexcept {
  std::size_t bytes = 0;
  if (__builtin_mul_overflow(count, size, &bytes)) {
    errno = ENOMEM;
    return nullptr;
  }
  return realloc(pointer, bytes);
}

void free(void* pointer) noexcept { __libc_free(pointer); }

void* memalign(std::size_t alignment, std::size_t size) noexcept {
  record(size);
  return __libc_memalign(alignment, size);
}

void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  record(size);
  return __libc_memalign(alignment, size);
}

int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0 || alignment == 0) {
    return EINVAL;
  }
  record(size);
  void* pointer = __libc_memalign(alignment, size);
  if (pointer == nullptr) return ENOMEM;
  *out = pointer;
  return 0;
}

void* valloc(std::size_t size) noexcept {
  record(size);
  return __libc_valloc(size);
}

void* pvalloc(std::size_t size) noexcept {
  record(size);
  return __libc_pvalloc(size);
}

}  // extern "C"
#endif
