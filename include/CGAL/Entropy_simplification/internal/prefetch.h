// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hint that data will be read soon.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PREFETCH_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PREFETCH_H

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h>
#endif

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Starts loading the cache line of `address`, so that the misses of reads
// that follow one another overlap; a no-op where the compiler offers no hint.
inline void prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
  _mm_prefetch(static_cast<const char*>(address), _MM_HINT_T0);
#else
  (void)address;
#endif
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PREFETCH_H
