// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The inputs of the benchmark: the replica of Experiment I, area-uniform
// samples of CGAL's demo meshes, and real scans.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_INPUTS_H
#define ENTROPY_SIMPLIFICATION_BENCH_INPUTS_H

#include "bench_common.h"

#include <CGAL/AABB_tree.h>
#include <CGAL/version.h>
// CGAL 6 renamed the AABB traits and primitives, deprecating the old names
#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_segment_primitive_3.h>
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#endif
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

using Mesh = CGAL::Surface_mesh<Point>;

inline Cloud replica(double noise, std::size_t scale_divisor = 1)
{
  CGAL::Entropy_simplification::Experiment_I_setup setup;
  setup.range_noise = noise;
  setup.board_points /= scale_divisor;
  setup.sphere_points /= scale_divisor;
  std::vector<std::pair<Point, int> > labelled;
  CGAL::Entropy_simplification::experiment_I_replica<Point>(std::back_inserter(labelled), setup);
  Cloud c;
  c.name = noise == 0.002 ? "replica_2mm" : "replica_1.2mm";
  c.description = "Experiment I replica, " + std::to_string(labelled.size()) + " points, range noise " +
                  (noise == 0.002 ? std::string("2") : std::string("1.2")) + " mm";
  for (const auto& p : labelled)
  {
    c.points.push_back(p.first);
    c.labels.push_back(p.second);
  }
  c.diagonal = bounding_box_diagonal(c.points);
  c.range_noise = noise;
  return c;
}

inline Mesh read_mesh(const std::string& file)
{
  Mesh mesh;
  std::ifstream in(file);
  if (!in || !(in >> mesh) || mesh.is_empty())
    throw std::runtime_error("cannot read the mesh " + file);
  return mesh;
}

// `n` points uniform in area on the mesh's faces, in random order: a face
// drawn with probability proportional to its area, then a uniform point in
// it. CGAL 5.5's sample_triangle_mesh is not used: it draws the point inside
// a face from CGAL's default generator whatever the seed, so its samples
// change from run to run.
inline std::vector<Point> sample_mesh(const Mesh& mesh, std::size_t n, std::uint64_t seed)
{
  std::vector<std::array<Point, 3> > triangles;
  std::vector<double> cumulative_area;
  double total = 0.;
  for (auto f : mesh.faces())
  {
    const auto h = mesh.halfedge(f);
    const std::array<Point, 3> t = { mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                     mesh.point(mesh.target(mesh.next(h))) };
    total += std::sqrt(Kernel::Triangle_3(t[0], t[1], t[2]).squared_area());
    triangles.push_back(t);
    cumulative_area.push_back(total);
  }
  Random random(seed);
  std::vector<Point> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t f = std::size_t(
      std::upper_bound(cumulative_area.begin(), cumulative_area.end(), random.uniform() * total) -
      cumulative_area.begin());
    const std::array<Point, 3>& t = triangles[(std::min)(f, triangles.size() - 1)];
    // uniform barycentric coordinates
    const double r1 = std::sqrt(random.uniform()), r2 = random.uniform();
    const double a = 1. - r1, b = r1 * (1. - r2), c = r1 * r2;
    points.emplace_back(a * t[0].x() + b * t[1].x() + c * t[2].x(), a * t[0].y() + b * t[1].y() + c * t[2].y(),
                        a * t[0].z() + b * t[1].z() + c * t[2].z());
  }
  return points;
}

// 1 for the points within `tolerance` of an edge whose two faces' normals
// differ by more than `angle_degrees`, 0 for the others.
inline std::vector<int> sharp_edge_labels(const Mesh& mesh, const std::vector<Point>& points, double angle_degrees,
                                          double tolerance)
{
  using Segment = Kernel::Segment_3;
  std::vector<Segment> sharp;
  const double cos_limit = std::cos(angle_degrees * CGAL_PI / 180.);
  for (auto e : mesh.edges())
  {
    const auto h = mesh.halfedge(e);
    if (mesh.is_border(e))
      continue;
    const Vector n1 = CGAL::Polygon_mesh_processing::compute_face_normal(mesh.face(h), mesh);
    const Vector n2 = CGAL::Polygon_mesh_processing::compute_face_normal(mesh.face(mesh.opposite(h)), mesh);
    if (n1 * n2 < cos_limit)
      sharp.emplace_back(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
  }
  using Segment_iterator = std::vector<Segment>::const_iterator;
#if CGAL_VERSION_NR >= 1060000000
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, CGAL::AABB_segment_primitive_3<Kernel, Segment_iterator> > >;
#else
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segment_iterator> > >;
#endif
  Tree tree(sharp.begin(), sharp.end());
  tree.accelerate_distance_queries();
  std::vector<int> labels;
  for (const Point& p : points)
    labels.push_back(!sharp.empty() && tree.squared_distance(p) <= tolerance * tolerance ? 1 : 0);
  return labels;
}

inline Cloud mesh_sample(const std::string& name, const std::string& file, std::size_t n, bool label_sharp_edges)
{
  const Mesh mesh = read_mesh(file);
  Cloud c;
  c.name = name;
  c.points = sample_mesh(mesh, n, 2018);
  c.diagonal = bounding_box_diagonal(c.points);
  c.description = file.substr(file.rfind('/') + 1) + " sampled uniformly in area, " + std::to_string(c.points.size()) +
                  " points";
  if (label_sharp_edges)
  {
    c.labels = sharp_edge_labels(mesh, c.points, 30., 0.005 * c.diagonal);
    c.description += ", labelled within 0.5% of the diagonal of an edge sharper than 30 degrees";
  }
  return c;
}

inline Cloud scan(const std::string& name, const std::string& file)
{
  Cloud c;
  c.name = name;
  if (!CGAL::IO::read_points(file, std::back_inserter(c.points)) || c.points.empty())
    throw std::runtime_error("cannot read the scan " + file);
  c.diagonal = bounding_box_diagonal(c.points);
  c.description = file.substr(file.rfind('/') + 1) + ", a real scan, " + std::to_string(c.points.size()) + " points";
  return c;
}

// How an input relates to the tuning of the default mode.
enum class Input_role
{
  tuned,         // its results guided the mode's design and constants
  held_out,      // set aside before the mode was first tuned, never used for it
  held_out_anew, // named before the work on anisotropy (issue 12) began, never used for it
  held_out_next, // named before any term is designed from the diagnosis of rotor's thin walls
};

// What the tables append to an input's name.
inline const char* role_mark(Input_role role)
{
  switch (role)
  {
  case Input_role::held_out:
    return " (held out)";
  case Input_role::held_out_anew:
    return " (held out anew)";
  case Input_role::held_out_next:
    return " (held out for the next term)";
  case Input_role::tuned:
    break;
  }
  return "";
}

// One input of the quality tables, made when needed: clouds of a million
// points are not all held at once.
struct Benchmark_input
{
  std::string name;
  Input_role role;
  bool is_scan;  // a real scan, read whole, rather than generated or sampled
  bool labelled; // its features are labelled (the replica's ball, sharp edges)
  std::function<Cloud()> make;
};

// Whether a diagnosis, which a term may be designed from, may read the
// input: not those held out for that term.
inline bool open_to_diagnosis(const Benchmark_input& input)
{
  return input.role != Input_role::held_out_next;
}

// The inputs of the quality tables, in their order: those the default mode
// was tuned on, those held out, those held out anew, those held out for the
// next term. The replicas and the
// mesh samples are divided in size by `scale`; the scans are read whole.
inline std::vector<Benchmark_input> benchmark_inputs(const std::string& data, std::size_t scale)
{
  std::vector<Benchmark_input> in;
  for (double noise : { 0.002, 0.0012 })
    in.push_back({ noise == 0.002 ? "replica_2mm" : "replica_1.2mm", Input_role::tuned, false, true,
                   [=] { return replica(noise, scale); } });
  const auto sample = [&](const std::string& name, std::size_t n, bool labelled, Input_role role) {
    return Benchmark_input{ name, role, false, labelled,
                            [=] { return mesh_sample(name, data + "/meshes/" + name + ".off", n / scale, labelled); } };
  };
  const auto read = [&](const std::string& file, Input_role role) {
    const std::string name = file.substr(0, file.find('.'));
    return Benchmark_input{ name, role, true, false, [=] { return scan(name, data + "/points_3/" + file); } };
  };
  in.push_back(sample("lion", 457124, false, Input_role::tuned));
  in.push_back(sample("fandisk", 200000, true, Input_role::tuned));
  in.push_back(read("b9_training.ply", Input_role::tuned));
  for (const std::string file : { "hippo1.ply", "oni.pwn", "radar.xyz" })
    in.push_back(read(file, Input_role::held_out));
  // named before the work on anisotropy (issue 12) began: three machined
  // parts whose sharp edges are labelled, a smooth animal, and two scans
  for (const std::string name : { "anchor", "rotor", "couplingdown" })
    in.push_back(sample(name, 100000, true, Input_role::held_out_anew));
  in.push_back(sample("armadillo", 100000, false, Input_role::held_out_anew));
  for (const std::string file : { "building.ply", "kitten.xyz" })
    in.push_back(read(file, Input_role::held_out_anew));
  // named before any term is designed from rotor's thin walls (rotor, held
  // out anew, was diagnosed): three machined parts whose sharp edges are
  // labelled, two animals and a scan
  for (const std::string name : { "turbine", "blade", "cheese" })
    in.push_back(sample(name, 100000, true, Input_role::held_out_next));
  for (const std::string name : { "bear", "camel" })
    in.push_back(sample(name, 100000, false, Input_role::held_out_next));
  in.push_back(read("hippo2.ply", Input_role::held_out_next));
  return in;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_INPUTS_H
