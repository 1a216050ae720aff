// The simplification of a cloud as the program runs it: on row numbers, so
// that the library reorders indices rather than copies of the points; with
// --lod or --indices, the ranks of the rows; with --importance, theirs.

#ifndef ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H
#define ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H

#include "command_line.h"
#include "point_files.h"

#include <CGAL/Entropy_simplification/compute_entropy_importance.h>
#include <CGAL/Entropy_simplification/entropy_simplification_ranks.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

namespace entropy_simplify {

using Kernel = CGAL::Simple_cartesian<double>;

// Row i of the cloud as a point, so that the library reorders row numbers
// rather than copies of the points.
template <typename Row>
struct Row_point_map
{
  using key_type = Row;
  using value_type = Kernel::Point_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  const Cloud* cloud;
  const Column* xyz[3];

  friend value_type get(const Row_point_map& map, Row row)
  {
    const std::array<double, 3> p = coordinates(*map.cloud, map.xyz, row);
    return value_type(p[0], p[1], p[2]);
  }
};

// Receives the final normal of each kept row.
template <typename Row>
struct Row_normal_map
{
  using key_type = Row;
  using value_type = Kernel::Vector_3;
  using reference = value_type;
  using category = boost::writable_property_map_tag;

  std::vector<std::array<double, 3> >* normals;

  friend void put(const Row_normal_map& map, Row row, const value_type& n)
  {
    (*map.normals)[row] = { n.x(), n.y(), n.z() };
  }
};

// The rows in input order, numbered by `Row`, and their point map.
template <typename Row>
std::vector<Row> all_rows(std::size_t n)
{
  std::vector<Row> rows(n);
  std::iota(rows.begin(), rows.end(), Row(0));
  return rows;
}

template <typename Row>
Row_point_map<Row> point_map_of(const Cloud& cloud)
{
  return Row_point_map<Row>{ &cloud, { cloud.table.find("x"), cloud.table.find("y"), cloud.table.find("z") } };
}

// The rows the simplification keeps, in input order, numbered by `Row`.
template <typename ConcurrencyTag, typename Row>
std::vector<std::size_t> simplify_rows(const Cloud& cloud, const Settings& s,
                                       const std::function<bool(double)>& callback,
                                       std::vector<std::array<double, 3> >& normals)
{
  std::vector<Row> rows = all_rows<Row>(cloud.size());
  const Row_point_map<Row> points = point_map_of<Row>(cloud);
  auto run = [&](const auto& np) {
    if (!s.write_normals)
      return CGAL::entropy_simplify_point_set<ConcurrencyTag>(rows, s.k, np, s.options);
    normals.assign(cloud.size(), { 0., 0., 0. });
    return CGAL::entropy_simplify_point_set<ConcurrencyTag>(
      rows, s.k, np.normal_map(Row_normal_map<Row>{ &normals }), s.options);
  };
  const auto np = CGAL::parameters::point_map(points).callback(callback);
  const auto first_removed = s.ratio ? run(np.select_percentage(*s.ratio * 100.))
                                     : run(np.number_of_output_points(*s.count));
  return std::vector<std::size_t>(rows.begin(), first_removed);
}

// The rank of every row, the level of --ratio or --count made exact.
template <typename ConcurrencyTag, typename Row>
std::vector<std::size_t> rank_rows(const Cloud& cloud, const Settings& s, const std::function<bool(double)>& callback)
{
  const std::vector<Row> rows = all_rows<Row>(cloud.size());
  const auto np = CGAL::parameters::point_map(point_map_of<Row>(cloud)).callback(callback);
  std::vector<std::size_t> ranks;
  ranks.reserve(rows.size());
  const bool done =
    s.ratio   ? CGAL::entropy_simplification_ranks<ConcurrencyTag>(rows, s.k, std::back_inserter(ranks),
                                                                   np.select_percentage(*s.ratio * 100.), s.options)
    : s.count ? CGAL::entropy_simplification_ranks<ConcurrencyTag>(rows, s.k, std::back_inserter(ranks),
                                                                   np.number_of_output_points(*s.count), s.options)
              : CGAL::entropy_simplification_ranks<ConcurrencyTag>(rows, s.k, std::back_inserter(ranks), np,
                                                                   s.options);
  if (!done)
    throw std::logic_error("the progress bar stopped the ranking");
  return ranks;
}

// The number of points of the level --ratio or --count asks for: with
// neither (--lod alone), the points the mode never removes.
inline std::size_t level_size(std::size_t n, const Settings& s)
{
  if (s.ratio)
    return CGAL::Entropy_simplification::internal::kept_count_from_percentage(n, *s.ratio * 100.);
  if (s.count)
    return (std::min)(n, *s.count);
  return s.options.mode == CGAL::Entropy_simplification::Mode::paper ? std::size_t(s.k) + 1 : std::size_t(1);
}

// What a run selects: the rows the simplification keeps, in input order,
// and, with --lod or --indices, the rows by rank: every row with --lod, the
// kept ones otherwise.
struct Selection
{
  std::vector<std::size_t> kept;
  std::vector<std::size_t> by_rank;
};

// The rows of a ranked run: the level's rows are the first by rank. Rows
// are numbered in 32 bits when they fit, which halves the memory of the
// ranges the library reads or reorders.
template <typename ConcurrencyTag>
Selection select_ranked_rows(const Cloud& cloud, const Settings& s, const std::function<bool(double)>& callback)
{
  const std::size_t level = level_size(cloud.size(), s);
  // a level asked for is refused where a run without ranks refuses it: in
  // the paper's mode, below k + 1 points
  if (s.ratio || s.count)
    CGAL::Entropy_simplification::internal::check_simplification_arguments(cloud.size(), cloud.size(), s.k, level,
                                                                           s.options);
  const std::vector<std::size_t> ranks =
    cloud.size() <= std::numeric_limits<std::uint32_t>::max()
      ? rank_rows<ConcurrencyTag, std::uint32_t>(cloud, s, callback)
      : rank_rows<ConcurrencyTag, std::size_t>(cloud, s, callback);
  Selection selection;
  selection.by_rank.resize(ranks.size());
  for (std::size_t row = 0; row < ranks.size(); ++row)
    selection.by_rank[ranks[row]] = row;
  selection.kept.assign(selection.by_rank.begin(), selection.by_rank.begin() + std::ptrdiff_t(level));
  std::sort(selection.kept.begin(), selection.kept.end());
  if (!s.lod)
    selection.by_rank.resize(level);
  return selection;
}

// The rows the simplification keeps, and their normals when asked for.
template <typename ConcurrencyTag>
Selection simplify_cloud(const Cloud& cloud, const Settings& s, const std::function<bool(double)>& callback,
                         std::vector<std::array<double, 3> >& normals)
{
  if (s.lod || !s.indices.empty())
    return select_ranked_rows<ConcurrencyTag>(cloud, s, callback);
  Selection selection;
  selection.kept = cloud.size() <= std::numeric_limits<std::uint32_t>::max()
                     ? simplify_rows<ConcurrencyTag, std::uint32_t>(cloud, s, callback, normals)
                     : simplify_rows<ConcurrencyTag, std::size_t>(cloud, s, callback, normals);
  if (s.write_normals)
  {
    std::vector<std::array<double, 3> > kept_normals;
    kept_normals.reserve(selection.kept.size());
    for (std::size_t row : selection.kept)
      kept_normals.push_back(normals[row]);
    normals.swap(kept_normals);
  }
  return selection;
}

// The importance of every row (--importance), computed on the whole cloud.
template <typename ConcurrencyTag>
std::vector<double> importance_of_rows(const Cloud& cloud, const Settings& s,
                                       const std::function<bool(double)>& callback)
{
  std::vector<std::size_t> rows = all_rows<std::size_t>(cloud.size());
  std::vector<double> importance(rows.size());
  if (!CGAL::compute_entropy_importance<ConcurrencyTag>(
        rows, s.k, CGAL::make_property_map(importance),
        CGAL::parameters::point_map(point_map_of<std::size_t>(cloud)).callback(callback), s.options))
    throw std::logic_error("the progress bar stopped the importance");
  return importance;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H
