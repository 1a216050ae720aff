// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's loop over indices: its blocks follow the time they take, so
// that a loop of slow calls reports progress often and stops soon when asked,
// and a loop of cheap calls goes in blocks that grow. The selection of the
// count-th smallest value is std::nth_element's. Large arrays touch their
// pages at allocation under Parallel_tag only.

#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace ESI = CGAL::Entropy_simplification::internal;

TEST_CASE("Loops: slow calls report progress often, and a stop ends the loop soon", "[kernels]")
{
  // 6000 calls of at least 0.1 ms: a single block of the former fixed size
  // (32768 indices), which reported once, after every call
  std::vector<char> done(6000, 0);
  const auto slow = [&done](std::size_t i) {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
    done[i] = 1;
  };
  std::vector<std::size_t> reports;
  CHECK(ESI::for_each_index<CGAL::Sequential_tag>(done.size(), slow, [&reports](std::size_t d) {
    reports.push_back(d);
    return true;
  }));
  CHECK(std::count(done.begin(), done.end(), 1) == 6000);
  CHECK(reports.size() >= 3);
  // the first block is small, whatever the calls cost
  CHECK(reports.front() <= 256);
  CHECK(std::is_sorted(reports.begin(), reports.end()));
  CHECK(reports.back() == 6000);

  std::fill(done.begin(), done.end(), 0);
  std::size_t calls = 0;
  CHECK_FALSE(ESI::for_each_index<CGAL::Sequential_tag>(done.size(), slow, [&calls](std::size_t) {
    ++calls;
    return false;
  }));
  CHECK(calls == 1);
  CHECK(std::count(done.begin(), done.end(), 1) < 6000);
}

TEST_CASE("Loops: cheap calls go in growing blocks, every index once", "[kernels]")
{
  std::vector<int> visits(1000000, 0);
  std::vector<std::size_t> reports;
  CHECK(ESI::for_each_index<CGAL::Parallel_if_available_tag>(
    visits.size(), [&visits](std::size_t i) { ++visits[i]; }, [&reports](std::size_t d) {
      reports.push_back(d);
      return true;
    }));
  CHECK(std::all_of(visits.begin(), visits.end(), [](int v) { return v == 1; }));
  // the former fixed blocks of 32768 indices made 31 reports
  CHECK(reports.size() <= 31);
  CHECK(reports.back() == visits.size());
}

namespace {

// The count-th smallest of `values` by std::nth_element, on a copy.
template <typename T>
T nth_by_std(std::vector<T> values, std::size_t count)
{
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(count - 1), values.end());
  return values[count - 1];
}

template <typename T>
void require_nth_smallest_as_std(const std::vector<T>& values)
{
  const std::size_t n = values.size();
  for (std::size_t count : { std::size_t(1), std::size_t(2), n / 10 + 1, n / 2 + 1, n - 1, n })
  {
    INFO("n = " << n << ", count = " << count);
    const T expected = nth_by_std(values, count);
    const auto value = [&values](std::size_t r) { return values[r]; };
    REQUIRE(ESI::nth_smallest<CGAL::Sequential_tag>(n, value, count, std::less<T>()) == expected);
    REQUIRE(ESI::nth_smallest<CGAL::Parallel_if_available_tag>(n, value, count, std::less<T>()) == expected);
  }
}

} // namespace

TEST_CASE("Selection: the count-th smallest is nth_element's, within the sample's bracket or not", "[kernels]")
{
  std::mt19937_64 random(2018);
  // below, at and above the size of the sample (4096), with distinct values
  // and with many ties
  for (std::size_t n : { std::size_t(2), std::size_t(1000), std::size_t(4095), std::size_t(4096), std::size_t(4097),
                         std::size_t(65536), std::size_t(300007) })
    for (std::uint64_t range : { std::uint64_t(0), std::uint64_t(50) })
    {
      std::vector<std::uint64_t> values(n);
      for (std::uint64_t& v : values)
        v = range == 0 ? random() : random() % range;
      require_nth_smallest_as_std(values);
    }
  // a sample that misses: every sampled place holds the least value, so
  // that the bracket holds the least values alone
  std::vector<std::uint64_t> values(300007);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = i % (values.size() / 4096) == 0 ? 0 : 1000 + random() % 1000000;
  require_nth_smallest_as_std(values);
  // sorted and reversed
  std::sort(values.begin(), values.end());
  require_nth_smallest_as_std(values);
  std::reverse(values.begin(), values.end());
  require_nth_smallest_as_std(values);
}

#ifdef __linux__
namespace {

// How many pages of the storage of `array` are resident, as mincore() says.
template <typename T>
std::size_t resident_pages(const ESI::Array<T>& array)
{
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  const auto first = reinterpret_cast<std::uintptr_t>(array.data()) / page * page;
  const auto beyond = reinterpret_cast<std::uintptr_t>(array.data() + array.capacity());
  std::vector<unsigned char> in_core((beyond - first + page - 1) / page);
  REQUIRE(mincore(reinterpret_cast<void*>(first), beyond - first, in_core.data()) == 0);
  return std::size_t(std::count_if(in_core.begin(), in_core.end(), [](unsigned char c) { return (c & 1) != 0; }));
}

} // namespace

TEST_CASE("Arrays: a large array's pages are touched at allocation under Parallel_tag only", "[kernels]")
{
  // 64 MiB: above the largest size glibc takes from its heap, so that the
  // storage is new to the process and no page is resident before a write
  constexpr std::size_t count = std::size_t(8) << 20;
  const std::size_t pages = count * sizeof(double) / std::size_t(sysconf(_SC_PAGESIZE));
  REQUIRE_FALSE(ESI::touches_pages_in_parallel());
  {
    const ESI::First_touch_scope<CGAL::Sequential_tag> sequential;
    ESI::Array<double> untouched;
    untouched.reserve(count);
    // a few pages may be: the allocator's header, or a huge page around it
    CHECK(resident_pages(untouched) < pages / 2);
  }
  {
    const ESI::First_touch_scope<CGAL::Parallel_tag> parallel;
    CHECK(ESI::touches_pages_in_parallel());
    ESI::Array<double> touched;
    touched.reserve(count);
#ifdef CGAL_LINKED_WITH_TBB
    CHECK(resident_pages(touched) >= pages);
#endif
    // the values are the ones written after the touch
    touched.assign(count, 0.5);
    CHECK(std::all_of(touched.begin(), touched.end(), [](double v) { return v == 0.5; }));
    // room reserved to grow in parts is touched part by part, not at once
    ESI::Array<double> in_parts;
    ESI::reserve_untouched(in_parts, count);
    CHECK(resident_pages(in_parts) < pages / 2);
    CHECK(ESI::touches_pages_in_parallel());
    ESI::grow_touched(in_parts, count / 4);
    CHECK(in_parts.size() == count / 4);
    CHECK(std::all_of(in_parts.begin(), in_parts.end(), [](double v) { return v == 0.; }));
    {
      const ESI::First_touch_scope<CGAL::Sequential_tag> nested;
      CHECK_FALSE(ESI::touches_pages_in_parallel());
    }
    CHECK(ESI::touches_pages_in_parallel());
  }
  CHECK_FALSE(ESI::touches_pages_in_parallel());
}
#endif
