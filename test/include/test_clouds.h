// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small seeded point clouds for the tests.

#ifndef ENTROPY_SIMPLIFICATION_TEST_CLOUDS_H
#define ENTROPY_SIMPLIFICATION_TEST_CLOUDS_H

#include <CGAL/Entropy_simplification/experiment_I_replica.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <string>
#include <vector>

namespace test_clouds {

using Point = CGAL::Simple_cartesian<double>::Point_3;
using Random = CGAL::Entropy_simplification::internal::Portable_random;

struct Cloud
{
  std::string name;
  std::vector<Point> points;
};

// A miniature of the paper's Experiment I: a noisy ball in front of a board.
inline Cloud small_replica(std::size_t board, std::size_t sphere, double noise, std::uint64_t seed)
{
  CGAL::Entropy_simplification::Experiment_I_setup setup;
  setup.board_points = board;
  setup.sphere_points = sphere;
  setup.range_noise = noise;
  setup.seed = seed;
  std::vector<std::pair<Point, int> > labelled;
  CGAL::Entropy_simplification::experiment_I_replica<Point>(std::back_inserter(labelled), setup);
  Cloud c{ "replica " + std::to_string(board + sphere) + " noise " + std::to_string(noise), {} };
  for (const auto& p : labelled)
    c.points.push_back(p.first);
  return c;
}

// A noisy height field z = f(x, y) with random (x, y).
inline Cloud wavy_surface(std::size_t n, double noise, std::uint64_t seed)
{
  Random random(seed);
  Cloud c{ "wavy surface " + std::to_string(n), {} };
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = random.uniform(), y = random.uniform();
    const double z = 0.2 * std::sin(6. * x) * std::cos(5. * y) + noise * random.gaussian();
    c.points.emplace_back(x, y, z);
  }
  return c;
}

// A wavy patch with `count` small islands of `per_island` points beyond it,
// in a row, listed first: the stages of a ranking empty the islands, whose
// points then have no present point within their reach.
inline Cloud wavy_with_islands(std::size_t n, std::size_t count, std::size_t per_island, std::uint64_t seed)
{
  Cloud patch = wavy_surface(n, 0.01, seed);
  Random random(seed + 1);
  Cloud c{ "wavy surface " + std::to_string(n) + " with " + std::to_string(count) + " islands", {} };
  for (std::size_t k = 0; k < count; ++k)
  {
    const double x = 2. + 0.5 * double(k), y = 3. * random.uniform();
    for (std::size_t j = 0; j < per_island; ++j)
      c.points.emplace_back(x + 0.03 * random.uniform(), y + 0.03 * random.uniform(), 0.03 * random.uniform());
  }
  c.points.insert(c.points.end(), patch.points.begin(), patch.points.end());
  return c;
}

// Points uniform in a cube: no surface at all.
inline Cloud cube_volume(std::size_t n, std::uint64_t seed)
{
  Random random(seed);
  Cloud c{ "cube volume " + std::to_string(n), {} };
  for (std::size_t i = 0; i < n; ++i)
    c.points.emplace_back(random.uniform(), random.uniform(), random.uniform());
  return c;
}

// A regular grid on a bent sheet: many exactly tied distances.
inline Cloud bent_grid(std::size_t side)
{
  Cloud c{ "bent grid " + std::to_string(side * side), {} };
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j)
    {
      const double x = double(i) / double(side), y = double(j) / double(side);
      c.points.emplace_back(x, y, x < 0.5 ? 0. : (x - 0.5));
    }
  return c;
}

// A noisy surface where every point appears two or three times.
inline Cloud with_duplicates(std::size_t n, std::uint64_t seed)
{
  Cloud base = wavy_surface(n, 0.01, seed);
  Cloud c{ "duplicates " + std::to_string(n), {} };
  for (std::size_t i = 0; i < base.points.size(); ++i)
  {
    c.points.push_back(base.points[i]);
    c.points.push_back(base.points[i]);
    if (i % 3 == 0)
      c.points.push_back(base.points[i]);
  }
  return c;
}

} // namespace test_clouds

#endif // ENTROPY_SIMPLIFICATION_TEST_CLOUDS_H
