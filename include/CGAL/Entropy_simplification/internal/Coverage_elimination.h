// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A greedy coverage elimination: removes, round after round, the present
// points whose removal raises least the weighted sum of the input points'
// distances to their nearest present point.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_ELIMINATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_ELIMINATION_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Cell_medians.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_engine.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_terms.h>
#include <CGAL/Entropy_simplification/internal/Elimination_field.h>
#include <CGAL/Entropy_simplification/internal/Feature_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Level_cells.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Whether more than 35% of the `n` points are present: the first stage of
// the weights (see coverage_weight_exponent and coverage_weights).
inline bool most_points_present(std::size_t present, std::size_t n)
{
  // in 64 bits, as 100 times 2^32 points would wrap a 32-bit size_t
  return 100 * std::uint64_t(present) > 35 * std::uint64_t(n);
}

// The exponent of (1 + w s) in the weights (see coverage_weights) while
// `present` of `n` points are present. Where each present point stands for
// many input points, removing it costs its weight times about the cube of
// the spacing, and an exponent of 3/2 makes the kept density grow as
// 1 + w s. Where it stands for two or three, as when half the points are
// kept, the cost goes about as the spacing itself, and the density grows
// about as the square of the weight, (1 + w s)^3: features kept whole and
// the flat regions thinned, which left the mean distance at 50% kept 3.6 to
// 5.0% higher on four of the benchmark's inputs with sharp edges, above
// Open3D's farthest point sampling. So the exponent is 1.1 while more than
// 35% of the points are present, 1.35 while more than 20%, and 1.6 below,
// a little above 3/2, which gives fandisk's sharp edges at 10% the share
// issue 12 asks for (design notes: the default mode). It depends
// on the points present, not on the count asked for, so that a ranking's
// prefixes follow the same weights as direct calls.
inline double coverage_weight_exponent(std::size_t present, std::size_t n)
{
  if (most_points_present(present, n))
    return 1.1;
  // in 64 bits, as 100 times 2^32 points would wrap a 32-bit size_t
  return 100 * std::uint64_t(present) > 20 * std::uint64_t(n) ? 1.35 : 1.6;
}

// The weight of each point in the sum of distances: (1 + w s)^e for a
// feature strength s, the budgeted feature weight w and the `exponent` e,
// that is the field's scale to the power -2e, divided by the greatest so
// that it is at most 1. Where a surface weighs c times more, the sum is
// least with about c^(2/3) times more points per area (the density of a
// weighted k-median on a surface) when each point stands for many.
//
// With `squared_strength`, (1 + w s^2)^e instead, w s taken from the scale
// (1 / scale^2 - 1) so that it is the same whatever computed the scale: a
// strong feature (s near 1) weighs as much, a weak one far less. It is for
// the first stage, while most points are present: there a kept point stands
// for two or three input points and the density grows about as the square
// of the weight, so that weak features, a noisy scan's or the coarse
// scale's wide bands, took points from the flat regions that the mean
// distance misses most (design notes: the square of the strength).
template <typename ConcurrencyTag>
Array<double> coverage_weights(const Elimination_field& field, double exponent, bool squared_strength)
{
  Array<double> weight(field.scale.size());
  if (!squared_strength || !(field.feature_weight > 0.))
  {
    const double smallest =
      field.scale.empty() ? 1. : *std::min_element(field.scale.begin(), field.scale.end());
    for_each_index<ConcurrencyTag>(
      weight.size(), [&](std::size_t i) { weight[i] = std::pow(smallest / field.scale[i], 2. * exponent); },
      [](std::size_t) { return true; });
    return weight;
  }
  for_each_index<ConcurrencyTag>(
    weight.size(),
    [&](std::size_t i) {
      const double feature = 1. / (field.scale[i] * field.scale[i]) - 1.; // w s
      weight[i] = 1. + feature * feature / field.feature_weight;
    },
    [](std::size_t) { return true; });
  const double greatest = weight.empty() ? 1. : *std::max_element(weight.begin(), weight.end());
  for_each_index<ConcurrencyTag>(
    weight.size(), [&](std::size_t i) { weight[i] = std::pow(weight[i] / greatest, exponent); },
    [](std::size_t) { return true; });
  return weight;
}

// The units of a point's share of a removal cost: 2^-20 of the typical
// spacing, the side of a point's share of the effective area, so that sums
// and differences of shares are exact whatever their order.
inline double share_unit(const Elimination_field& field, std::size_t n)
{
  return std::sqrt(field.effective_area / double((std::max)(n, std::size_t(1)))) / 1048576.;
}

// The most a point's share of a cost may be (see removal_share) among `n`
// points: 2^40 units, a million spacings, unless the shares of all `n`
// points at that bound could overflow a cost, as with a point far from a
// scan of more than 2^23 points when a ranking comes down to two points.
inline std::int64_t largest_share(std::size_t n)
{
  return (std::min)(std::int64_t(1) << 40,
                    std::numeric_limits<std::int64_t>::max() / std::int64_t((std::max)(n, std::size_t(1))));
}

// What removing point `a` costs point `i`, whose nearest present point it is
// and whose next is at `to_next` from it: its weight times the distance it
// then gains, in units of `unit`, truncated, at most `largest`. The distance
// to `a` is 0 when `i` is `a`, unless `i` stands for input points spread
// around it (see follow_representatives_when_few).
inline std::int64_t removal_share(double weight, double to_nearest, double to_next, double unit,
                                  std::int64_t largest)
{
  const double share = weight * (to_next - to_nearest) / unit;
  return share < double(largest) ? std::int64_t(share) : largest;
}

// The elimination on the present points. Each input point follows its
// nearest and next nearest present point (the neighbour order), and each
// present point's cost is the sum of the shares of the points it is the
// nearest of. Each round removes the present points that come first (see
// Key) among those they share an input point with, among the tenth of the
// present points that come first: none of them is the nearest and next of
// one point, so each point loses at most one of the two. The round's
// removals, in that order, are the order of removal. A ranking's rounds
// below 1% of the points have the present points stand for the input
// points (see follow_representatives_when_few).
class Coverage_elimination : public Default_mode_engine
{
public:
  Coverage_elimination(const Indexed_points& points, unsigned int k, const Options& options,
                       const Default_mode_terms& terms = Default_mode_terms())
    : Default_mode_engine(points, k, options, terms, following)
  {}

  // Makes the points of `present` the present ones, which the next
  // remove_down_to() follows from the start. `nearest`, when not empty,
  // holds each point's nearest present point, itself when present (ties by
  // input position), as the searches would find it: when the next run has
  // its representatives follow from the start (see
  // follow_representatives_when_few), that is all it needs of the input
  // points, which then search nothing.
  void set_present(Array<char> present, Array<Index> nearest = Array<Index>())
  {
    m_present = std::move(present);
    m_count = std::size_t(std::count(m_present.begin(), m_present.end(), char(1)));
    m_given_nearest = std::move(nearest);
  }

  // Makes the next remove_down_to() end its rounds at the level boundaries
  // (see level_boundary_below) and relocate each of them (see Level_cells),
  // so that the prefixes a ranking passes through are nearly as good as
  // direct calls'.
  void relocate_level_boundaries() { m_relocates_levels = true; }

  // Removes points down to `target` (at least 1), calling `removed(i)` after
  // each removal; stops early, returning false, when it returns false.
  template <typename ConcurrencyTag, typename Removed>
  bool remove_down_to(std::size_t target, const Removed& removed)
  {
    CGAL_precondition(target >= 1);
    Array<Index>().swap(m_nearest_present); // an earlier run's
    const bool relocates_levels = std::exchange(m_relocates_levels, false);
    Array<Index> given_nearest = std::move(m_given_nearest);
    if (m_count <= target)
    {
      // nothing to remove: no relocation follows to take the offsets, which
      // a ranking's run through the kept points would hold at its peak;
      // the columns stay for that run to follow from its start
      m_first_neighbors.offsets = Neighbor_offsets();
      return true;
    }
    if (relocates_levels && few_present() && !given_nearest.empty())
      take_nearest<ConcurrencyTag>(std::move(given_nearest));
    else
    {
      Array<Index>().swap(given_nearest); // not to be held through the run
      follow_present<ConcurrencyTag>();
    }
    if (relocates_levels)
    {
      m_level_cells.emplace(indices_by_input_position(m_points), m_nearest);
      follow_representatives_when_few<ConcurrencyTag>();
    }
    bool completed = true;
    while (completed && m_count > target)
    {
      const Array<Index> removals =
        m_level_cells
          ? remove_level<ConcurrencyTag>((std::max)(target, level_boundary_below(m_count, m_points.size())), target)
          : remove_round<ConcurrencyTag>(target);
      for (std::size_t r = 0; completed && r < removals.size(); ++r)
        completed = removed(removals[r]);
    }
    release();
    return completed;
  }

private:
  // A point's place in the order of removal: the lowest cost first, ties to
  // the lowest scrambled input position (see scrambled). On a regular grid
  // in row order, every cost ties, and with ties to the lowest position
  // each point's next, the neighbour of lowest position, would come before
  // it: the rounds would remove one point each. Scrambled, about one point
  // in a few comes first among its neighbours.
  struct Key
  {
    std::int64_t cost;
    std::uint32_t tie;
    bool operator<(const Key& other) const // comes first
    {
      return cost < other.cost || (cost == other.cost && tie < other.tie);
    }
  };
  // Costs are read between the passes that change them only.
  Key key(Index s) const
  {
    return Key{ m_cost[s].load(std::memory_order_relaxed), scrambled(m_points.input_position[s]) };
  }

  // The relocation that follows a run needs none of its memory but the
  // nearest present points of a direct call, from which it starts, and a
  // run that follows it starts from the present points alone.
  void release()
  {
    if (m_followers.empty() && !m_level_cells)
      m_nearest_present = std::move(m_nearest);
    Array<Index>().swap(m_followers);
    Array<double>().swap(m_spread);
    m_level_cells.reset();
    m_tree.reset();
    Array<Index>().swap(m_listed);
    Array<double>().swap(m_weight);
    Array<Index>().swap(m_nearest);
    Array<Index>().swap(m_following);
    Array<std::atomic<std::int64_t> >().swap(m_cost);
  }

  // Every point's nearest, next and spares, and the costs, from the present
  // points alone; from the field's first neighbours when every point is
  // present.
  template <typename ConcurrencyTag>
  void follow_present()
  {
    const std::size_t n = m_points.size();
    prepare_to_follow<ConcurrencyTag>();
    m_nearest.assign(n, none_index);
    Array<Index> first_neighbors = std::move(m_first_neighbors.columns);
    if (m_count == n && first_neighbors.size() == n * following)
    {
      // each point is its own nearest, and its first neighbours follow it,
      // as the search would find them
      m_following = std::move(first_neighbors);
      for_each_follower<ConcurrencyTag>([&](Index i) {
        m_nearest[i] = i;
        m_cost[i].fetch_add(share(i), std::memory_order_relaxed);
      });
    }
    else
    {
      Array<Index>().swap(first_neighbors);
      m_following.assign(n * following, none_index);
      for_each_follower<ConcurrencyTag>([&](Index i) { follow_anew(i); });
    }
  }

  // Each point's `nearest` present point, given to set_present(), the
  // costs at 0, and nothing followed: where the representatives follow at
  // once, they search anew, and the input points' next and spares would go
  // unread.
  template <typename ConcurrencyTag>
  void take_nearest(Array<Index> nearest)
  {
    prepare_to_follow<ConcurrencyTag>();
    m_nearest = std::move(nearest);
    m_following.assign(m_points.size() * following, none_index);
  }

  // The weights, the costs at 0, the present points listed and their tree.
  template <typename ConcurrencyTag>
  void prepare_to_follow()
  {
    const std::size_t n = m_points.size();
    m_exponent = coverage_weight_exponent(m_count, n);
    m_weight = weights_for_present<ConcurrencyTag>();
    m_unit = share_unit(m_field, n);
    m_largest_share = largest_share(n);
    Array<std::atomic<std::int64_t> >(n).swap(m_cost);
    list_present();
    build_tree<ConcurrencyTag>();
  }

  // Weighs the points with the exponent for the points present, when it
  // changed, and sums the costs anew. The representatives' weights, below
  // 1%, are sums of input points' (see follow_representatives_when_few),
  // whose exponent no longer changes there. The old weights go before the
  // new ones come: both at once were the program's peak of memory on
  // 10,000,000 points, 1413 MiB against 1408 without them.
  template <typename ConcurrencyTag>
  void weigh_for_present()
  {
    const double exponent = coverage_weight_exponent(m_count, m_points.size());
    if (exponent == m_exponent)
      return;
    CGAL_precondition(m_followers.empty());
    m_exponent = exponent;
    Array<double>().swap(m_weight);
    m_weight = weights_for_present<ConcurrencyTag>();
    for_each_index<ConcurrencyTag>(
      m_cost.size(), [&](std::size_t i) { m_cost[i].store(0, std::memory_order_relaxed); },
      [](std::size_t) { return true; });
    for_each_follower<ConcurrencyTag>(
      [&](Index i) { m_cost[m_nearest[i]].fetch_add(share(i), std::memory_order_relaxed); });
  }

  // The weights of m_exponent, for the points present (see coverage_weights).
  template <typename ConcurrencyTag>
  Array<double> weights_for_present() const
  {
    return coverage_weights<ConcurrencyTag>(
      m_field, m_exponent, m_terms.strong_features_first && most_points_present(m_count, m_points.size()));
  }

  // Whether at most 1% of the points are present, below which a ranking's
  // representatives follow (see follow_representatives_when_few).
  bool few_present() const { return m_count <= (m_points.size() + 99) / 100; }

  // Calls `f(i)` for each point `i` that follows the present points: every
  // point, or the representatives (see follow_representatives_when_few).
  template <typename ConcurrencyTag, typename F>
  void for_each_follower(const F& f) const
  {
    const bool all = m_followers.empty();
    for_each_index<ConcurrencyTag>(
      all ? m_points.size() : m_followers.size(), [&](std::size_t s) { f(all ? Index(s) : m_followers[s]); },
      [](std::size_t) { return true; });
  }

  // Once a ranking has at most 1% of the points present (from the start,
  // or after the relocation of the boundary of 1%), each present point
  // stands for the input points nearest it, and these representatives
  // alone follow the present points from then on: every later present
  // point is one of them. With every input point following, each halving
  // of the present points searched anew about every input point (twice
  // before the spares), and the stages below 1% cost about a third of a
  // direct call to 1%. A representative weighs as much as its input points
  // together, and its spread is their mean distance to it (weighted, both
  // summed in input order): it is as far from a point at distance d as
  // sqrt(d^2 + spread^2), and from itself as its spread, so that the
  // removal of its own point does not cost it its whole weight times the
  // distance to its next, which a stage just below 1%, where the present
  // points are hardly farther apart than the representatives, would
  // overestimate. The cells of the level boundaries keep every input
  // point, so that their medians stay those of the input points, and the
  // shares are bounded by the representatives' count, as only they add to
  // the costs.
  template <typename ConcurrencyTag>
  void follow_representatives_when_few()
  {
    if (!m_followers.empty() || !few_present())
      return;
    CGAL_precondition(m_level_cells.has_value()); // a ranking's, whose cells list the input order
    Array<double> weight(m_points.size(), 0.);
    m_spread.assign(m_points.size(), 0.);
    const Cell_members represented = represented_in_input_order();
    for_each_index<ConcurrencyTag>(
      m_listed.size(),
      [&](std::size_t r) {
        const Index p = m_listed[r];
        for (const Index* i = represented.begin(r); i != represented.end(r); ++i)
        {
          weight[p] += m_weight[*i];
          if (*i != p)
            m_spread[p] += m_weight[*i] * std::sqrt(squared_distance(m_points.points[*i], m_points.points[p]));
        }
        m_spread[p] /= weight[p];
      },
      [](std::size_t) { return true; });
    m_weight.swap(weight);
    m_followers = m_listed;
    m_largest_share = largest_share(m_followers.size());
    for (Index i = 0; i < Index(m_points.size()); ++i)
      m_cost[i].store(0, std::memory_order_relaxed);
    for_each_follower<ConcurrencyTag>([&](Index r) { follow_anew(r); });
  }

  // The input points each present point represents, that of rank r in
  // m_listed as cell r, in input order.
  Cell_members represented_in_input_order() const
  {
    Array<Index> rank(m_points.size());
    for (std::size_t r = 0; r < m_listed.size(); ++r)
      rank[m_listed[r]] = Index(r);
    return group_by_cell(m_listed.size(), m_level_cells->by_input(), [&](Index i) { return rank[m_nearest[i]]; });
  }

  // Follows the present points after a relocation brought back the points
  // `arrived` in place of others: each point from the points it followed
  // and the arrivals (see first_with_arrivals), and anew only when these
  // hold fewer than its nearest and next. A point whose nearest and next
  // stay keeps its share in its nearest's cost.
  template <typename ConcurrencyTag>
  void follow_relocated(const Array<Index>& arrived)
  {
    list_present();
    build_tree<ConcurrencyTag>();
    const Point_tree arrivals(m_points, arrived.begin(), arrived.end());
    for_each_follower<ConcurrencyTag>([&](Index i) {
      Index listed[1 + following];
      if (!first_with_arrivals(i, arrivals, listed))
      {
        unfollow(i);
        follow_anew(i);
      }
      else if (listed[0] == m_nearest[i] && listed[1] == next_of(i))
        std::copy_n(listed + 2, spares, following_of(i) + 1);
      else
      {
        unfollow(i);
        follow(i, listed[0], listed + 1);
      }
    });
  }

  // Writes to `listed` `i`'s nearest present point (itself when present),
  // its next and its spares, or as many of them as are known (none_index
  // for the others), after a relocation brought back the points of
  // `arrivals`; returns false when fewer than the nearest and the next are
  // known. The points `i` follows are the first present points of its
  // neighbour order up to the last of them, as only removals came since
  // they were listed: the present ones among them and the arrivals that
  // come before that last one are so again.
  bool first_with_arrivals(Index i, const Point_tree& arrivals, Index* listed) const
  {
    Index followed[1 + following];
    followed_of(i, followed);
    Neighbor known[1 + following], came[1 + following];
    std::size_t known_count = 0;
    Index last = none_index;
    for (Index p : followed)
      if (p != none_index && p != i)
      {
        last = p;
        if (is_present(p))
          known[known_count++] = neighbor_of(m_points, i, p);
      }
    if (last == none_index)
      return false;
    const std::size_t came_count = arrivals.nearest_before(i, 1 + following, neighbor_of(m_points, i, last), came);
    std::size_t count = 0;
    if (is_present(i))
      listed[count++] = i;
    // in the neighbour order, each point once: a point the stage removed,
    // still followed as a spare, may come back
    for (std::size_t a = 0, b = 0; count < 1 + following && (a < known_count || b < came_count);)
      if (b == came_count || (a < known_count && !(came[b] < known[a])))
      {
        b += std::size_t(b < came_count && came[b].id == known[a].id);
        listed[count++] = known[a++].id;
      }
      else
        listed[count++] = came[b++].id;
    std::fill(listed + count, listed + 1 + following, none_index);
    return count >= 2;
  }

  void list_present()
  {
    m_listed.clear();
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (is_present(i))
        m_listed.push_back(i);
  }

  template <typename ConcurrencyTag>
  void build_tree()
  {
    m_tree.emplace(m_points, m_listed.begin(), m_listed.end(), ConcurrencyTag());
    m_tree_size = m_listed.size();
  }

  // What `i` adds to the cost of its nearest present point: its share of
  // that point's removal (see removal_share), from its nearest and next.
  // It is computed again rather than kept, as the spares take its memory,
  // and the same expression gives the same value each time on builds that
  // do not contract floating-point operations (x86-64 without -march).
  std::int64_t share(Index i) const
  {
    const Index nearest = m_nearest[i], next = next_of(i);
    if (next == none_index)
      return 0;
    const double spread = m_spread.empty() ? 0. : m_spread[i];
    const auto to = [&](Index p) {
      return std::sqrt((p == i ? 0. : squared_distance(m_points.points[i], m_points.points[p])) + spread * spread);
    };
    return removal_share(m_weight[i], to(nearest), to(next), m_unit, m_largest_share);
  }

  Index* following_of(Index i) { return m_following.data() + std::size_t(i) * following; }
  Index next_of(Index i) const { return m_following[std::size_t(i) * following]; }

  // Writes to `followed` `i`'s nearest present point, then its next and
  // its spares.
  void followed_of(Index i, Index* followed) const
  {
    followed[0] = m_nearest[i];
    std::copy_n(m_following.data() + std::size_t(i) * following, following, followed + 1);
  }

  // Takes `i`'s share out of the cost of its nearest, before it follows
  // others.
  void unfollow(Index i) { m_cost[m_nearest[i]].fetch_sub(share(i), std::memory_order_relaxed); }

  // Sets `i`'s nearest present point to `nearest` (itself when present),
  // and its next and spares to the `following` points of `listed`
  // (none_index where there are none), then adds its share to the cost of
  // the nearest.
  void follow(Index i, Index nearest, const Index* listed)
  {
    m_nearest[i] = nearest;
    std::copy_n(listed, following, following_of(i));
    m_cost[nearest].fetch_add(share(i), std::memory_order_relaxed);
  }

  // Follows `i`'s nearest and next present points, and the spares after
  // them, searched anew among at least two: among its first neighbours
  // when they hold them (see Neighbor_offsets), and in the tree otherwise.
  void follow_anew(Index i)
  {
    CGAL_precondition(m_count >= 2);
    Index listed[1 + following];
    const std::size_t itself = is_present(i) ? 1 : 0;
    listed[0] = i; // its own nearest when present, overwritten otherwise
    const std::size_t others = 1 + following - itself;
    if (!m_first_neighbors.offsets.first_present(i, others, [this](Index p) { return is_present(p); },
                                                 listed + itself))
    {
      Neighbor found[1 + following];
      const std::size_t count = m_tree->nearest(i, others, found);
      for (std::size_t r = 0; r < others; ++r)
        listed[itself + r] = r < count ? found[r].id : none_index;
    }
    follow(i, listed[0], listed + 1);
  }

  // Follows, as `i`'s nearest and next, the first two of its nearest, next
  // and spares that are still present, and the spares after them, when two
  // are (or one, the last present point); searches anew otherwise. Only
  // removals came since they were listed, so that they still come first
  // among the present points.
  void follow_still_present(Index i)
  {
    Index listed[1 + following];
    followed_of(i, listed);
    std::size_t count = 0;
    for (Index p : listed)
      if (p != none_index && is_present(p))
        listed[count++] = p;
    CGAL_assertion(count >= 1); // no round removes both nearest and next
    if (count < 2 && m_count >= 2)
      return follow_anew(i);
    std::fill(listed + count, listed + 1 + following, none_index);
    follow(i, listed[0], listed + 1);
  }

  // One round, down to `target` at most: its removals, by cost.
  template <typename ConcurrencyTag>
  Array<Index> remove_round(std::size_t target)
  {
    weigh_for_present<ConcurrencyTag>();
    const Array<Index> round = removable_in_round<ConcurrencyTag>(m_count - target);
    remove_points<ConcurrencyTag>(round);
    return round;
  }

  // Rounds down to the level `boundary`, which is relocated unless it is
  // the `target`: the removals, each point that the relocation brings back
  // replaced by the point it replaces. The removed points join the cells of
  // their nearest present points, whose medians move in, and the input
  // points, or their representatives, then follow the relocated points
  // (see follow_relocated and follow_representatives_when_few). While every
  // input point follows, the cells then become those of the points' nearest
  // present points and their medians move in once more: a second step of
  // Lloyd's, as a direct call's relocation takes two, which brought the
  // prefixes' mean distance at 1 to 50% from up to 1.056 times a direct
  // call's to up to 1.044 on the benchmark's inputs, in about 8% of the
  // whole order's time (design notes: levels of detail). Below 1%, the
  // representatives alone know their nearest.
  template <typename ConcurrencyTag>
  Array<Index> remove_level(std::size_t boundary, std::size_t target)
  {
    Array<Index> removals;
    while (m_count > boundary)
    {
      const Array<Index> round = remove_round<ConcurrencyTag>(boundary);
      removals.insert(removals.end(), round.begin(), round.end());
    }
    if (boundary == target)
      return removals;
    for (Index r : removals)
      m_level_cells->join(r, m_nearest[r]);
    follow_relocated<ConcurrencyTag>(
      m_level_cells->move_to_medians<ConcurrencyTag>(m_points, m_listed, m_present, removals));
    if (m_followers.empty())
    {
      m_level_cells->take_cells_of_nearest(m_nearest);
      follow_relocated<ConcurrencyTag>(
        m_level_cells->move_to_medians<ConcurrencyTag>(m_points, m_listed, m_present, removals));
    }
    follow_representatives_when_few<ConcurrencyTag>();
    return removals;
  }

  // The points the next round removes, by cost: those of the first tenth of
  // the present points that come before every present point they share an
  // input point with, at most `removals`. Only the pairs with a point of
  // that tenth compare keys. The keys are computed where they are read
  // rather than held, which at the first round would take 16 bytes a point.
  template <typename ConcurrencyTag>
  Array<Index> removable_in_round(std::size_t removals) const
  {
    const Key threshold = nth_smallest<ConcurrencyTag>(
      m_listed.size(), [&](std::size_t r) { return key(m_listed[r]); }, (std::max)(std::size_t(1), m_count / 10),
      std::less<Key>());
    enum : char { beyond_threshold, removable, blocked };
    Array<std::atomic<char> > state(m_points.size()); // zero: beyond_threshold
    for_each_index<ConcurrencyTag>(
      m_listed.size(),
      [&](std::size_t r) {
        if (!(threshold < key(m_listed[r])))
          state[m_listed[r]].store(removable, std::memory_order_relaxed);
      },
      [](std::size_t) { return true; });
    for_each_follower<ConcurrencyTag>([&](Index i) {
      const Index a = m_nearest[i], b = next_of(i);
      if (b == none_index || (state[a].load(std::memory_order_relaxed) == beyond_threshold &&
                              state[b].load(std::memory_order_relaxed) == beyond_threshold))
        return;
      const Index later = key(a) < key(b) ? b : a;
      if (state[later].load(std::memory_order_relaxed) != beyond_threshold)
        state[later].store(blocked, std::memory_order_relaxed);
    });
    Growing_array<std::pair<Key, Index> > round;
    for (std::size_t r = 0; r < m_listed.size(); ++r)
      if (state[m_listed[r]].load(std::memory_order_relaxed) == removable)
        round.emplace_back(key(m_listed[r]), m_listed[r]);
    return first_by_key<ConcurrencyTag>(std::move(round), removals);
  }

  // The first `count` points of `keyed` by key, in that order (all of them
  // when fewer): keys are a total order, their scrambled input positions
  // being distinct, so that the order does not depend on the tag.
  template <typename ConcurrencyTag>
  static Array<Index> first_by_key(Growing_array<std::pair<Key, Index> > keyed, std::size_t count)
  {
    sort_by<ConcurrencyTag>(keyed.begin(), keyed.end(),
                            [](const std::pair<Key, Index>& a, const std::pair<Key, Index>& b) {
                              return a.first < b.first;
                            });
    Array<Index> first;
    first.reserve((std::min)(count, keyed.size()));
    for (std::size_t r = 0; r < (std::min)(count, keyed.size()); ++r)
      first.push_back(keyed[r].second);
    return first;
  }

  // Removes the points of `round`, then moves each point whose nearest or
  // next present point was removed to its new ones (see
  // follow_still_present): no round removes both.
  template <typename ConcurrencyTag>
  void remove_points(const Array<Index>& round)
  {
    for (Index p : round)
    {
      m_present[p] = 0;
      m_tree->remove(p);
    }
    m_count -= round.size();
    m_listed.erase(std::remove_if(m_listed.begin(), m_listed.end(), [this](Index i) { return !is_present(i); }),
                   m_listed.end());
    if (4 * m_count < 3 * m_tree_size)
      build_tree<ConcurrencyTag>();
    for_each_follower<ConcurrencyTag>([&](Index i) {
      const Index next = next_of(i);
      if (is_present(m_nearest[i]) && (next == none_index || is_present(next)))
        return;
      unfollow(i);
      follow_still_present(i);
    });
  }

  // the present points in index order
  Array<Index> m_listed;
  // the points that follow the present points, when not all of them, and
  // the spread of each (see follow_representatives_when_few), when not 0
  Array<Index> m_followers;
  Array<double> m_spread;
  // a tree of the present points, from which the removed ones are left out
  // until a quarter of the points it holds are, when it is built again: its
  // searches visit the leaves of the removed points, and rebuilt when half
  // of them were, a direct call to 10% took 2.6 to 3.6% more processor time
  // on the replicas and on 1,000,000 lion samples
  std::optional<Point_tree> m_tree;
  // the points the tree was built with, removed ones included
  std::size_t m_tree_size = 0;
  // whether a ranking's level boundaries are relocated, and their cells
  // while it runs
  bool m_relocates_levels = false;
  std::optional<Level_cells> m_level_cells;
  Array<double> m_weight;
  double m_exponent = 0.; // of m_weight, set with it (see coverage_weight_exponent)
  double m_unit = 1.;
  std::int64_t m_largest_share = 0;
  Array<Index> m_nearest;
  Array<Index> m_given_nearest; // see set_present; read by the next run only
  // of each point, its next present point and then its spares, the present
  // points that came after the next when they were listed (none_index
  // where there were none, or where a relocation left fewer known; see
  // first_with_arrivals): fewer searches, as a point searches again only
  // once it lost all but one of them
  static constexpr std::size_t spares = 2;
  static constexpr std::size_t following = 1 + spares;
  Array<Index> m_following;
  Array<std::atomic<std::int64_t> > m_cost;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_ELIMINATION_H
