// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// For the tests that compare a sequential run with a parallel one: they use
// CGAL::Parallel_tag, run it on at least two threads, and fail when the tests
// were built without TBB rather than compare sequential with sequential.

#ifndef ENTROPY_SIMPLIFICATION_REQUIRE_TBB_H
#define ENTROPY_SIMPLIFICATION_REQUIRE_TBB_H

#include <catch2/catch.hpp>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#endif

namespace test_parallel {

#ifdef CGAL_LINKED_WITH_TBB
using Parallel_tag = CGAL::Parallel_tag;
#else
// CGAL::Parallel_tag does not compile without TBB. A placeholder that is
// never run: require_tbb() fails the test first.
using Parallel_tag = CGAL::Sequential_tag;
#endif

// Fails the current test when it was built without TBB.
inline void require_tbb()
{
#ifndef CGAL_LINKED_WITH_TBB
  FAIL("built without TBB (CGAL_LINKED_WITH_TBB is not defined): this test compares a sequential run with a "
       "CGAL::Parallel_tag run and cannot test the parallel one; link the tests with CGAL::TBB_support");
#endif
}

// Returns f(), run in a TBB arena of at least two threads, even on a
// single-core machine, so that a parallel run really is concurrent.
template <typename F>
auto on_two_threads_or_more(const F& f) -> decltype(f())
{
  require_tbb();
#ifdef CGAL_LINKED_WITH_TBB
  const int threads = (std::max)(2, tbb::info::default_concurrency());
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  tbb::task_arena arena(threads);
  return arena.execute([&] {
    REQUIRE(tbb::this_task_arena::max_concurrency() >= 2);
    return f();
  });
#else
  return f();
#endif
}

} // namespace test_parallel

#endif // ENTROPY_SIMPLIFICATION_REQUIRE_TBB_H
