// The package's tree against a linear scan: the k nearest neighbours in
// the package's order (squared distance, then input position), the points
// within a reach that depends on both points' scales, removals, and the
// coverage elimination's searches (the first one to four, whether one is
// nearer). The clouds hold thousands of points, so that the tree has many
// levels, and points on an integer lattice, so that many distances tie.
// And the kd order the tree follows against the independent reference's,
// and the searches answered from each point's first neighbours (offsets)
// against the scan.

#include <catch2/catch.hpp>

#include "reference_elimination.h"

#include <CGAL/Entropy_simplification/experiment_I_replica.h>
#include <CGAL/Entropy_simplification/internal/Decremental_knn.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/Nearest_present_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>

#include <algorithm>
#include <numeric>
#include <tuple>
#include <vector>

namespace {

namespace ESI = CGAL::Entropy_simplification::internal;

// 3,000 points: half uniform in a flat box, half on a 12 x 12 x 3 lattice
// (with repeats of lattice positions), with input positions shuffled.
ESI::Indexed_points test_points()
{
  ESI::Portable_random random(11);
  ESI::Indexed_points p;
  for (std::size_t i = 0; i < 3000; ++i)
  {
    if (i % 2 == 0)
      p.points.emplace_back(random.uniform() * 12., random.uniform() * 12., random.uniform() * 3.);
    else
      p.points.emplace_back(double(random.below(12)), double(random.below(12)), double(random.below(3)));
    p.input_position.push_back(ESI::Index(i));
  }
  for (std::size_t i = p.size(); i-- > 1;)
    std::swap(p.input_position[i], p.input_position[random.below(i + 1)]);
  return p;
}

// The first `count` points of `candidates` other than q, by (squared
// distance, input position), by ordering them all on that key.
ESI::Array<ESI::Index> scan_nearest(const ESI::Indexed_points& p, const ESI::Array<ESI::Index>& candidates,
                                     ESI::Index q, std::size_t count)
{
  std::vector<std::tuple<double, ESI::Index, ESI::Index> > keyed;
  for (ESI::Index i : candidates)
    if (i != q)
      keyed.emplace_back(ESI::squared_distance(p.points[q], p.points[i]), p.input_position[i], i);
  const std::size_t first = (std::min)(count, keyed.size());
  std::partial_sort(keyed.begin(), keyed.begin() + std::ptrdiff_t(first), keyed.end());
  ESI::Array<ESI::Index> result;
  for (std::size_t r = 0; r < first; ++r)
    result.push_back(std::get<2>(keyed[r]));
  return result;
}

ESI::Array<ESI::Index> ids(const ESI::Array<ESI::Neighbor>& best)
{
  ESI::Array<ESI::Index> result;
  for (const ESI::Neighbor& n : best)
    result.push_back(n.id);
  return result;
}

// The first `count` points of `candidates` other than q that come before
// `than` in the neighbour order of q: the scan's first points, kept while
// their distance and input position come before its.
ESI::Array<ESI::Index> scan_nearest_before(const ESI::Indexed_points& p, const ESI::Array<ESI::Index>& candidates,
                                            ESI::Index q, std::size_t count, const ESI::Neighbor& than)
{
  ESI::Array<ESI::Index> result;
  for (ESI::Index i : scan_nearest(p, candidates, q, count))
  {
    const double d = ESI::squared_distance(p.points[q], p.points[i]);
    if (d < than.squared_distance || (d == than.squared_distance && p.input_position[i] < than.input_position))
      result.push_back(i);
  }
  return result;
}

// The searches of the coverage elimination and of the relocation against
// the scans, `members` being the tree's points that are not removed: the
// first one to four points, the first one from a bound, the first one to
// four that come before another point (or that point), that other being one
// of the four points of the cloud nearest the query (on the lattice, many
// tie with the tree's points by distance, and only the input position
// decides) or a point anywhere. The queries step by 2 over a tree of every
// third point, so that they come from the tree and from outside it alike.
void require_few_nearest_and_nearer(const ESI::Indexed_points& p, const ESI::Point_tree& tree,
                                    const ESI::Array<ESI::Index>& members)
{
  ESI::Array<ESI::Index> everyone(p.size());
  std::iota(everyone.begin(), everyone.end(), ESI::Index(0));
  for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 2)
  {
    for (std::size_t count = 1; count <= 4; ++count)
    {
      const ESI::Array<ESI::Index> first = scan_nearest(p, members, q, count);
      ESI::Neighbor found[4];
      const std::size_t found_count = tree.nearest(q, count, found);
      REQUIRE(ids(ESI::Array<ESI::Neighbor>(found, found + found_count)) == first);
      for (std::size_t r = 0; r < found_count; ++r)
        REQUIRE(found[r].squared_distance == ESI::squared_distance(p.points[q], p.points[first[r]]));
    }
    ESI::Array<ESI::Index> others = scan_nearest(p, everyone, q, 4);
    others.push_back(ESI::Index((q * 7919u) % p.size()));
    for (ESI::Index other : others)
    {
      const ESI::Neighbor than = ESI::neighbor_of(p, q, other);
      const ESI::Array<ESI::Index> first_before = scan_nearest_before(p, members, q, 1, than);
      REQUIRE(tree.nearest_before(q, other) == (first_before.empty() ? other : first_before.front()));
      for (std::size_t count = 1; count <= 4; ++count)
      {
        ESI::Neighbor found[4];
        const std::size_t found_count = tree.nearest_before(q, count, than, found);
        REQUIRE(ids(ESI::Array<ESI::Neighbor>(found, found + found_count)) ==
                scan_nearest_before(p, members, q, count, than));
      }
    }
    // bounded from the start by a point of the tree, near or far, the
    // search for one point finds the first
    others.push_back(members[(q * 7919u) % members.size()]);
    for (ESI::Index seed : others)
      if (seed != q && std::find(members.begin(), members.end(), seed) != members.end())
        REQUIRE(tree.nearest_before(q, seed) == scan_nearest(p, members, q, 1).front());
  }
}

} // namespace

TEST_CASE("Point tree: nearest neighbours in the package's order, before and after removals, one or many", "[point tree]")
{
  const ESI::Indexed_points p = test_points();
  // a tree over every third point, queried from every point
  ESI::Array<ESI::Index> members;
  for (ESI::Index i = 0; i < ESI::Index(p.size()); i += 3)
    members.push_back(i);
  ESI::Point_tree tree(p, members.begin(), members.end());
  ESI::Array<ESI::Neighbor> best;
  for (std::size_t count : { std::size_t(0), std::size_t(1), std::size_t(10), std::size_t(40) })
    for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 7)
    {
      tree.nearest(q, count, best);
      REQUIRE(ids(best) == scan_nearest(p, members, q, count));
    }
  // the search for one point alone finds the same, ties included: the
  // lattice repeats positions
  for (ESI::Index q = 0; q < ESI::Index(p.size()); ++q)
    REQUIRE(tree.nearest_one(q) == scan_nearest(p, members, q, 1).front());
  require_few_nearest_and_nearer(p, tree, members);
  // remove all but 30 members: the searches skip the removed points
  ESI::Portable_random random(5);
  ESI::Array<ESI::Index> present = members;
  while (present.size() > 30)
  {
    const std::size_t r = random.below(present.size());
    tree.remove(present[r]);
    present.erase(present.begin() + std::ptrdiff_t(r));
  }
  for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 7)
  {
    tree.nearest(q, 10, best);
    REQUIRE(ids(best) == scan_nearest(p, present, q, 10));
    tree.nearest(q, 100, best); // more than are present
    REQUIRE(ids(best) == scan_nearest(p, present, q, 100));
    REQUIRE(tree.nearest_one(q) == scan_nearest(p, present, q, 1).front());
  }
  require_few_nearest_and_nearer(p, tree, present);
  // fewer points than asked for: all those other than the query
  const ESI::Array<ESI::Index> three(members.begin(), members.begin() + 3);
  const ESI::Point_tree small(p, three.begin(), three.end());
  for (ESI::Index q : { three[0], ESI::Index(1) })
  {
    ESI::Neighbor found[4];
    const std::size_t count = small.nearest(q, 4, found);
    REQUIRE(count == (q == three[0] ? 2u : 3u));
    REQUIRE(ids(ESI::Array<ESI::Neighbor>(found, found + count)) == scan_nearest(p, three, q, 4));
  }
}

TEST_CASE("Point tree: any indices, in any order, on points in any order", "[point tree]")
{
  // the tree follows the halves of the kd order, which these points are not
  // in, and sorts the indices it is given: given shuffled, clustered in two
  // short runs, or repeated, it answers as a scan
  ESI::Indexed_points p = test_points();
  ESI::Portable_random random(7);
  ESI::Array<ESI::Index> members;
  for (ESI::Index i = 1000; i < 1100; ++i)
    members.push_back(i);
  for (ESI::Index i = 2990; i < 3000; ++i)
    members.push_back(i);
  for (std::size_t i = members.size(); i-- > 1;)
    std::swap(members[i], members[random.below(i + 1)]);
  ESI::Array<ESI::Neighbor> best;
  {
    const ESI::Point_tree tree(p, members.begin(), members.end());
    for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 3)
    {
      tree.nearest(q, 10, best);
      REQUIRE(ids(best) == scan_nearest(p, members, q, 10));
    }
  }
  // 60 copies of one index and 60 of another: the tree stops splitting
  ESI::Array<ESI::Index> repeated(60, 5);
  repeated.insert(repeated.end(), 60, 6);
  const ESI::Point_tree tree(p, repeated.begin(), repeated.end());
  for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 11)
  {
    tree.nearest(q, 1, best);
    REQUIRE(ids(best) == scan_nearest(p, repeated, q, 1));
  }
  // and on points in kd order, whose halves it follows
  ESI::Array<ESI::Working_point> input(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    input[p.input_position[i]] = p.points[i];
  p = ESI::sort_spatially(input);
  for (ESI::Index i = 0; i < ESI::Index(p.size()); i += 2)
    members.push_back(i);
  const ESI::Point_tree sorted(p, members.begin(), members.end());
  for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 3)
  {
    sorted.nearest(q, 10, best);
    REQUIRE(ids(best) == scan_nearest(p, members, q, 10));
    REQUIRE(sorted.nearest_one(q) == scan_nearest(p, members, q, 1).front());
  }
}

TEST_CASE("Point tree: the points within a reach of both scales, leaf by leaf", "[point tree]")
{
  // in kd order, so that the leaves' boxes are apart and the search prunes
  const ESI::Indexed_points unsorted = test_points();
  ESI::Array<ESI::Working_point> input(unsorted.size());
  for (std::size_t i = 0; i < unsorted.size(); ++i)
    input[unsorted.input_position[i]] = unsorted.points[i];
  const ESI::Indexed_points p = ESI::sort_spatially(input);
  ESI::Portable_random random(3);
  ESI::Array<double> scales;
  // small on one side, large on the other, so that a leaf's reach depends
  // on its neighbours' scales
  for (std::size_t i = 0; i < p.size(); ++i)
    scales.push_back((p.points[i].x() < 6. ? 0.1 : 2.) * (1. + 0.5 * random.uniform()));
  // a tree of two points in three, random and lattice ones, so that the
  // leaves near a leaf hold points that are not in the tree
  ESI::Array<ESI::Index> members;
  for (ESI::Index i = 0; i < ESI::Index(p.size()); ++i)
    if (i % 3 != 0)
      members.push_back(i);
  ESI::Point_tree tree(p, members.begin(), members.end());
  tree.record_largest_scales(scales);
  std::size_t found = 0;
  for (double radius : { 0.3, 1. })
  {
    ESI::Array<ESI::Index> visited;
    for (ESI::Index leaf : tree.leaves())
      tree.within_reach_of_leaf(leaf, radius, scales, [&](ESI::Index q, const ESI::Array<ESI::Index>& found_inside) {
        visited.push_back(q);
        ESI::Array<ESI::Index> inside = found_inside;
        std::sort(inside.begin(), inside.end());
        REQUIRE(std::adjacent_find(inside.begin(), inside.end()) == inside.end());
        // every member strictly within the reach is found; any other found
        // is a member at the reach within rounding
        ESI::Array<ESI::Index> strictly;
        for (ESI::Index j : members)
        {
          const double reach = radius * (scales[q] + scales[j]);
          const double d2 = ESI::squared_distance(p.points[q], p.points[j]);
          if (d2 < reach * reach)
            strictly.push_back(j);
          else if (std::binary_search(inside.begin(), inside.end(), j))
            REQUIRE(d2 <= reach * reach * (1. + 1e-8));
        }
        REQUIRE(std::includes(members.begin(), members.end(), inside.begin(), inside.end()));
        REQUIRE(std::includes(inside.begin(), inside.end(), strictly.begin(), strictly.end()));
        found += strictly.size();
      });
    // every member once, in index order
    REQUIRE(visited == members);
  }
  CHECK(found > 10 * members.size()); // the reaches hold many points
}

#ifdef CGAL_LINKED_WITH_TBB
TEST_CASE("Point tree: a tree built in parallel answers as a linear scan", "[point tree]")
{
  // 150,000 points, above the size from which subtrees are built in parallel
  ESI::Portable_random random(17);
  ESI::Indexed_points p;
  for (std::size_t i = 0; i < 150000; ++i)
  {
    p.points.emplace_back(double(random.below(400)), double(random.below(400)), random.uniform());
    p.input_position.push_back(ESI::Index(i));
  }
  const ESI::Array<ESI::Index> all = ESI::all_indices(p.size());
  const ESI::Point_tree tree(p, all.begin(), all.end(), CGAL::Parallel_tag());
  ESI::Array<ESI::Neighbor> best;
  for (ESI::Index q = 0; q < ESI::Index(p.size()); q += 997)
  {
    tree.nearest(q, 10, best);
    REQUIRE(ids(best) == scan_nearest(p, all, q, 10));
  }
}
#endif

#ifdef CGAL_LINKED_WITH_TBB
// The orders the two modes start from: the parallel kd sort makes the
// splits of the sequential one, and the sort of coincident points is by a
// total order; on 150,000 points both run their parallel code.
TEST_CASE("Point tree: the spatial order and the collapse of copies do not depend on the tag", "[point tree]")
{
  ESI::Portable_random random(23);
  ESI::Array<ESI::Working_point> points;
  for (std::size_t i = 0; i < 150000; ++i)
    points.emplace_back(double(random.below(100)), double(random.below(100)), double(random.below(3)));
  const ESI::Indexed_points sequential = ESI::sort_spatially<CGAL::Sequential_tag>(points);
  const ESI::Indexed_points parallel = ESI::sort_spatially<CGAL::Parallel_tag>(points);
  CHECK(sequential.input_position == parallel.input_position);
  const ESI::Distinct_points one = ESI::collapse_duplicates<CGAL::Sequential_tag>(points);
  const ESI::Distinct_points two = ESI::collapse_duplicates<CGAL::Parallel_tag>(points);
  CHECK(one.input_position == two.input_position);
  CHECK(one.copies == two.copies);
  CHECK(one.representative == two.representative);
  CHECK(one.copies.size() > 100000); // 30,000 lattice positions for 150,000 points
}
#endif

// The kd order against the reference's definition, by full sorts, on
// lattice points whose coordinates tie everywhere, and on uniform ones.
TEST_CASE("Point tree: the kd order is the manual's", "[point tree]")
{
  ESI::Portable_random random(29);
  for (bool lattice : { true, false })
  {
    ESI::Array<ESI::Working_point> points;
    for (std::size_t i = 0; i < 20000; ++i)
      if (lattice)
        points.emplace_back(double(random.below(30)), double(random.below(20)), double(random.below(4)));
      else
        points.emplace_back(random.uniform(), 2. * random.uniform(), 0.5 * random.uniform());
    const ESI::Indexed_points sorted = ESI::sort_spatially(points);
    const std::vector<std::size_t> expected = reference::kd_order({ points.begin(), points.end() });
    REQUIRE(std::equal(sorted.input_position.begin(), sorted.input_position.end(), expected.begin(), expected.end()));
  }
}

// With a large k the table is filled a part at a time (2097 rows per part
// at k = 2000): rows on either side of a part's end are those of a scan,
// the progress counts every row once, and a stop ends the fill.
TEST_CASE("Point tree: the neighbour table of a large k, part after part", "[point tree]")
{
  const ESI::Indexed_points p = test_points();
  const ESI::Array<ESI::Index> all = ESI::all_indices(p.size());
  const ESI::Point_tree tree(p, all.begin(), all.end());
  const unsigned int k = 2000;
  ESI::Array<ESI::Index> table;
  std::vector<std::size_t> reports;
  REQUIRE(ESI::nearest_neighbor_table<CGAL::Parallel_if_available_tag>(tree, all, k, table, [&](std::size_t done) {
    reports.push_back(done);
    return true;
  }));
  REQUIRE(table.size() == p.size() * k);
  CHECK(std::is_sorted(reports.begin(), reports.end()));
  CHECK(std::find(reports.begin(), reports.end(), std::size_t(2097)) != reports.end());
  CHECK(reports.back() == p.size());
  for (std::size_t r : { std::size_t(0), std::size_t(2096), std::size_t(2097), std::size_t(2999) })
  {
    const ESI::Array<ESI::Index> expected = scan_nearest(p, all, ESI::Index(r), k);
    REQUIRE(ESI::Array<ESI::Index>(table.begin() + std::ptrdiff_t(r * k), table.begin() + std::ptrdiff_t((r + 1) * k)) ==
            expected);
  }
  std::size_t calls = 0;
  CHECK_FALSE(ESI::nearest_neighbor_table<CGAL::Sequential_tag>(tree, all, k, table, [&](std::size_t) {
    ++calls;
    return false;
  }));
  CHECK(calls == 1);
}

// The paper mode's lists grow a part at a time too (2098 points per part at
// k = 1000, which keeps 2000 candidates): the lists on either side of a
// part's end are a scan's, before and after removals, the progress rises to
// 1 through the candidates (80%) and the reverse lists, and a stop ends it.
TEST_CASE("Point tree: the decremental neighbours of a large k, part after part", "[point tree]")
{
  const ESI::Indexed_points p = test_points();
  const unsigned int k = 1000;
  std::vector<double> fractions;
  ESI::Decremental_knn knn(p, k);
  REQUIRE(knn.initialize<CGAL::Parallel_if_available_tag>([&](double f) {
    fractions.push_back(f);
    return true;
  }));
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  CHECK(std::find(fractions.begin(), fractions.end(), 0.8) != fractions.end());
  CHECK(fractions.back() == 1.);
  ESI::Array<ESI::Index> present = ESI::all_indices(p.size());
  auto check = [&](ESI::Index q) {
    const ESI::Array<ESI::Index> expected = scan_nearest(p, present, q, k);
    REQUIRE(ESI::Array<ESI::Index>(knn.neighbors(q), knn.neighbors(q) + k) == expected);
  };
  for (ESI::Index q : { 0u, 2097u, 2098u, 2999u })
    check(q);
  // removals reach the lists of both parts through the reverse lists
  ESI::Array<ESI::Index> changed;
  for (ESI::Index removed : { 2097u, 2098u, 10u, 2500u })
  {
    knn.remove(removed, changed);
    present.erase(std::find(present.begin(), present.end(), removed));
    CHECK_FALSE(changed.empty());
    for (ESI::Index q : changed)
      check(q);
  }

  std::size_t calls = 0;
  ESI::Decremental_knn stopped(p, k);
  CHECK_FALSE(stopped.initialize<CGAL::Sequential_tag>([&](double) {
    ++calls;
    return false;
  }));
  CHECK(calls == 1);
}

// The coverage elimination answers its searches from each point's first
// neighbours when they hold enough present points: on the test points in
// kd order, where most offsets fit in a byte, and as they are, where most
// do not, for sets of present points from all to 30, the answers are the
// scan's, and a search is declined exactly when the neighbours before the
// first offset that does not fit hold too few present points; and so are
// the nearest present points that the relocation searches. The table is
// the scan's, not the tree's.
TEST_CASE("Neighbor offsets: the present points among the first neighbours are the nearest present points", "[point tree]")
{
  const ESI::Indexed_points unsorted = test_points();
  const ESI::Indexed_points sorted = ESI::sort_spatially(unsorted.points);
  constexpr unsigned int k = 10;
  for (const ESI::Indexed_points* p : { &sorted, &unsorted })
  {
    const std::size_t n = p->size();
    ESI::Array<ESI::Index> everyone(n);
    std::iota(everyone.begin(), everyone.end(), ESI::Index(0));
    ESI::Array<ESI::Index> knn;
    for (ESI::Index q = 0; q < ESI::Index(n); ++q)
    {
      const ESI::Array<ESI::Index> row = scan_nearest(*p, everyone, q, k);
      knn.insert(knn.end(), row.begin(), row.end());
    }
    const ESI::Neighbor_offsets offsets(knn, k);
    ESI::Portable_random random(31);
    std::size_t answered = 0, declined = 0, answered_of_all = 0;
    for (std::size_t kept : { n, n / 2, n / 10, std::size_t(30) })
    {
      ESI::Array<char> present(n, 0);
      ESI::Array<ESI::Index> members = everyone;
      for (std::size_t i = n; i-- > 1;)
        std::swap(members[i], members[random.below(i + 1)]);
      members.resize(kept);
      std::sort(members.begin(), members.end());
      for (ESI::Index i : members)
        present[i] = 1;
      const auto is_present = [&](ESI::Index i) { return present[i] != 0; };
      for (ESI::Index q = 0; q < ESI::Index(n); ++q)
        for (std::size_t count = 1; count <= 4; ++count)
        {
          ESI::Index first[4];
          std::size_t present_in_prefix = 0;
          for (std::size_t j = 0; j < k; ++j)
          {
            const long long offset = (long long)(knn[q * k + j]) - (long long)(q);
            if (offset < -127 || offset > 127)
              break;
            present_in_prefix += present[knn[q * k + j]];
          }
          if (offsets.first_present(q, count, is_present, first))
          {
            ++answered;
            answered_of_all += kept == n;
            REQUIRE(ESI::Array<ESI::Index>(first, first + count) == scan_nearest(*p, members, q, count));
          }
          else
          {
            ++declined;
            REQUIRE(present_in_prefix < count);
          }
        }
      // the relocation's search for the nearest present point, which they
      // answer first
      const ESI::Array<ESI::Index> nearest = ESI::nearest_present_points<CGAL::Sequential_tag>(
        *p, present, ESI::Array<ESI::Index>(), offsets);
      for (ESI::Index q = 0; q < ESI::Index(n); ++q)
        REQUIRE(nearest[q] == (present[q] ? q : scan_nearest(*p, members, q, 1).front()));
    }
    // both ways are taken, and with every point present, on points in kd
    // order, the first in most searches (83%)
    CHECK(answered > 0);
    CHECK(declined > 0);
    if (p == &sorted)
      CHECK(answered_of_all > 3 * n); // of 4 n
  }
}

// The offsets of one byte end at 127 either way, -128 marking the first
// that does not fit: points on a line, far apart, but for point 0, whose
// nearest are points 127 and 128, and point 255, whose nearest is 127. And
// at most 16 neighbours are kept.
TEST_CASE("Neighbor offsets: the offsets that fit in a byte, and the first that does not", "[point tree]")
{
  ESI::Indexed_points p;
  for (std::size_t i = 0; i < 300; ++i)
  {
    p.points.emplace_back(10. * double(i) + 1000., 0., 0.);
    p.input_position.push_back(ESI::Index(i));
  }
  p.points[0] = ESI::Working_point(0., 0., 0.);
  p.points[127] = ESI::Working_point(1., 0., 0.);
  p.points[128] = ESI::Working_point(-2., 0., 0.);
  p.points[255] = ESI::Working_point(1.5, 0., 0.);
  ESI::Array<ESI::Index> everyone(p.size());
  std::iota(everyone.begin(), everyone.end(), ESI::Index(0));
  constexpr unsigned int k = 3;
  ESI::Array<ESI::Index> knn;
  for (ESI::Index q = 0; q < ESI::Index(p.size()); ++q)
  {
    const ESI::Array<ESI::Index> row = scan_nearest(p, everyone, q, k);
    knn.insert(knn.end(), row.begin(), row.end());
  }
  REQUIRE(ESI::Array<ESI::Index>(knn.begin(), knn.begin() + 3) == ESI::Array<ESI::Index>{ 127, 255, 128 });
  REQUIRE(knn[255 * k] == 127);
  const ESI::Neighbor_offsets offsets(knn, k);
  const auto all = [](ESI::Index) { return true; };
  ESI::Index first[3];
  REQUIRE(offsets.first_present(0, 1, all, first));
  CHECK(first[0] == 127);
  CHECK_FALSE(offsets.first_present(0, 2, all, first)); // 255 is 255 ahead
  CHECK_FALSE(offsets.first_present(255, 1, all, first)); // 127 is 128 behind
  // an ordinary point of the line: its next two
  REQUIRE(offsets.first_present(1, 2, all, first));
  CHECK(first[0] == 2);
  CHECK(first[1] == 3);
  CHECK_FALSE(ESI::Neighbor_offsets().first_present(1, 1, all, first));
  // of k = 20 neighbours, the first 16 are kept: those of point 150 go
  // 149, 151, 148, 152, ... out to 158, the 16th, then 141
  constexpr unsigned int wide = 20;
  ESI::Array<ESI::Index> wide_knn;
  for (ESI::Index q = 0; q < ESI::Index(p.size()); ++q)
  {
    const ESI::Array<ESI::Index> row = scan_nearest(p, everyone, q, wide);
    wide_knn.insert(wide_knn.end(), row.begin(), row.end());
  }
  REQUIRE(wide_knn[150 * wide + 15] == 158);
  REQUIRE(wide_knn[150 * wide + 16] == 141);
  const ESI::Neighbor_offsets sixteen(wide_knn, wide);
  REQUIRE(sixteen.first_present(150, 1, [](ESI::Index i) { return i == 158; }, first));
  CHECK(first[0] == 158);
  CHECK_FALSE(sixteen.first_present(150, 1, [](ESI::Index i) { return i == 141; }, first));
}
