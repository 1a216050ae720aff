// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --threads: at most N worker threads for the whole run, through TBB's
// global_control. Without TBB the program runs on one thread whatever N.

#ifndef ENTROPY_SIMPLIFY_THREAD_LIMIT_H
#define ENTROPY_SIMPLIFY_THREAD_LIMIT_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#endif

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>

namespace entropy_simplify {

// Holds the limit while it lives; no limit when `threads` is empty. A limit
// above the threads the machine runs at once is that number: TBB reserves
// memory for every thread a limit allows (1.3 GB for 10^7).
class Thread_limit
{
public:
  explicit Thread_limit(std::optional<std::size_t> threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if (threads)
      m_control = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism,
        (std::min)(*threads, std::size_t(tbb::info::default_concurrency())));
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> m_control;
#endif
};

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_THREAD_LIMIT_H
