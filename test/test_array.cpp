// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's arrays: blocks below and above the huge-page size hold what
// is written to them, through growth, copies and moves, and the mapped ones
// are aligned on 2 MiB.

#include <CGAL/Entropy_simplification/internal/Array.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <new>
#include <utility>

namespace ESI = CGAL::Entropy_simplification::internal;

namespace {

// i * 2654435761 mod 2^32: distinct values that a stale or shared block
// would not hold by chance.
std::uint32_t value_at(std::size_t i) { return std::uint32_t(i * 2654435761u); }

bool holds_its_values(const ESI::Array<std::uint32_t>& a)
{
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != value_at(i))
      return false;
  return true;
}

ESI::Array<std::uint32_t> filled(std::size_t n)
{
  ESI::Array<std::uint32_t> a(n);
  for (std::size_t i = 0; i < n; ++i)
    a[i] = value_at(i);
  return a;
}

} // namespace

TEST_CASE("Arrays: blocks on either side of the huge-page size", "[array]")
{
  const std::size_t per_huge_page = ESI::huge_page_size / sizeof(std::uint32_t);
  for (std::size_t n : { std::size_t(0), std::size_t(1), std::size_t(1000), per_huge_page - 1, per_huge_page,
                         per_huge_page + 1, 3 * per_huge_page + 12345 })
  {
    CAPTURE(n);
    const ESI::Array<std::uint32_t> a = filled(n);
    CHECK(holds_its_values(a));
#ifdef CGAL_ENTROPY_SIMPLIFICATION_HUGE_PAGES
    if (n >= per_huge_page)
      CHECK(reinterpret_cast<std::uintptr_t>(a.data()) % ESI::huge_page_size == 0);
#endif
    ESI::Array<std::uint32_t> copy = a;
    CHECK(holds_its_values(copy));
    ESI::Array<std::uint32_t> moved = std::move(copy);
    CHECK(holds_its_values(moved));
    moved.resize(n / 2);
    moved.shrink_to_fit();
    CHECK(holds_its_values(moved));
  }
}

TEST_CASE("Arrays: growth across the huge-page size keeps every value", "[array]")
{
  ESI::Array<std::uint32_t> a;
  for (std::size_t i = 0; i < 5 * ESI::huge_page_size / sizeof(std::uint32_t); ++i)
    a.push_back(value_at(i));
  CHECK(holds_its_values(a));
}

TEST_CASE("Arrays: a block whose size overflows is refused before any allocation", "[array]")
{
  ESI::Huge_page_allocator<double> allocator;
  CHECK_THROWS_AS(allocator.allocate((std::numeric_limits<std::size_t>::max)() / sizeof(double)),
                  std::bad_array_new_length);
}
