// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's arrays.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Whether the calling thread's large allocations touch their pages in
// parallel (see First_touch_scope).
inline bool& touches_pages_in_parallel()
{
  static thread_local bool in_parallel = false;
  return in_parallel;
}

// Writes a byte in each page of `bytes` of new storage, in parallel, when the
// calling thread may and the storage is large. Memory a process gets from the
// system costs a page fault per page at its first write: on the benchmark's
// virtual machine about 11 microseconds per 4 KiB page when the system has
// not used it recently: a direct call on 1,000,000 points with 2 threads took
// 2.9 to 3.1 s in a new process and 2.6 to 2.7 s when run again, as one
// thread first wrote most of its memory, copying the points and zeroing the
// arrays that the parallel stages then fill (see the design notes).
inline void touch_pages(void* storage, std::size_t bytes)
{
#ifdef CGAL_LINKED_WITH_TBB
  constexpr std::size_t page = 4096, large = std::size_t(1) << 20;
  if (bytes < large || !touches_pages_in_parallel())
    return;
  volatile char* first = static_cast<char*>(storage);
  // isolated: an allocation inside a parallel loop must not run another of
  // that loop's tasks while it waits, which could reallocate the very array
  tbb::this_task_arena::isolate([first, bytes] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, (bytes + page - 1) / page, 64),
                      [first](const tbb::blocked_range<std::size_t>& pages) {
                        for (std::size_t p = pages.begin(); p != pages.end(); ++p)
                          first[p * page] = 0;
                      });
  });
#else
  (void)storage;
  (void)bytes;
#endif
}

// std::allocator, with the pages of large arrays touched in parallel (see
// touch_pages).
template <typename T>
struct First_touch_allocator
{
  using value_type = T;

  First_touch_allocator() = default;
  template <typename U>
  First_touch_allocator(const First_touch_allocator<U>&) noexcept
  {}

  T* allocate(std::size_t n)
  {
    T* storage = std::allocator<T>().allocate(n);
    touch_pages(storage, n * sizeof(T));
    return storage;
  }
  void deallocate(T* storage, std::size_t n) noexcept { std::allocator<T>().deallocate(storage, n); }

  template <typename U>
  bool operator==(const First_touch_allocator<U>&) const noexcept
  {
    return true;
  }
  template <typename U>
  bool operator!=(const First_touch_allocator<U>&) const noexcept
  {
    return false;
  }
};

// While it lives, the calling thread's large arrays touch their pages in
// parallel under Parallel_tag, and not under Sequential_tag: a public
// function creates one first.
template <typename ConcurrencyTag>
class First_touch_scope
{
public:
  First_touch_scope() { touches_pages_in_parallel() = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value; }
  ~First_touch_scope() { touches_pages_in_parallel() = m_before; }
  First_touch_scope(const First_touch_scope&) = delete;
  First_touch_scope& operator=(const First_touch_scope&) = delete;

private:
  const bool m_before = touches_pages_in_parallel();
};

// Every array of the package, nearly all of them a value per point. They
// were once mapped in transparent huge pages, to pay one page fault where
// there were 512. On the benchmark's virtual machine, memory that the
// system has not used for a few seconds costs 10 to 17 ms per 2 MiB on its
// first touch, and a huge page is nearly always such memory, while 4 KiB
// pages are mostly recently freed ones: the default mode on 10^7 points
// took 30 to 40 s with huge pages and 26 to 28 s without (runs in turn).
template <typename T>
using Array = std::vector<T, First_touch_allocator<T> >;

// Reserves room for `count` elements of `array` without touching its pages,
// for an array that then grows in parts (see grow_touched), so that a stop
// is seen between them and the room is resident only as it fills.
template <typename T>
void reserve_untouched(Array<T>& array, std::size_t count)
{
  const First_touch_scope<CGAL::Sequential_tag> untouched;
  array.reserve(count);
}

// Resizes `array`, reserved by reserve_untouched, to `count` elements, the
// pages of the new ones touched first as touch_pages does.
template <typename T>
void grow_touched(Array<T>& array, std::size_t count)
{
  if (count > array.size() && count <= array.capacity())
    touch_pages(array.data() + array.size(), (count - array.size()) * sizeof(T));
  array.resize(count);
}

// An array that grows by appending, which its final size does not bound
// beforehand: its pages are touched as it fills, as the room a growth adds
// but leaves unused would count in the peak if touched at allocation.
template <typename T>
using Growing_array = std::vector<T>;

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
