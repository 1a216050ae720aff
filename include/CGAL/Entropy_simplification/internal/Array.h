// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's arrays.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H

#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Every array of the package, nearly all of them a value per point. They
// were once mapped in transparent huge pages, to pay one page fault where
// there were 512. On the benchmark's virtual machine, memory that the
// system has not used for a few seconds costs 10 to 17 ms per 2 MiB on its
// first touch, and a huge page is nearly always such memory, while 4 KiB
// pages are mostly recently freed ones: the default mode on 10^7 points
// took 30 to 40 s with huge pages and 26 to 28 s without (runs in turn).
template <typename T>
using Array = std::vector<T>;

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ARRAY_H
