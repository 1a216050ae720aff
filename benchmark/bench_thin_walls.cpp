// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_thin_walls: where the point-to-plane error of the machined parts
// comes from, by the thickness of their walls.
//
//   bench_thin_walls --data DIR [--out DIR] [--smoke]
//
// On the benchmark's labelled mesh samples (fandisk, anchor, rotor,
// couplingdown) at 10, 20 and 50% kept, runs the default mode with the
// entropy term off (feature_weight 0) and at its default weight, and splits
// the point-to-plane error (bench::point_distances, as in quality.csv) by
// the thickness of the wall each input point lies on: the distance from the
// point, against the normal of the mesh face nearest it, to the mesh's
// other side (faces oriented outwards), in kept spacings (the mean distance
// from a kept point to its nearest, in the run without the entropy term).
// Where a wall is a few spacings thick, the 10 nearest kept points of a
// kept point can reach its other side, and their plane tilts. For each
// class of thickness: the input's share of points, the kept density there
// over the input's, and the class's part of the squared error, as a share
// of the run without the entropy term's whole squared error (so that those
// shares sum to 1 in that run, and to the square of the ratio of the errors
// in the other).
// Prints the section "Thin walls" of RESULTS.md and writes every cell to
// thin_walls.csv. With --smoke: rotor alone, divided in size by 16.
// Invariants checked (the program fails otherwise): each run keeps exactly
// its count, and the range it returns is a permutation of the input.

#include "bench_arguments.h"
#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_machine.h"
#include "bench_metrics.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using bench::Cloud;
using bench::Point;

namespace {

using Primitive = CGAL::AABB_face_graph_triangle_primitive<bench::Mesh>;
#if CGAL_VERSION_NR >= 1060000000
using Face_tree = CGAL::AABB_tree<CGAL::AABB_traits_3<bench::Kernel, Primitive> >;
#else
using Face_tree = CGAL::AABB_tree<CGAL::AABB_traits<bench::Kernel, Primitive> >;
#endif

constexpr std::array<double, 3> ratios = { 0.1, 0.2, 0.5 };
constexpr std::array<double, 2> weights = { 0., 3. };
// the classes' upper bounds, in kept spacings: below 2, 2 to 4, 4 and more
constexpr std::array<double, 2> class_bounds = { 2., 4. };
constexpr std::size_t classes = class_bounds.size() + 1;

// Each point's wall thickness over the diagonal: the distance, against the
// normal of the face nearest it, to the first face beyond; infinity where
// the ray leaves the mesh.
std::vector<double> wall_thickness(const bench::Mesh& mesh, const Cloud& cloud)
{
  Face_tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  std::vector<double> thickness;
  thickness.reserve(cloud.points.size());
  for (const Point& p : cloud.points)
  {
    const auto nearest = tree.closest_point_and_primitive(p);
    const bench::Vector n = CGAL::Polygon_mesh_processing::compute_face_normal(nearest.second, mesh);
    // from just inside the face, so that the ray does not meet it
    const bench::Kernel::Ray_3 ray(p - n * (1e-7 * cloud.diagonal), -n);
    const auto hit = tree.first_intersection(ray);
    double t = std::numeric_limits<double>::infinity();
#if CGAL_VERSION_NR >= 1060000000
    const Point* q = hit ? std::get_if<Point>(&hit->first) : nullptr;
#else
    const Point* q = hit ? boost::get<Point>(&hit->first) : nullptr;
#endif
    if (q != nullptr)
      t = std::sqrt(CGAL::squared_distance(p, *q)) / cloud.diagonal;
    thickness.push_back(t);
  }
  return thickness;
}

std::size_t class_of(double thickness, double spacing)
{
  std::size_t c = 0;
  while (c < class_bounds.size() && !(thickness < class_bounds[c] * spacing))
    ++c;
  return c;
}

// The default mode's kept points on `cloud` at `feature_weight`; checks
// the invariants.
std::vector<Point> default_mode(const Cloud& cloud, std::size_t count, double feature_weight)
{
  ES::Options options;
  options.feature_weight = feature_weight;
  std::vector<Point> points = cloud.points;
  const auto end = CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
    points, 10, CGAL::parameters::number_of_output_points(count), options);
  std::vector<Point> all = points, input = cloud.points;
  std::sort(all.begin(), all.end());
  std::sort(input.begin(), input.end());
  if (std::size_t(end - points.begin()) != count || all != input)
    throw std::runtime_error(cloud.name + ": the default mode did not keep exactly " + std::to_string(count) +
                             " of the input points");
  points.erase(end, points.end());
  return points;
}

struct Cell
{
  std::string input;
  double ratio = 0., weight = 0., point_to_plane = 0., spacing = 0.;
  std::array<double, classes> input_share{}, density{}, error_share{};
};

double mean(const std::vector<double>& values)
{
  double sum = 0.;
  for (double v : values)
    sum += v;
  return sum / double(values.size());
}

// The two runs of one ratio, classified by the spacing of the first.
std::vector<Cell> measure_ratio(const Cloud& cloud, const std::vector<double>& thickness, double ratio)
{
  const std::size_t n = cloud.points.size(), m = std::size_t(std::ceil(ratio * double(n)));
  const bench::Index_tree input_tree(cloud.points);
  std::vector<Cell> cells;
  double spacing = 0., first_squares = 0.;
  for (double weight : weights)
  {
    const std::vector<Point> kept = default_mode(cloud, m, weight);
    const bench::Point_distances d = bench::point_distances(cloud, kept);
    Cell cell{ cloud.name, ratio, weight };
    if (cells.empty())
      spacing = mean(d.spacing);
    cell.spacing = spacing;
    std::array<double, classes> squares{}, input_count{}, kept_count{};
    double all_squares = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t c = class_of(thickness[i], spacing);
      squares[c] += d.to_plane[i] * d.to_plane[i];
      input_count[c] += 1.;
      all_squares += d.to_plane[i] * d.to_plane[i];
    }
    for (const Point& p : kept)
    {
      thread_local std::vector<bench::Index> nearest;
      input_tree.nearest(p, 1, nearest);
      kept_count[class_of(thickness[nearest[0]], spacing)] += 1.;
    }
    if (cells.empty())
      first_squares = all_squares;
    cell.point_to_plane = std::sqrt(all_squares / double(n));
    for (std::size_t c = 0; c < classes; ++c)
    {
      cell.input_share[c] = input_count[c] / double(n);
      cell.density[c] = input_count[c] > 0. ? (kept_count[c] / double(m)) / cell.input_share[c] : 0.;
      cell.error_share[c] = squares[c] / first_squares;
    }
    cells.push_back(cell);
  }
  return cells;
}

void write_csv(const std::string& file, const std::vector<Cell>& cells)
{
  std::ofstream out(file);
  out << "input,ratio,feature_weight,point_to_plane,spacing";
  for (const char* c : { "below_2", "2_to_4", "from_4" })
    out << ",input_share_" << c << ",density_" << c << ",error_share_" << c;
  out << '\n' << std::setprecision(9);
  for (const Cell& cell : cells)
  {
    out << cell.input << ',' << cell.ratio << ',' << cell.weight << ',' << cell.point_to_plane << ',' << cell.spacing;
    for (std::size_t c = 0; c < classes; ++c)
      out << ',' << cell.input_share[c] << ',' << cell.density[c] << ',' << cell.error_share[c];
    out << '\n';
  }
  if (!out.flush())
    throw std::runtime_error("cannot write " + file);
}

const std::array<const char*, classes> class_names = { "below 2 spacings", "2 to 4 spacings", "4 spacings and more" };

// Where the entropy term raises the error: the class of walls whose squared
// error rose most, its part of the rise, and its density with and without
// the term; where it lowers it, the range of the ratios.
void write_summary(std::ostream& out, const std::vector<Cell>& cells)
{
  std::vector<std::string> raised;
  double lowest = std::numeric_limits<double>::infinity(), highest = 0.;
  for (std::size_t r = 0; r + 1 < cells.size(); r += weights.size())
  {
    const Cell &off = cells[r], &on = cells[r + 1];
    const double ratio = on.point_to_plane / off.point_to_plane;
    if (ratio <= 1.)
    {
      lowest = (std::min)(lowest, ratio);
      highest = (std::max)(highest, ratio);
      continue;
    }
    std::size_t most = 0;
    double rise = 0.;
    for (std::size_t c = 0; c < classes; ++c)
    {
      rise += on.error_share[c] - off.error_share[c];
      if (on.error_share[c] - off.error_share[c] > on.error_share[most] - off.error_share[most])
        most = c;
    }
    raised.push_back(on.input + " at " + bench::fixed(100. * on.ratio, 0) + "% (" + bench::fixed(ratio, 3) +
                     " times; the walls " + class_names[most] + " thick, " +
                     bench::fixed(100. * on.input_share[most], 0) + "% of the points, take " +
                     bench::fixed(100. * (on.error_share[most] - off.error_share[most]) / rise, 0) +
                     "% of the rise in squared error, their kept density " + bench::fixed(on.density[most], 3) +
                     " times the input's, against " + bench::fixed(off.density[most], 3) + ")");
  }
  const std::size_t pairs = cells.size() / weights.size();
  out << "\nThe entropy term raises the point-to-plane error in " << raised.size() << " of " << pairs << " cells";
  for (std::size_t i = 0; i < raised.size(); ++i)
    out << (i == 0 ? ": " : "; ") << raised[i];
  if (raised.size() < pairs)
    out << (raised.empty() ? "" : "; it lowers it in the others") << " (" << bench::fixed(lowest, 3) << " to "
        << bench::fixed(highest, 3) << " times)";
  out << ".\n";
}

void write_section(std::ostream& out, const std::vector<Cell>& cells)
{
  out << "\n## Thin walls\n\n"
      << "Produced by `bench_thin_walls --data DIR --out DIR` (`bash benchmark/run.sh` runs it; every cell in "
         "`results/thin_walls.csv`). On " << bench::machine_description() << ".\n\n"
      << "The default mode with the entropy term off (`feature_weight` 0) and at its default (3), on the labelled "
         "mesh samples, the point-to-plane error (as in the quality tables, over the diagonal) split by the "
         "thickness of the wall each input point lies on: the distance from the point, against the normal of "
         "the mesh face nearest it, to the mesh's other side, in kept spacings (the mean distance from a kept "
         "point to its nearest, in the run at weight 0). Each class: the input's share of points, the kept "
         "density there over the input's, and the class's part of the squared error as a share of the run at "
         "weight 0's whole (summing to 1 at weight 0, to the square of the ratio of the errors at 3).\n\n"
      << "| input | kept | weight | point-to-plane | below 2 spacings: points, density, error | 2 to 4 | 4 and "
         "more (or no other side) |\n|---|---:|---:|---:|---|---|---|\n";
  for (const Cell& cell : cells)
  {
    out << "| " << cell.input << " | " << bench::fixed(100. * cell.ratio, 0) << "% | " << bench::fixed(cell.weight, 0) << " | "
        << std::setprecision(4) << cell.point_to_plane;
    for (std::size_t c = 0; c < classes; ++c)
      out << " | " << bench::fixed(cell.input_share[c], 3) << ", " << bench::fixed(cell.density[c], 3) << ", "
          << bench::fixed(cell.error_share[c], 3);
    out << " |\n";
  }
  write_summary(out, cells);
}

} // namespace

int main(int argc, char** argv)
{
  return bench::run_section(argc, argv, "bench_thin_walls", false, [](const bench::Section_arguments& arguments) {
    const auto& [data, out, quality, smoke] = arguments;
    std::vector<Cell> cells;
    for (const bench::Benchmark_input& in : bench::benchmark_inputs(data, smoke ? 16 : 1))
      if (!in.is_scan && in.labelled && in.name.rfind("replica", 0) != 0 && (!smoke || in.name == "rotor"))
      {
        std::cerr << "bench_thin_walls: " << in.name << '\n';
        Cloud cloud = in.make();
        const std::string mesh = data + "/meshes/" + cloud.name + ".off";
        cloud.name += bench::role_mark(in.role);
        const std::vector<double> thickness =
          wall_thickness(bench::read_mesh(mesh), cloud);
        for (double ratio : ratios)
        {
          const std::vector<Cell> c = measure_ratio(cloud, thickness, ratio);
          cells.insert(cells.end(), c.begin(), c.end());
        }
      }
    write_csv(out + "/thin_walls.csv", cells);
    write_section(std::cout, cells);
  });
}
