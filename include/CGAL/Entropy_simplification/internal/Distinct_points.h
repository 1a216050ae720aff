// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Coincident points collapsed to one representative before either mode runs,
// or cut to the few that a measure of them all reads.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The points of a range with every group of coincident points (equal as
// doubles, so -0.0 equals 0.0) reduced to its first in input order.
//
// Both modes would otherwise suffer copies: c copies of a point are each
// other's neighbours at distance 0, so the default mode's neighbour lists and
// the paper mode's exact updates grow as c^2, and the copies' normals and
// entropies are undefined. A copy adds nothing to the geometry, so copies are
// removed before any distinct point and return, in input order, only once
// every distinct point is kept.
struct Distinct_points
{
  Array<Working_point> points;  // the representatives, in input order
  Array<Index> input_position;  // of each representative
  Array<Index> copies;          // input positions of the other points, ascending
  Array<Index> representative;  // for each copy, the index of its representative in `points`

  std::size_t size() const { return input_position.size(); }
};

// A 64-bit mix of a point's coordinates: equal points (as doubles, so -0.0
// and 0.0 alike) have equal keys, and distinct points rarely do.
inline std::uint64_t coordinate_key(const Working_point& p)
{
  auto mixed = [](std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    return h ^ (h >> 33);
  };
  std::uint64_t key = 0;
  for (int d = 0; d < 3; ++d)
  {
    const double c = p.cartesian(d) == 0. ? 0. : p.cartesian(d);
    std::uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    key = mixed(key ^ bits);
  }
  return key;
}

// A point's key (see coordinate_key) and its input position.
struct Keyed_position
{
  std::uint64_t key;
  Index position;
};

// Orders `keyed` stably by `bucket_of(key)`, one of `buckets` (a power of
// two), and returns where each bucket starts, then the end. First by the
// bucket's leading bits, into at most 256 parts, a chunk of `keyed` at a
// time, then each part by the rest: parts and chunks are done in parallel
// with CGAL::Parallel_tag, and each part's writes stay within its own range,
// which a cache holds, where writes across the whole array missed it nearly
// every time: with two threads, this function and the buckets' sorts took
// 0.42 s on 10,000,000 lion samples, against 0.60 s with one pass over the
// whole array.
template <typename ConcurrencyTag, typename BucketOf>
Array<Index> order_by_bucket(Array<Keyed_position>& keyed, std::size_t buckets, const BucketOf& bucket_of)
{
  const std::size_t n = keyed.size(), parts = (std::min)(buckets, std::size_t(256)), per_part = buckets / parts;
  constexpr std::size_t chunk = std::size_t(1) << 16;
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const auto part_of = [&](const Keyed_position& k) { return bucket_of(k.key) / per_part; };
  // each chunk's count of each part, then where its entries of that part go
  Array<Index> offset(chunks * parts, 0);
  for_each_index<ConcurrencyTag>(
    chunks,
    [&](std::size_t c) {
      for (std::size_t r = c * chunk; r < (std::min)(n, (c + 1) * chunk); ++r)
        ++offset[c * parts + part_of(keyed[r])];
    },
    [](std::size_t) { return true; });
  Array<Index> part_start(parts + 1);
  Index sum = 0;
  for (std::size_t p = 0; p < parts; ++p)
  {
    part_start[p] = sum;
    for (std::size_t c = 0; c < chunks; ++c)
    {
      const Index count = offset[c * parts + p];
      offset[c * parts + p] = sum;
      sum += count;
    }
  }
  part_start[parts] = sum;
  Array<Keyed_position> by_part(n);
  for_each_index<ConcurrencyTag>(
    chunks,
    [&](std::size_t c) {
      for (std::size_t r = c * chunk; r < (std::min)(n, (c + 1) * chunk); ++r)
        by_part[offset[c * parts + part_of(keyed[r])]++] = keyed[r];
    },
    [](std::size_t) { return true; });
  Array<Index>().swap(offset);

  Array<Index> bucket_start(buckets + 1);
  bucket_start[buckets] = Index(n);
  for_each_index<ConcurrencyTag>(
    parts,
    [&](std::size_t p) {
      Index* const start = bucket_start.data() + p * per_part;
      std::fill_n(start, per_part, Index(0));
      for (Index r = part_start[p]; r < part_start[p + 1]; ++r)
        ++start[bucket_of(by_part[r].key) % per_part];
      Index within = part_start[p];
      for (std::size_t b = 0; b < per_part; ++b)
      {
        const Index count = start[b];
        start[b] = within;
        within += count;
      }
      Array<Index> next(start, start + per_part);
      for (Index r = part_start[p]; r < part_start[p + 1]; ++r)
        keyed[next[bucket_of(by_part[r].key) % per_part]++] = by_part[r];
    },
    [](std::size_t) { return true; });
  return bucket_start;
}

// For each point, the input position of the first point equal to it, its
// own when none comes before it. The points go into buckets by their keys'
// leading bits, about four to a bucket, in input order (see
// order_by_bucket); each bucket is sorted by key, then coordinates, then
// position, so that equal points follow each other, the first in input
// order first. Coordinates are read only where keys are equal, and a bucket
// sorts in O(m log m) even where keys collide, as a file made to collide
// would make them. A sort of the whole cloud by coordinates took twice as
// long.
template <typename ConcurrencyTag, typename Key = std::uint64_t (*)(const Working_point&)>
Array<Index> first_equal_points(const Array<Working_point>& points, const Key& key_of = coordinate_key)
{
  const std::size_t n = points.size();
  int bits = 0;
  while (bits < 24 && (std::size_t(4) << bits) < n)
    ++bits;
  auto bucket_of = [bits](std::uint64_t key) { return bits == 0 ? std::size_t(0) : std::size_t(key >> (64 - bits)); };

  Array<Keyed_position> by_bucket(n);
  for_each_index<ConcurrencyTag>(
    n, [&](std::size_t i) { by_bucket[i] = Keyed_position{ key_of(points[i]), Index(i) }; },
    [](std::size_t) { return true; });
  const Array<Index> bucket_start = order_by_bucket<ConcurrencyTag>(by_bucket, std::size_t(1) << bits, bucket_of);

  auto before = [&points](const Keyed_position& a, const Keyed_position& b) {
    if (a.key != b.key)
      return a.key < b.key;
    const Working_point &p = points[a.position], &q = points[b.position];
    return std::make_tuple(p.x(), p.y(), p.z(), a.position) < std::make_tuple(q.x(), q.y(), q.z(), b.position);
  };
  Array<Index> first(n);
  for_each_index<ConcurrencyTag>(n, [&](std::size_t i) { first[i] = Index(i); }, [](std::size_t) { return true; });
  for_each_index<ConcurrencyTag>(
    bucket_start.size() - 1,
    [&](std::size_t b) {
      if (bucket_start[b + 1] - bucket_start[b] < 2)
        return;
      Keyed_position* const begin = by_bucket.data() + bucket_start[b];
      Keyed_position* const end = by_bucket.data() + bucket_start[b + 1];
      std::sort(begin, end, before);
      for (Keyed_position* k = begin + 1; k < end; ++k)
        if (k->key == k[-1].key && points[k->position] == points[k[-1].position])
          first[k->position] = first[k[-1].position];
    },
    [](std::size_t) { return true; });
  return first;
}

// The representatives move to the front of `points`, in input order: each
// goes to a slot at or before its own, so the compaction is in place. The
// slot of each representative is where it goes.
template <typename ConcurrencyTag>
Distinct_points collapse_duplicates(Array<Working_point> points)
{
  const Array<Index> first = first_equal_points<ConcurrencyTag>(points);
  Distinct_points result;
  if (std::equal(first.begin(), first.end(), boost::counting_iterator<Index>(0)))
  {
    // no copies, as in most scans: every point represents itself
    result.input_position = all_indices(points.size());
    result.points = std::move(points);
    return result;
  }
  Array<Index> slot(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (first[i] == i)
    {
      slot[i] = Index(result.input_position.size());
      points[slot[i]] = points[i];
      result.input_position.push_back(Index(i));
    }
    else
    {
      result.copies.push_back(Index(i));
      result.representative.push_back(slot[first[i]]);
    }
  }
  points.resize(result.input_position.size());
  result.points = std::move(points);
  return result;
}

// The points of a range with each group of coincident points cut to its
// first `count` in input order, and for each point of the range the index
// among those that remain of itself or, where it was cut, of its group's
// first. A computation that reads at most `count - 1` neighbours of a point,
// in the package's neighbour order (by distance, then input position), finds
// the same ones among the remaining points, as later copies come after
// `count` at the same distance, so a copy that was cut takes the result of
// its group's first. Without the cut, c copies of a point would each visit
// the others in every search: c^2 visits.
struct Limited_copies
{
  Array<Working_point> points;
  Array<Index> stand_in;
};

template <typename ConcurrencyTag>
Limited_copies limit_copies(Array<Working_point> points, std::size_t count)
{
  const Array<Index> first = first_equal_points<ConcurrencyTag>(points);
  Limited_copies result;
  result.stand_in.resize(points.size());
  Array<Index> copies_so_far(points.size(), 0); // by each group's first
  std::size_t remaining = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Index group = first[i];
    if (copies_so_far[group] < count)
    {
      ++copies_so_far[group];
      result.stand_in[i] = Index(remaining);
      points[remaining++] = points[i];
    }
    else
      result.stand_in[i] = result.stand_in[group];
  }
  points.resize(remaining);
  result.points = std::move(points);
  return result;
}

// The input positions of the `distinct_count` representatives, ascending:
// those of no copy, `copies` being ascending.
inline Array<Index> positions_of_no_copy(const Array<Index>& copies, std::size_t distinct_count)
{
  Array<Index> positions;
  positions.reserve(distinct_count);
  std::size_t c = 0;
  for (Index p = 0; positions.size() < distinct_count; ++p)
  {
    if (c < copies.size() && copies[c] == p)
      ++c;
    else
      positions.push_back(p);
  }
  return positions;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H
