// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's loop over indices: its blocks follow the time they take, so
// that a loop of slow calls reports progress often and stops soon when asked,
// and a loop of cheap calls goes in blocks that grow.

#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

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
