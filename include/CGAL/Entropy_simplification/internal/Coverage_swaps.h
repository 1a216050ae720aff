// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coverage swaps that end the default mode's relocation: the input point
// farthest from the present points is swapped in for a most crowded present
// point, a few times, so that the gaps the elimination left behind close.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Nearest_present_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Three swaps per hundred kept points, rounded up.
inline std::size_t three_per_hundred(std::size_t kept) { return (3 * kept + 99) / 100; }

// The swaps a direct call keeping `kept` of `n` points makes: three per
// hundred kept points when it keeps at most a quarter of them, one per
// hundred otherwise, rounded up. The widest gaps set the Hausdorff
// distance, the narrower ones weigh on the mean distance; each swap closes
// one, and takes a point from the most crowded (see crowding). Three per
// hundred everywhere against one (benchmark run at 4ddaf34, see the
// design notes): the mean-distance target of issue 12 met in two more cells
// (lion at 20%, anchor at 10%), fandisk's edge shares 2.233 / 2.196 / 1.584
// instead of 2.264 / 2.232 / 1.606 at 10 / 20 / 50%, the last below its
// target of 1.6.
inline std::size_t coverage_swap_count(std::size_t kept, std::size_t n)
{
  return std::uint64_t(4) * kept <= n ? three_per_hundred(kept) : (kept + 99) / 100;
}

// The swaps at a ranking's level boundary keeping `kept` points: three per
// hundred at every boundary, including those above a quarter, where the
// direct calls make one per hundred. Beyond one per hundred, the prefixes
// fell behind the direct calls until the boundaries were swapped too; with
// one per hundred at the 50% boundary, every boundary below changed, and
// `b9_training`'s prefix at 5% had 1.0555 times the direct call's mean
// distance and 1.066 times its point-to-plane error, above the test's 1.055
// and 1.06 (see swap_among_neighbors).
inline std::size_t boundary_swap_count(std::size_t kept) { return three_per_hundred(kept); }

// How crowded a present point is, the smaller the more: the squared
// distance to its nearest other present point over the square of its
// scale, the factor of its interaction radius. The elimination made the
// features dense on purpose; measured against the spacing it asked for, a
// point on a feature is no more crowded than one on a flat region (the
// edge share falls by 0.6% rather than 3.3% at ten swaps per thousand).
inline double crowding(double squared_distance, double scale) { return squared_distance / (scale * scale); }

// The farthest points the swaps' heap holds at first (see Nearest_present):
// a few per swap, as each swap takes one and outdates those whose present
// point it moves; a refill, when they run out, costs a pass over the points.
inline std::size_t heap_size(std::size_t swaps) { return 4 * swaps + 64; }

// The nearest present point of a point that has none, at an infinite distance.
inline Neighbor no_neighbor() { return Neighbor{ std::numeric_limits<double>::infinity(), none_index, none_index }; }

// The members of each present point's cell, `site` holding each point's
// present point, as lists linked through the points.
class Cell_lists
{
public:
  explicit Cell_lists(const Array<Index>& site) : m_first_member(site.size(), none_index), m_next_member(site.size())
  {
    for (Index p = 0; p < Index(site.size()); ++p)
      if (site[p] != none_index)
        link(p, site[p]);
  }

  // `p` leaves the cell of `from` for that of `to`, either none.
  void move(Index p, Index from, Index to)
  {
    if (from != none_index)
    {
      Index* at = &m_first_member[from];
      while (*at != p)
        at = &m_next_member[*at];
      *at = m_next_member[p];
    }
    if (to != none_index)
      link(p, to);
  }

  Array<Index> members(Index site) const
  {
    Array<Index> result;
    for (Index p = m_first_member[site]; p != none_index; p = m_next_member[p])
      result.push_back(p);
    return result;
  }

private:
  void link(Index p, Index site)
  {
    m_next_member[p] = m_first_member[site];
    m_first_member[site] = p;
  }

  Array<Index> m_first_member, m_next_member;
};

// The searches of a direct call's swaps, where every point takes part: the
// present points, in a tree that holds them and the points likely to be
// made present, those not present left out. A tree of every point would
// hold about nine absent points to a present one in a direct call to 10%,
// and its searches would visit that many more leaves. The points made
// present are the farthest from the present points, which the heap of
// Nearest_present holds: the tree takes each of its fillings (see
// may_become_present). A point made present that it does not hold, one
// whose present point left after the filling, is listed apart and read by
// every search, until the list is long enough that building the tree again
// with it costs less (on 1,000,000 lion samples kept to 10%, 76 of 3,000
// swaps made present such a point). The tree finds the cells near a point,
// not their members, which are listed. `site` holds each point's present
// point at the start.
template <typename ConcurrencyTag>
class Tree_search
{
public:
  Tree_search(const Indexed_points& points, const Array<char>& present, const Array<Index>& site)
    : m_points(points), m_present(present), m_held_flag(points.size(), 0), m_cells(site)
  {
    for (Index i = 0; i < Index(points.size()); ++i)
      if (present[i])
      {
        m_held_flag[i] = 1;
        m_held.push_back(i);
      }
  }

  // The points taking part: every point.
  std::size_t taking_part_count() const { return m_points.size(); }
  Index taking_part(std::size_t r) const { return Index(r); }

  // The tree holds the points of `far` (Neighbor entries) from then on.
  template <typename Range>
  void may_become_present(const Range& far)
  {
    Array<Index> added;
    for (const Neighbor& f : far)
      if (!m_held_flag[f.id])
        added.push_back(f.id);
    if (!added.empty() || !m_tree)
      build_tree(std::move(added));
  }

  // The present point nearest `q` other than `q` and `excluded`, at an
  // infinite distance when there is none.
  Neighbor nearest_but(Index q, Index excluded) const
  {
    thread_local Array<Neighbor> best;
    nearest_present(q, 2, best);
    for (const Neighbor& b : best)
      if (b.id != excluded && b.id != q)
        return b;
    return no_neighbor();
  }

  // The points that may be nearer `x` than their present points, before `x`
  // is present, `x` being the point farthest from the present points, at
  // `squared_distance` from its own: none is farther from its own, so they
  // lie in the cells of the present points within twice that distance.
  Array<Index> may_move_to(Index x, double squared_distance) const
  {
    Array<Index> result;
    for (Index s : present_within(x, 4. * squared_distance * (1. + 1e-9)))
      for (Index p : m_cells.members(s))
        result.push_back(p);
    return result;
  }

  // The members of the cell of `y`.
  Array<Index> members(Index y, const Array<Index>&) const { return m_cells.members(y); }

  void made_present(Index x)
  {
    if (m_held_flag[x])
      return m_tree->restore(x);
    m_apart.push_back(x);
    if (m_apart.size() * m_apart.size() > m_held.size())
      build_tree(Array<Index>());
  }
  void made_absent(Index y)
  {
    if (m_held_flag[y])
      m_tree->remove(y);
    else
      m_apart.erase(std::find(m_apart.begin(), m_apart.end(), y));
  }
  // `p`'s present point was `from` and is `to`.
  void moved(Index p, Index from, Index to) { m_cells.move(p, from, to); }

private:
  // The tree of the points it held, those listed apart and `added`, those
  // not present left out.
  void build_tree(Array<Index> added)
  {
    added.insert(added.end(), m_apart.begin(), m_apart.end());
    m_apart.clear();
    std::sort(added.begin(), added.end());
    for (Index i : added)
      m_held_flag[i] = 1;
    const std::ptrdiff_t held = std::ptrdiff_t(m_held.size());
    m_held.insert(m_held.end(), added.begin(), added.end());
    std::inplace_merge(m_held.begin(), m_held.begin() + held, m_held.end());
    m_tree.emplace(m_points, m_held.begin(), m_held.end(), ConcurrencyTag());
    for (Index i : m_held)
      if (!m_present[i])
        m_tree->remove(i);
  }

  // The first `count` present points of `q`'s neighbour order other than
  // `q` (all of them when fewer), to `near`: the tree's, with those listed
  // apart.
  void nearest_present(Index q, std::size_t count, Array<Neighbor>& near) const
  {
    near.resize(count);
    Point_tree::Best_list best{ count, near.data(), m_tree->nearest(q, count, near.data()) };
    for (Index a : m_apart)
      if (a != q)
        best.offer(neighbor_of(m_points, q, a));
    near.resize(best.size);
  }

  // The present points within `squared_reach` of `q`, other than `q`.
  Array<Index> present_within(Index q, double squared_reach) const
  {
    Array<Neighbor> near;
    for (std::size_t count = 16;; count *= 4)
    {
      nearest_present(q, count, near);
      if (near.size() < count || near.back().squared_distance > squared_reach)
        break;
    }
    Array<Index> result;
    for (const Neighbor& s : near)
      if (s.squared_distance <= squared_reach)
        result.push_back(s.id);
    return result;
  }

  const Indexed_points& m_points;
  const Array<char>& m_present;
  Array<Index> m_held;      // the points the tree holds, present or not, in index order
  Array<char> m_held_flag;  // whether the tree holds each point
  Array<Index> m_apart;     // the present points it does not hold
  std::optional<Point_tree> m_tree;
  Cell_lists m_cells;
};

// The searches of a ranking's swaps at a level boundary, where the points of
// the level above take part: each one's present points are searched among
// its neighbours in the stage that ended there (the points within its reach,
// lists in CSR form, which hold the level above alone and are symmetric).
// The elimination built the lists; the swaps then build no tree, which at
// every boundary cost the whole order 1.6 to 1.7 times a direct call (see
// the design notes). A point with no present neighbour is at an infinite distance.
// Each point's present point is one of its neighbours, as it is searched
// there; the lists being symmetric, a cell's members are then among its
// present point's neighbours, and need no lists of their own.
class List_search
{
public:
  List_search(const Indexed_points& points, const Array<char>& present, const Array<Index>& level,
              const Array<std::size_t>& first, const Array<Index>& neighbors)
    : m_points(points), m_present(present), m_level(level), m_first(first), m_neighbors(neighbors)
  {}

  // The points taking part: those of the level.
  std::size_t taking_part_count() const { return m_level.size(); }
  Index taking_part(std::size_t r) const { return m_level[r]; }

  Neighbor nearest_but(Index q, Index excluded) const
  {
    Neighbor best = no_neighbor();
    for (std::size_t e = m_first[q]; e < m_first[q + 1]; ++e)
    {
      const Index j = m_neighbors[e];
      if (j != excluded && m_present[j])
        best = (std::min)(best, neighbor_of(m_points, q, j));
    }
    return best;
  }

  // `x`'s neighbours, the only points whose nearest present point it can be.
  Array<Index> may_move_to(Index x, double) const
  {
    return Array<Index>(m_neighbors.begin() + std::ptrdiff_t(m_first[x]),
                        m_neighbors.begin() + std::ptrdiff_t(m_first[x + 1]));
  }

  // The members of the cell of the present point `y`, `site` holding each
  // point's present point: `y` itself, and its neighbours whose present
  // point it is.
  Array<Index> members(Index y, const Array<Index>& site) const
  {
    Array<Index> result{ y };
    for (std::size_t e = m_first[y]; e < m_first[y + 1]; ++e)
      if (site[m_neighbors[e]] == y)
        result.push_back(m_neighbors[e]);
    return result;
  }

  template <typename Range>
  void may_become_present(const Range&)
  {}
  void made_present(Index) {}
  void made_absent(Index) {}
  void moved(Index, Index, Index) {}

private:
  const Indexed_points& m_points;
  const Array<char>& m_present;
  const Array<Index>& m_level;
  const Array<std::size_t>& m_first;
  const Array<Index>& m_neighbors;
};

// Each taking part point's nearest present point (ties by input position;
// found by a `Search`, see Tree_search and List_search, which also gives
// each cell's members), and the points not present farthest from theirs,
// kept up to date as points are made present or not. The farthest points
// are a heap of the points beyond a threshold and of every change since it
// was set, the outdated entries skipped when they come to the top; when
// none beyond the threshold is left, it is set again lower.
template <typename Search, typename ConcurrencyTag>
class Nearest_present
{
  // the heap's order: farthest on top, then the lowest input position
  static bool below(const Neighbor& a, const Neighbor& b)
  {
    return a.squared_distance < b.squared_distance ||
           (a.squared_distance == b.squared_distance && a.input_position > b.input_position);
  }

public:
  // `site[i]`: the present point nearest `i`, `i` itself when present, none
  // when `i` takes no part or has no present point.
  Nearest_present(const Indexed_points& points, Array<char>& present, Search search, Array<Index> site,
                  std::size_t heap_size)
    : m_points(points), m_present(present), m_search(std::move(search)), m_site(std::move(site)),
      m_heap_size(heap_size)
  {
    fill_heap();
  }

  bool is_present(Index i) const { return m_present[i] != 0; }

  Neighbor nearest(Index i) const { return neighbor(i, m_site[i]); }
  // Each point's nearest present point, as the constructor takes them, the structure then spent.
  Array<Index> release_sites() { return std::move(m_site); }
  Neighbor nearest_but(Index q, Index excluded) const { return m_search.nearest_but(q, excluded); }

  // The point farthest from the present points, or nothing when every point is present.
  std::optional<Index> farthest()
  {
    for (;;)
    {
      while (!m_far.empty() && (m_present[m_far.front().id] ||
                                m_far.front().squared_distance != nearest(m_far.front().id).squared_distance))
      {
        std::pop_heap(m_far.begin(), m_far.end(), below);
        m_far.pop_back();
      }
      if (!m_far.empty() && m_far.front().squared_distance >= m_threshold)
        return m_far.front().id;
      if (m_threshold == 0.)
        return m_far.empty() ? std::nullopt : std::optional<Index>(m_far.front().id);
      fill_heap();
    }
  }

  // The greatest squared distance from a point to the present points.
  double greatest_squared_distance()
  {
    const std::optional<Index> f = farthest();
    return f ? nearest(*f).squared_distance : 0.;
  }

  // Makes the farthest point `x` present: it takes into its cell the
  // points not present nearer it than to their present points. A present
  // point stays in its own cell even when `x` lies at a distance of 0 from
  // it (two distinct points whose squared distance underflows) with a lower
  // input position, so that each present point is its own site, as the
  // levels of detail that start from the sites require.
  void make_present(Index x)
  {
    const Array<Index> near = m_search.may_move_to(x, nearest(x).squared_distance);
    m_present[x] = 1;
    m_search.made_present(x);
    move(x, x);
    for (Index p : near)
      if (!m_present[p] && neighbor(p, x) < nearest(p))
        move(p, x);
  }

  // The members of `y`'s cell with their nearest present points other than
  // `y`: where they go once `y` is no longer present.
  Array<std::pair<Index, Neighbor> > cell_without(Index y) const
  {
    Array<std::pair<Index, Neighbor> > moves;
    for (Index p : m_search.members(y, m_site))
      moves.emplace_back(p, m_search.nearest_but(p, y));
    return moves;
  }

  // Makes `y` no longer present, the members of its cell going as
  // `moves` (cell_without(y)) says.
  void make_absent(Index y, const Array<std::pair<Index, Neighbor> >& moves)
  {
    m_present[y] = 0;
    m_search.made_absent(y);
    for (const auto& [p, site] : moves)
      move(p, site.id);
  }

private:
  Neighbor neighbor(Index q, Index site) const
  {
    if (site == none_index)
      return no_neighbor();
    return neighbor_of(m_points, q, site);
  }

  // The heap holds again every point not present at least as far as the
  // `m_heap_size` farthest (all of them when as few), the threshold. The
  // passes over the points run in parallel with CGAL::Parallel_tag, the
  // entries listed in index order.
  void fill_heap()
  {
    const std::size_t count = m_search.taking_part_count();
    // a present point's entry comes before every other
    const auto entry = [this](std::size_t r) {
      const Index i = m_search.taking_part(r);
      return m_present[i] ? Neighbor{ -1., 0, i } : far_entry(i);
    };
    const auto nearer = [](const Neighbor& a, const Neighbor& b) { return a.squared_distance < b.squared_distance; };
    std::size_t absent = 0;
    for (std::size_t r = 0; r < count; ++r)
      absent += std::size_t(!m_present[m_search.taking_part(r)]);
    m_threshold = absent > m_heap_size
                    ? nth_smallest<ConcurrencyTag>(count, entry, count - m_heap_size + 1, nearer).squared_distance
                    : 0.;
    std::size_t nearer_count = 0;
    m_far = values_within<ConcurrencyTag>(count, entry, Neighbor{ m_threshold, 0, 0 }, no_neighbor(), nearer,
                                          nearer_count);
    std::make_heap(m_far.begin(), m_far.end(), below);
    m_search.may_become_present(m_far);
    m_heap_size *= 2;
  }

  // The heap's entry of `p`: its squared distance to its nearest present
  // point, its own input position, itself.
  Neighbor far_entry(Index p) const
  {
    return Neighbor{ nearest(p).squared_distance, m_points.input_position[p], p };
  }

  // `p` joins the cell of `site`, its new nearest present point, or none.
  void move(Index p, Index site)
  {
    m_search.moved(p, m_site[p], site);
    m_site[p] = site;
    if (!m_present[p])
    {
      m_far.push_back(far_entry(p));
      std::push_heap(m_far.begin(), m_far.end(), below);
    }
  }

  const Indexed_points& m_points;
  Array<char>& m_present;
  Search m_search;
  Array<Index> m_site; // each point's nearest present point
  std::size_t m_heap_size;
  double m_threshold = 0.;
  Array<Neighbor> m_far; // (squared distance, input position, point), as the heap's entries
};

// The entry of present point `s` in a Crowding_order, `squared_distance`
// from its nearest other present point: its crowding in place of the
// squared distance.
inline Neighbor crowding_entry(const Indexed_points& points, const Array<double>& scale, Index s,
                               double squared_distance)
{
  return Neighbor{ crowding(squared_distance, scale[s]), points.input_position[s], s };
}

// The present points in the order of their crowding at the start (see
// crowding), most crowded first, ties by input position, taken one at a
// time: a heap, as the swaps take few of them.
class Crowding_order
{
public:
  // `crowded`: the entries of the present points (see crowding_entry).
  explicit Crowding_order(Array<Neighbor> crowded) : m_heap(std::move(crowded))
  {
    std::make_heap(m_heap.begin(), m_heap.end(), after);
  }

  // The next point with its crowding at the start, or nothing when all were taken.
  std::optional<Neighbor> next()
  {
    if (m_heap.empty())
      return std::nullopt;
    std::pop_heap(m_heap.begin(), m_heap.end(), after);
    const Neighbor y = m_heap.back();
    m_heap.pop_back();
    return y;
  }

private:
  static bool after(const Neighbor& a, const Neighbor& b) { return b < a; }

  Array<Neighbor> m_heap;
};

// The present point that leaves once the farthest point is present: the
// next of `crowded` still present and as crowded as it was, whose cell's
// members would all be nearer their new nearest present points than the
// farthest point then is. The points passed, and the one returned, are
// passed for good. Nothing when none is left.
template <typename Search, typename ConcurrencyTag>
std::optional<Index> next_to_leave(Nearest_present<Search, ConcurrencyTag>& nearest, Crowding_order& crowded,
                                   const Array<double>& scale)
{
  const double greatest = nearest.greatest_squared_distance();
  while (const std::optional<Neighbor> next = crowded.next())
  {
    const Neighbor& y = *next;
    if (!nearest.is_present(y.id) ||
        crowding(nearest.nearest_but(y.id, y.id).squared_distance, scale[y.id]) > y.squared_distance)
      continue;
    const Array<std::pair<Index, Neighbor> > moves = nearest.cell_without(y.id);
    if (std::all_of(moves.begin(), moves.end(), [&](const std::pair<Index, Neighbor>& m) {
          return m.second.squared_distance < greatest;
        }))
    {
      nearest.make_absent(y.id, moves);
      return y.id;
    }
  }
  return std::nullopt;
}

// Up to `swaps` times, the point farthest from the present points becomes
// present and a crowded present point leaves (see next_to_leave; `scale`,
// each point's, says how crowded), so that the swaps never raise the
// greatest distance from a point to the present points. They stop early when
// every point is present, or no present point can leave.
template <typename Search, typename ConcurrencyTag>
void swap_in_turn(Nearest_present<Search, ConcurrencyTag>& nearest, Crowding_order& crowded, const Array<double>& scale,
                  std::size_t swaps)
{
  for (std::size_t swap = 0; swap < swaps; ++swap)
  {
    const std::optional<Index> x = nearest.farthest();
    if (!x)
      return;
    nearest.make_present(*x);
    if (!next_to_leave(nearest, crowded, scale))
    {
      nearest.make_absent(*x, nearest.cell_without(*x));
      return;
    }
  }
}

// The coverage swaps of a direct call (see swap_in_turn), among all the
// points, each point's nearest present point searched first from `hint`
// and `offsets` (see nearest_present_points). Returns each point's nearest
// present point after the swaps (ties by input position): itself when
// present, none when no point is. The levels of detail below a ranking's
// level start from them: searched anew,
// they took about a third of what the levels add to the level's direct
// call (1,000,000 lion samples, level 1%, without threads: 104 ms, against
// 215 to 232 for the 11 boundaries below).
template <typename ConcurrencyTag>
Array<Index> swap_farthest_for_crowded(const Indexed_points& points, Array<char>& present, std::size_t swaps,
                                       const Array<double>& scale, Array<Index> hint = Array<Index>(),
                                       const Neighbor_offsets& offsets = Neighbor_offsets())
{
  Array<Index> sites;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
      sites.push_back(i);
  if (sites.size() == points.size())
    return sites;
  if (sites.empty())
    return Array<Index>(points.size(), none_index);
  Array<Index> site = nearest_present_points<ConcurrencyTag>(points, present, hint, offsets);
  Array<Index>().swap(hint); // not to be held through the swaps
  if (sites.size() < 2 || swaps == 0)
    return site;
  // the present points' own tree serves the crowding, and goes
  Array<Neighbor> crowded(sites.size());
  {
    const Point_tree tree(points, sites.begin(), sites.end(), ConcurrencyTag());
    for_each_index<ConcurrencyTag>(
      sites.size(),
      [&](std::size_t r) {
        const Index s = sites[r];
        crowded[r] =
          crowding_entry(points, scale, s, squared_distance(points.points[s], points.points[tree.nearest_one(s)]));
      },
      [](std::size_t) { return true; });
  }
  Tree_search<ConcurrencyTag> search(points, present, site);
  Nearest_present<Tree_search<ConcurrencyTag>, ConcurrencyTag> nearest(points, present, std::move(search),
                                                                       std::move(site), heap_size(swaps));
  Crowding_order order(std::move(crowded));
  swap_in_turn(nearest, order, scale, swaps);
  return nearest.release_sites();
}

// The coverage swaps at a ranking's level boundary (see swap_in_turn, and
// List_search), among the points of the level above alone, `level`, in
// index order, so that the levels stay nested: those present, which are
// `present_points` (in index order), and those the stage that ended there
// removed. `first` and `neighbors` are that stage's lists of neighbours.
// Returns each point's nearest present neighbour after the swaps (ties by
// input position): itself when present, none when it has none or lies
// outside `level`.
template <typename ConcurrencyTag>
Array<Index> swap_among_neighbors(const Indexed_points& points, Array<char>& present, const Array<Index>& level,
                                  const Array<Index>& present_points, const Array<std::size_t>& first,
                                  const Array<Index>& neighbors, std::size_t swaps, const Array<double>& scale)
{
  CGAL_assertion(std::size_t(std::count_if(level.begin(), level.end(), [&](Index i) { return present[i] != 0; })) ==
                 present_points.size());
  const List_search search(points, present, level, first, neighbors);
  Array<Index> site(points.size(), none_index);
  for_each_index<ConcurrencyTag>(
    level.size(),
    [&](std::size_t r) {
      const Index i = level[r];
      site[i] = present[i] ? i : search.nearest_but(i, i).id;
    },
    [](std::size_t) { return true; });
  if (present_points.size() < 2 || present_points.size() == level.size() || swaps == 0)
    return site;
  // the present points alone: at the 50% boundary of 1,000,000 points, an
  // entry for each point of the level took about 25 ms more (page faults)
  Array<Neighbor> crowded(present_points.size());
  for_each_index<ConcurrencyTag>(
    crowded.size(),
    [&](std::size_t r) {
      const Index s = present_points[r];
      crowded[r] = crowding_entry(points, scale, s, search.nearest_but(s, s).squared_distance);
    },
    [](std::size_t) { return true; });
  Nearest_present<List_search, ConcurrencyTag> nearest(points, present, search, std::move(site), heap_size(swaps));
  Crowding_order order(std::move(crowded));
  swap_in_turn(nearest, order, scale, swaps);
  return nearest.release_sites();
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H
