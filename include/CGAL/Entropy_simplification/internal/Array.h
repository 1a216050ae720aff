// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's arrays: std::vector with an allocator that maps large
// blocks in huge pages where the system offers them.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <vector>

// Mapped blocks escape AddressSanitizer's checks: sanitized builds keep
// operator new.
#if defined(MADV_HUGEPAGE) && !defined(__SANITIZE_ADDRESS__)
#if defined(__has_feature)
#if !__has_feature(address_sanitizer)
#define CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
#endif
#else
#define CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
#endif
#endif

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Nearly every array of the package holds a value per point, is allocated
// while the run goes on, and is written through at once. The first write to
// each page of fresh memory costs a page fault: with 4 KiB pages, the
// faults took about a sixth of the default mode's time on 10^6 points on
// the benchmark's virtual machine (12 microseconds each). So blocks of 2 MiB
// and more are mapped on their own, aligned on 2 MiB and advised as
// candidates for transparent huge pages: one fault where there were 512,
// and the memory goes back to the system as soon as the block is freed.
// Where the kernel gives no huge page, the advice changes nothing.
constexpr std::size_t huge_page_size = std::size_t(1) << 21;

inline std::size_t whole_huge_pages(std::size_t bytes)
{
  return (bytes + huge_page_size - 1) / huge_page_size * huge_page_size;
}

#ifdef CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
// `length` bytes, a multiple of huge_page_size, aligned on it: mapped with
// room to align, then trimmed.
inline void* map_huge_pages(std::size_t length)
{
  void* mapped = mmap(nullptr, length + huge_page_size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED)
    throw std::bad_alloc();
  char* const start = static_cast<char*>(mapped);
  const std::size_t lead = (huge_page_size - reinterpret_cast<std::uintptr_t>(start) % huge_page_size) % huge_page_size;
  if (lead > 0)
    munmap(start, lead);
  munmap(start + lead + length, huge_page_size - lead);
  madvise(start + lead, length, MADV_HUGEPAGE); // advice only: a refusal leaves ordinary pages
  return start + lead;
}
#endif

template <typename T>
class Huge_page_allocator
{
public:
  using value_type = T;

  Huge_page_allocator() = default;
  template <typename U>
  Huge_page_allocator(const Huge_page_allocator<U>&) noexcept
  {}

  T* allocate(std::size_t n)
  {
    if (n > ((std::numeric_limits<std::size_t>::max)() - huge_page_size) / sizeof(T))
      throw std::bad_array_new_length();
#ifdef CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
    if (is_mapped(n))
      return static_cast<T*>(map_huge_pages(whole_huge_pages(n * sizeof(T))));
#endif
    return static_cast<T*>(::operator new(n * sizeof(T)));
  }

  void deallocate(T* block, std::size_t n) noexcept
  {
#ifdef CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
    if (is_mapped(n))
    {
      munmap(block, whole_huge_pages(n * sizeof(T)));
      return;
    }
#endif
    ::operator delete(block);
  }

  template <typename U>
  bool operator==(const Huge_page_allocator<U>&) const noexcept
  {
    return true;
  }
  template <typename U>
  bool operator!=(const Huge_page_allocator<U>&) const noexcept
  {
    return false;
  }

private:
  static bool is_mapped(std::size_t n) { return n * sizeof(T) >= huge_page_size; }
};

// Every array of the package.
template <typename T>
using Array = std::vector<T, Huge_page_allocator<T> >;

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
