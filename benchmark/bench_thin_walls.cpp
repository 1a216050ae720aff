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
// over the input's, the share of its points whose measuring plane reaches
// across a wall (through a kept point whose mesh face faces the other way),
// and the class's part of the squared error, as a share
// of the run without the entropy term's whole squared error (so that those
// shares sum to 1 in that run, and to the square of the ratio of the errors
// in the other).
// Prints the section "Thin walls" of RESULTS.md and writes every cell to
// thin_walls.csv. With --smoke: rotor alone, divided in size by 16.
// Invariants checked (the program fails otherwise): each mesh is closed and
// oriented outwards; each run keeps exactly its count, and the range it
// returns is a permutation of the input; the classes' squared errors sum to
// the whole.

#include "bench_arguments.h"
#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_machine.h"
#include "bench_metrics.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
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

#include <tbb/parallel_for.h>

#include <Eigen/Dense>

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

// Each point's wall: the outward normal of the mesh face nearest it, and
// the wall's thickness over the diagonal, the distance against that normal
// to the first face beyond (infinity where the ray leaves the mesh). The
// mesh must be closed and oriented outwards, or "beyond" is not inside.
struct Walls
{
  std::vector<Eigen::Vector3d> normal;
  std::vector<double> thickness;
};

Walls walls_of(const bench::Mesh& mesh, const Cloud& cloud)
{
  if (!CGAL::is_closed(mesh) || !CGAL::Polygon_mesh_processing::is_outward_oriented(mesh))
    throw std::runtime_error(cloud.name + ": the mesh is not closed and oriented outwards");
  Face_tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  Walls walls;
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
    walls.normal.emplace_back(n.x(), n.y(), n.z());
    walls.thickness.push_back(t);
  }
  return walls;
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
  std::array<double, classes> input_share{}, density{}, across{}, error_share{};
};

double mean(const std::vector<double>& values)
{
  double sum = 0.;
  for (double v : values)
    sum += v;
  return sum / double(values.size());
}

// Whether each kept point's 10 nearest kept points (itself included), the
// points of its measuring plane, hold one on the other side of its wall:
// one whose wall faces the other way (outward normals more than 120
// degrees apart). `origin[j]` is the input point kept point j is.
std::vector<char> planes_across(const std::vector<Point>& kept, const std::vector<bench::Index>& origin,
                                const Walls& walls)
{
  const bench::Index_tree tree(kept);
  std::vector<char> across(kept.size(), 0);
  tbb::parallel_for(std::size_t(0), kept.size(), [&](std::size_t j) {
    thread_local std::vector<bench::Index> near;
    tree.nearest(kept[j], 10, near);
    for (bench::Index other : near)
      across[j] |= walls.normal[origin[j]].dot(walls.normal[origin[other]]) < -0.5;
  });
  return across;
}

// The two runs of one ratio, classified by the spacing of the first.
// `input_tree` holds the cloud's points.
std::vector<Cell> measure_ratio(const Cloud& cloud, const bench::Index_tree& input_tree, const Walls& walls,
                                double ratio)
{
  const std::size_t n = cloud.points.size(), m = std::size_t(std::ceil(ratio * double(n)));
  std::vector<Cell> cells;
  double spacing = 0., first_squares = 0.;
  for (double weight : weights)
  {
    const std::vector<Point> kept = default_mode(cloud, m, weight);
    const bench::Point_distances d = bench::point_distances(cloud, kept);
    std::vector<bench::Index> origin(m);
    tbb::parallel_for(std::size_t(0), m, [&](std::size_t j) {
      thread_local std::vector<bench::Index> nearest;
      input_tree.nearest(kept[j], 1, nearest);
      origin[j] = nearest[0];
    });
    const std::vector<char> across = planes_across(kept, origin, walls);
    Cell cell{ cloud.name, ratio, weight };
    if (cells.empty())
      spacing = mean(d.spacing);
    cell.spacing = spacing;
    std::array<double, classes> squares{}, input_count{}, kept_count{}, across_count{};
    double all_squares = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t c = class_of(walls.thickness[i], spacing);
      squares[c] += d.to_plane[i] * d.to_plane[i];
      input_count[c] += 1.;
      across_count[c] += across[d.nearest[i]];
      all_squares += d.to_plane[i] * d.to_plane[i];
    }
    for (bench::Index i : origin)
      kept_count[class_of(walls.thickness[i], spacing)] += 1.;
    if (cells.empty())
      first_squares = all_squares;
    cell.point_to_plane = std::sqrt(all_squares / double(n));
    const double undefined = std::numeric_limits<double>::quiet_NaN();
    double shares = 0.;
    for (std::size_t c = 0; c < classes; ++c)
    {
      cell.input_share[c] = input_count[c] / double(n);
      cell.density[c] = input_count[c] > 0. ? (kept_count[c] / double(m)) / cell.input_share[c] : undefined;
      cell.across[c] = input_count[c] > 0. ? across_count[c] / input_count[c] : undefined;
      cell.error_share[c] = squares[c] / first_squares;
      shares += cell.error_share[c];
    }
    // the shares sum to the square of the ratio of the errors
    const double expected = all_squares / first_squares;
    if (!(std::abs(shares - expected) <= 1e-9 * expected))
      throw std::logic_error(cloud.name + ": the classes' squared errors do not sum to the whole");
    cells.push_back(cell);
  }
  return cells;
}

void write_csv(const std::string& file, const std::vector<Cell>& cells)
{
  std::ofstream out(file);
  out << "input,ratio,feature_weight,point_to_plane,spacing";
  for (const char* c : { "below_2", "2_to_4", "from_4" })
    out << ",input_share_" << c << ",density_" << c << ",across_" << c << ",error_share_" << c;
  out << '\n' << std::setprecision(9);
  for (const Cell& cell : cells)
  {
    out << cell.input << ',' << cell.ratio << ',' << cell.weight << ',' << cell.point_to_plane << ',' << cell.spacing;
    for (std::size_t c = 0; c < classes; ++c)
      out << ',' << cell.input_share[c] << ',' << cell.density[c] << ',' << cell.across[c] << ','
          << cell.error_share[c];
    out << '\n';
  }
  if (!out.flush())
    throw std::runtime_error("cannot write " + file);
}

const std::array<const char*, classes> class_names = { "below 2 spacings", "2 to 4 spacings", "4 spacings and more" };

// Where the entropy term raises the error: the class of walls whose squared
// error rose most, its part of the rise, its density and its share of
// measuring planes across a wall with and without the term; elsewhere, the
// range of the ratios.
void write_summary(std::ostream& out, const std::vector<Cell>& cells)
{
  std::vector<std::string> raised;
  double lowest = std::numeric_limits<double>::infinity(), highest = 0.;
  for (std::size_t r = 0; r + 1 < cells.size(); r += weights.size())
  {
    const Cell &off = cells[r], &on = cells[r + 1];
    const double ratio = on.point_to_plane / off.point_to_plane;
    if (!(ratio > 1.))
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
                     " times the input's against " + bench::fixed(off.density[most], 3) + ", the planes of " +
                     bench::fixed(100. * on.across[most], 0) + "% of their points across the wall against " +
                     bench::fixed(100. * off.across[most], 0) + "%)");
  }
  const std::size_t pairs = cells.size() / weights.size();
  if (raised.empty())
  {
    out << "\nThe entropy term raises the point-to-plane error in none of the " << pairs << " cells ("
        << bench::fixed(lowest, 3) << " to " << bench::fixed(highest, 3) << " times).\n";
    return;
  }
  out << "\nThe entropy term raises the point-to-plane error in " << raised.size() << " of " << pairs << " cells";
  for (std::size_t i = 0; i < raised.size(); ++i)
    out << (i == 0 ? ": " : "; ") << raised[i];
  if (raised.size() < pairs)
    out << "; not in the others (" << bench::fixed(lowest, 3) << " to " << bench::fixed(highest, 3) << " times)";
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
         "point to its nearest, in the run at weight 0). Each class: the input's share of points; the kept "
         "density there over the input's; the share of its points whose measuring plane (that of their nearest "
         "kept point's 10 nearest kept points) reaches across a wall, through a kept point whose mesh face "
         "faces the other way (normals more than 120 degrees apart); and the class's part of the squared error "
         "as a share of the run at weight 0's whole (summing to 1 at weight 0, to the square of the ratio of "
         "the errors at 3). n/a: no point in the class.\n\n"
      << "| input | kept | weight | point-to-plane | below 2 spacings: points, density, across, error | 2 to 4 | "
         "4 and more (or no other side) |\n|---|---:|---:|---:|---|---|---|\n";
  for (const Cell& cell : cells)
  {
    out << "| " << cell.input << " | " << bench::fixed(100. * cell.ratio, 0) << "% | " << bench::fixed(cell.weight, 0) << " | "
        << std::setprecision(4) << cell.point_to_plane;
    for (std::size_t c = 0; c < classes; ++c)
      out << " | " << bench::fixed(cell.input_share[c], 3) << ", " << bench::fixed(cell.density[c], 3) << ", "
          << bench::fixed(cell.across[c], 3) << ", " << bench::fixed(cell.error_share[c], 3);
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
      if (bench::open_to_diagnosis(in) && !in.is_scan && in.labelled && in.name.rfind("replica", 0) != 0 &&
          (!smoke || in.name == "rotor"))
      {
        std::cerr << "bench_thin_walls: " << in.name << '\n';
        Cloud cloud = in.make();
        const std::string mesh = data + "/meshes/" + cloud.name + ".off";
        cloud.name += bench::role_mark(in.role);
        const Walls walls = walls_of(bench::read_mesh(mesh), cloud);
        const bench::Index_tree input_tree(cloud.points);
        for (double ratio : ratios)
        {
          const std::vector<Cell> c = measure_ratio(cloud, input_tree, walls, ratio);
          cells.insert(cells.end(), c.begin(), c.end());
        }
      }
    write_csv(out + "/thin_walls.csv", cells);
    write_section(std::cout, cells);
  });
}
