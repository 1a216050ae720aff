// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A loop over indices, parallel with CGAL::Parallel_tag, that reports progress
// on the calling thread, and a sort and a selection, parallel with
// CGAL::Parallel_tag.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FOR_EACH_INDEX_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FOR_EACH_INDEX_H

#include <CGAL/Entropy_simplification/internal/Array.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The size of the next block of for_each_index, from the last one's size
// and time: blocks of about 25 to 100 ms, so that a stop asked for through
// the progress callback is seen soon however long one call takes (with
// k = 1000, fixed blocks of 32768 points took seconds), and so that cheap
// calls still go in blocks long enough to spread over the threads.
inline std::size_t next_block_size(std::size_t block, double seconds)
{
  if (seconds < 0.025)
    return (std::min)(block * 2, std::size_t(1) << 20);
  if (seconds > 0.1)
    return (std::max)(std::size_t(double(block) * 0.05 / seconds), std::size_t(1));
  return block;
}

// Calls `f(i)` for every i in [0, n), block after block. After each block,
// `progress(done)` runs on the calling thread, so a user callback is never
// called concurrently; when it returns false the loop stops and this returns
// false. Within a block the calls run in parallel with `CGAL::Parallel_tag`:
// `f` must then only write to data owned by index i. The blocks' sizes
// follow the time they take (see next_block_size), which changes nothing
// but when progress is reported. The first is small, since nothing is known
// of a call's cost yet: with k = 1000, a first block of 4096 neighbour
// searches took 2 s.
template <typename ConcurrencyTag, typename Function, typename Progress>
bool for_each_index(std::size_t n, const Function& f, const Progress& progress)
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL::Parallel_tag is enabled but TBB is unavailable");
#endif
  std::size_t block = 1 << 8;
  for (std::size_t first = 0; first < n;)
  {
    const std::size_t beyond = (std::min)(n, first + block);
    const auto start = std::chrono::steady_clock::now();
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, beyond),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i)
                            f(i);
                        });
    }
    else
#endif
    {
      for (std::size_t i = first; i != beyond; ++i)
        f(i);
    }
    block = next_block_size(block, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    first = beyond;
    if (!progress(beyond))
      return false;
  }
  return true;
}

// A progress of for_each_index over n indices, reported to `progress` as
// the fraction done of a larger task, of which the loop does the share
// [first, first + width).
template <typename Progress>
auto share_of_progress(std::size_t n, double first, double width, const Progress& progress)
{
  return [&progress, n, first, width](std::size_t done) { return progress(first + width * double(done) / double(n)); };
}

// for_each_index over [0, n) a part of `part` indices at a time, calling
// `grow(beyond)` before the part that ends at `beyond`: an array the calls
// fill can grow with them. Zeroed at once, the arrays of a large k (1.2 GB
// at 300,000 points and k = 1000) took seconds in which no stop was seen.
template <typename ConcurrencyTag, typename Grow, typename Function, typename Progress>
bool for_each_index_growing(std::size_t n, std::size_t part, const Grow& grow, const Function& f,
                            const Progress& progress)
{
  for (std::size_t first = 0; first < n; first += part)
  {
    const std::size_t beyond = (std::min)(n, first + part);
    grow(beyond);
    if (!for_each_index<ConcurrencyTag>(
          beyond - first, [&](std::size_t i) { f(first + i); },
          [&](std::size_t done) { return progress(first + done); }))
      return false;
  }
  return true;
}

// Sorts [first, beyond) by `less`, in parallel with CGAL::Parallel_tag. The
// order must be total for the result not to depend on the tag.
template <typename ConcurrencyTag, typename Iterator, typename Less>
void sort_by(Iterator first, Iterator beyond, const Less& less)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    tbb::parallel_sort(first, beyond, less);
  else
#endif
    std::sort(first, beyond, less);
}

// Two values between which the `count`-th smallest of the `n` values
// `value(r)` most likely lies: those four standard deviations of a
// sample's rank (and a few more) below and above it in a regular sample.
template <typename Value, typename Less>
auto sampled_bracket(std::size_t n, const Value& value, std::size_t count, const Less& less)
{
  constexpr std::size_t most_samples = 4096;
  const std::size_t samples = (std::min)(n, most_samples), stride = n / samples;
  std::vector<std::decay_t<decltype(value(std::size_t(0)))> > sample;
  for (std::size_t s = 0; s < samples; ++s)
    sample.push_back(value(s * stride));
  std::sort(sample.begin(), sample.end(), less);
  const std::size_t at = count * samples / n;
  const std::size_t margin = std::size_t(4. * std::sqrt(double(at) * double(samples - at) / double(samples))) + 8;
  return std::make_pair(sample[at > margin ? at - margin : 0], sample[(std::min)(at + margin, samples - 1)]);
}

// The values `value(r)`, r in [0, n), within [low, high] by `less`, in no
// particular order, and in `below` how many lie below `low`; counted and
// listed a chunk at a time, in parallel with CGAL::Parallel_tag.
template <typename ConcurrencyTag, typename Value, typename T, typename Less>
Array<T> values_within(std::size_t n, const Value& value, const T& low, const T& high, const Less& less,
                             std::size_t& below)
{
  constexpr std::size_t chunk = std::size_t(1) << 14;
  const std::size_t chunks = (n + chunk - 1) / chunk;
  std::vector<std::size_t> below_in(chunks, 0);
  std::vector<std::vector<T> > within_in(chunks);
  for_each_index<ConcurrencyTag>(
    chunks,
    [&](std::size_t c) {
      std::size_t count = 0;
      for (std::size_t r = c * chunk; r < (std::min)(n, (c + 1) * chunk); ++r)
      {
        const T v = value(r);
        if (less(v, low))
          ++count;
        else if (!less(high, v))
          within_in[c].push_back(v);
      }
      below_in[c] = count;
    },
    [](std::size_t) { return true; });
  below = 0;
  Array<T> within;
  for (std::size_t c = 0; c < chunks; ++c)
  {
    below += below_in[c];
    within.insert(within.end(), within_in[c].begin(), within_in[c].end());
    std::vector<T>().swap(within_in[c]);
  }
  return within;
}

// The `count`-th smallest (from 1) of the `n` values `value(r)`, r in
// [0, n), by `less`, which must be a total order for the result not to
// depend on the tag. Its passes over all values run in parallel with
// CGAL::Parallel_tag, and it holds only a few hundredths of them: those
// within a sample's bracket (see sampled_bracket), unless it missed, when
// it holds all of them.
template <typename ConcurrencyTag, typename Value, typename Less>
auto nth_smallest(std::size_t n, const Value& value, std::size_t count, const Less& less)
{
  CGAL_precondition(count >= 1 && count <= n);
  using T = std::decay_t<decltype(value(std::size_t(0)))>;
  const std::pair<T, T> bracket = sampled_bracket(n, value, count, less);
  std::size_t below = 0;
  Array<T> within = values_within<ConcurrencyTag>(n, value, bracket.first, bracket.second, less, below);
  if (count <= below || count > below + within.size())
  {
    within.resize(n);
    for_each_index<ConcurrencyTag>(n, [&](std::size_t r) { within[r] = value(r); }, [](std::size_t) { return true; });
    below = 0;
  }
  std::nth_element(within.begin(), within.begin() + std::ptrdiff_t(count - below - 1), within.end(), less);
  return within[count - below - 1];
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FOR_EACH_INDEX_H
