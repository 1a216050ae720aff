// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Coincident points collapsed to one representative before either mode runs.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

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

// For each point, the input position of the first point equal to it, its
// own when none comes before it. The points go into buckets by their keys'
// leading bits, about four to a bucket, in input order; each bucket is
// sorted by key, then coordinates, then position, so that equal points
// follow each other, the first in input order first. Coordinates are read
// only where keys are equal, and a bucket sorts in O(m log m) even where
// keys collide, as a file made to collide would make them. A sort of the
// whole cloud by coordinates took twice as long.
template <typename ConcurrencyTag, typename Key = std::uint64_t (*)(const Working_point&)>
Array<Index> first_equal_points(const Array<Working_point>& points, const Key& key_of = coordinate_key)
{
  struct Keyed_position
  {
    std::uint64_t key;
    Index position;
  };
  const std::size_t n = points.size();
  int bits = 0;
  while (bits < 24 && (std::size_t(4) << bits) < n)
    ++bits;
  auto bucket_of = [bits](std::uint64_t key) { return bits == 0 ? std::size_t(0) : std::size_t(key >> (64 - bits)); };

  Array<Keyed_position> keyed(n);
  for_each_index<ConcurrencyTag>(
    n, [&](std::size_t i) { keyed[i] = Keyed_position{ key_of(points[i]), Index(i) }; },
    [](std::size_t) { return true; });
  // 32-bit offsets, like the positions they count
  Array<Index> bucket_start((std::size_t(1) << bits) + 1, 0);
  for (const Keyed_position& k : keyed)
    ++bucket_start[bucket_of(k.key) + 1];
  for (std::size_t b = 1; b < bucket_start.size(); ++b)
    bucket_start[b] += bucket_start[b - 1];
  Array<Keyed_position> by_bucket(n);
  Array<Index> next(bucket_start.begin(), bucket_start.end() - 1);
  for (const Keyed_position& k : keyed)
    by_bucket[next[bucket_of(k.key)]++] = k;
  Array<Keyed_position>().swap(keyed);
  Array<Index>().swap(next);

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
