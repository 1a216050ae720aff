// The simplification of a cloud as the program runs it: on row numbers, so
// that the library reorders indices rather than copies of the points.

#ifndef ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H
#define ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H

#include "command_line.h"
#include "point_files.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstdint>
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

// The rows the simplification keeps, in input order, numbered by `Row`.
template <typename ConcurrencyTag, typename Row>
std::vector<std::size_t> simplify_rows(const Cloud& cloud, const Settings& s,
                                       const std::function<bool(double)>& callback,
                                       std::vector<std::array<double, 3> >& normals)
{
  std::vector<Row> rows(cloud.size());
  std::iota(rows.begin(), rows.end(), Row(0));
  Row_point_map<Row> points{ &cloud, { cloud.table.find("x"), cloud.table.find("y"), cloud.table.find("z") } };
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

// The rows the simplification keeps, in input order, and their normals when
// asked for. Rows are numbered in 32 bits when they fit, which halves the
// memory of the range the library reorders.
template <typename ConcurrencyTag>
std::vector<std::size_t> simplify_cloud(const Cloud& cloud, const Settings& s,
                                        const std::function<bool(double)>& callback,
                                        std::vector<std::array<double, 3> >& normals)
{
  const std::vector<std::size_t> rows =
    cloud.size() <= std::numeric_limits<std::uint32_t>::max()
      ? simplify_rows<ConcurrencyTag, std::uint32_t>(cloud, s, callback, normals)
      : simplify_rows<ConcurrencyTag, std::size_t>(cloud, s, callback, normals);
  if (s.write_normals)
  {
    std::vector<std::array<double, 3> > kept_normals;
    kept_normals.reserve(rows.size());
    for (std::size_t row : rows)
      kept_normals.push_back(normals[row]);
    normals.swap(kept_normals);
  }
  return rows;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_SIMPLIFY_CLOUD_H
