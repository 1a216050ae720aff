// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call of entropy_simplify_point_set on a copy of some points, seen
// through the input positions of the range afterwards.

#ifndef ENTROPY_SIMPLIFICATION_TEST_SIMPLIFICATION_RUN_H
#define ENTROPY_SIMPLIFICATION_TEST_SIMPLIFICATION_RUN_H

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace test_runs {

namespace ES = CGAL::Entropy_simplification;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Vector = CGAL::Simple_cartesian<double>::Vector_3;

inline ES::Options paper_mode()
{
  ES::Options options;
  options.mode = ES::Mode::paper;
  return options;
}

struct Run
{
  std::vector<std::size_t> order; // the input position of each element of the range after the call
  std::size_t kept = 0;           // the position of the returned iterator
  std::vector<Vector> normals;    // by input position, null where nothing was written
};

// Calls the function on (point, input position, normal) records, with the
// point map added to `np`, and the normal map when `with_normals`; checks
// that every record kept its own point.
template <typename Tag, typename NP>
Run run_on_records(const std::vector<Point>& points, unsigned int k, const NP& np, const ES::Options& options,
                   bool with_normals)
{
  using Record = std::tuple<Point, std::size_t, Vector>;
  std::vector<Record> range;
  for (std::size_t i = 0; i < points.size(); ++i)
    range.emplace_back(points[i], i, CGAL::NULL_VECTOR);
  const auto with_points = np.point_map(CGAL::Nth_of_tuple_property_map<0, Record>());
  const auto it = with_normals ? CGAL::entropy_simplify_point_set<Tag>(
                                   range, k, with_points.normal_map(CGAL::Nth_of_tuple_property_map<2, Record>()),
                                   options)
                               : CGAL::entropy_simplify_point_set<Tag>(range, k, with_points, options);
  Run run;
  run.kept = std::size_t(it - range.begin());
  run.normals.assign(points.size(), CGAL::NULL_VECTOR);
  for (const Record& r : range)
  {
    if (!(std::get<0>(r) == points[std::get<1>(r)]))
      throw std::logic_error("a record lost its point");
    run.order.push_back(std::get<1>(r));
    run.normals[std::get<1>(r)] = std::get<2>(r);
  }
  return run;
}

template <typename Tag = CGAL::Sequential_tag, typename NP>
Run simplify(const std::vector<Point>& points, unsigned int k, const NP& np, const ES::Options& options = {})
{
  return run_on_records<Tag>(points, k, np, options, false);
}

// The same, with the normals written to `Run::normals`.
template <typename Tag = CGAL::Sequential_tag, typename NP>
Run simplify_with_normals(const std::vector<Point>& points, unsigned int k, const NP& np,
                          const ES::Options& options = {})
{
  return run_on_records<Tag>(points, k, np, options, true);
}

// The input positions of the removed points, first removed first.
inline std::vector<std::size_t> removal_order(const Run& run)
{
  return std::vector<std::size_t>(run.order.rbegin(), run.order.rend() - std::ptrdiff_t(run.kept));
}

inline std::set<std::size_t> kept_positions(const Run& run)
{
  return std::set<std::size_t>(run.order.begin(), run.order.begin() + std::ptrdiff_t(run.kept));
}

// The range after the call is a permutation of the input positions.
inline bool is_permutation_of_input(const Run& run)
{
  std::vector<std::size_t> sorted = run.order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (sorted[i] != i)
      return false;
  return true;
}

} // namespace test_runs

#endif // ENTROPY_SIMPLIFICATION_TEST_SIMPLIFICATION_RUN_H
