// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A synthetic replica of the paper's Experiment I scan.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_EXPERIMENT_I_REPLICA_H
#define CGAL_ENTROPY_SIMPLIFICATION_EXPERIMENT_I_REPLICA_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {

/*!
  \ingroup PkgEntropySimplificationRef
  The scene and the scanner of the replica of the paper's Experiment I. The
  defaults are the paper's: a basketball in front of a plane board, 147,876
  board points and 34,315 ball points. Lengths are in metres.
*/
struct Experiment_I_setup
{
  double range_noise = 0.002;          ///< standard deviation of the Gaussian range noise
  std::size_t board_points = 147876;   ///< exact number of points on the board
  std::size_t sphere_points = 34315;   ///< exact number of points on the ball
  double board_size = 0.6;             ///< side of the square board
  double board_distance = 1.5;         ///< the board lies in the plane `z = board_distance`
  double sphere_radius = 0.1205;       ///< radius of the ball
  double sphere_gap = 0.25;            ///< distance from the ball's centre to the board
  double sphere_x = 0.03;              ///< x of the ball's centre (the board is centred on the z axis)
  double sphere_y = -0.02;             ///< y of the ball's centre
  std::uint64_t seed = 2018;           ///< seed of the noise and of the choice of dropped hits
};

/// \ingroup PkgEntropySimplificationRef
/// The label of a replica point on the board.
constexpr int board_label = 0;
/// \ingroup PkgEntropySimplificationRef
/// The label of a replica point on the ball.
constexpr int sphere_label = 1;

/// \cond SKIP_IN_MANUAL
namespace internal {

// Uniform and Gaussian draws defined here rather than by the standard
// library, whose distributions differ between implementations: the replica
// must be the same everywhere.
class Portable_random
{
public:
  explicit Portable_random(std::uint64_t seed) : m_engine(seed) {}

  // uniform in [0, 1)
  double uniform() { return double(m_engine() >> 11) * (1. / 9007199254740992.); }

  // uniform in [0, n), without modulo bias
  std::size_t below(std::size_t n)
  {
    const std::uint64_t limit = ~std::uint64_t(0) - ~std::uint64_t(0) % n;
    std::uint64_t draw;
    do
      draw = m_engine();
    while (draw >= limit);
    return std::size_t(draw % n);
  }

  // standard normal, by Box-Muller
  double gaussian()
  {
    const double u = 1. - uniform(); // in (0, 1]
    const double v = uniform();
    return std::sqrt(-2. * std::log(u)) * std::cos(6.283185307179586 * v);
  }

private:
  std::mt19937_64 m_engine;
};

struct Ray_hit
{
  double range;
  int label;
};

// The first surface hit by the ray from the origin along the unit vector d.
inline std::optional<Ray_hit> first_hit(const Experiment_I_setup& s, const double d[3])
{
  const double c[3] = { s.sphere_x, s.sphere_y, s.board_distance - s.sphere_gap };
  const double along = d[0] * c[0] + d[1] * c[1] + d[2] * c[2];
  const double discriminant =
    along * along - (c[0] * c[0] + c[1] * c[1] + c[2] * c[2] - s.sphere_radius * s.sphere_radius);
  if (discriminant >= 0. && along - std::sqrt(discriminant) > 0.)
    return Ray_hit{ along - std::sqrt(discriminant), sphere_label };
  const double t = s.board_distance / d[2];
  const double half = s.board_size / 2.;
  if (std::abs(t * d[0]) <= half && std::abs(t * d[1]) <= half)
    return Ray_hit{ t, board_label };
  return std::nullopt;
}

// The hits of a scan with angular step `step`, in scan order: columns of
// constant azimuth, each swept in elevation.
inline std::vector<std::pair<std::array<double, 3>, Ray_hit> > scan(const Experiment_I_setup& s, double step)
{
  std::vector<std::pair<std::array<double, 3>, Ray_hit> > hits;
  const double half_angle = std::atan(s.board_size / 2. / s.board_distance) * 1.05;
  const long half_steps = long(std::ceil(half_angle / step));
  for (long i = -half_steps; i <= half_steps; ++i)
    for (long j = -half_steps; j <= half_steps; ++j)
    {
      const double azimuth = double(i) * step, elevation = double(j) * step;
      const double d[3] = { std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                            std::cos(azimuth) * std::cos(elevation) };
      if (const std::optional<Ray_hit> hit = first_hit(s, d))
        hits.push_back({ { d[0], d[1], d[2] }, *hit });
    }
  return hits;
}

} // namespace internal
/// \endcond

/*!
  \ingroup PkgEntropySimplificationRef

  Generates a replica of the scan of the paper's Experiment I.

  A scanner at the origin looks along `+z` and samples a regular grid of
  directions (azimuth and elevation in equal angular steps). A square board
  of side `setup.board_size` lies in the plane `z = setup.board_distance`,
  centred on the `z` axis; a ball of radius `setup.sphere_radius` is centred
  `setup.sphere_gap` in front of it, near its centre. Each ray records its
  first hit, displaced along the ray by a Gaussian range noise of standard
  deviation `setup.range_noise`. The angular step is the largest of the
  sequence `s0 * 0.995^i` that yields at least the requested number of hits on
  each object; the surplus hits of each object are then dropped uniformly at
  random, so the counts are exact. Every draw comes from `setup.seed` with
  portable algorithms, so the replica is the same on every platform.

  The points are written in scan order, each with its label:
  `board_label` or `sphere_label`.

  \tparam Point_3 a point type constructible from three `double`
  \tparam OutputIterator an output iterator accepting `std::pair<Point_3, int>`

  \param output where the labelled points are written
  \param setup the scene, the noise and the seed

  \return the output iterator past the last point written

  \throw std::invalid_argument if a count is zero or a length is not positive
*/
template <typename Point_3, typename OutputIterator>
OutputIterator experiment_I_replica(OutputIterator output, const Experiment_I_setup& setup = Experiment_I_setup())
{
  if (setup.board_points == 0 || setup.sphere_points == 0 || !(setup.board_size > 0.) ||
      !(setup.board_distance > 0.) || !(setup.sphere_radius > 0.) || !(setup.range_noise >= 0.) ||
      !(setup.sphere_gap > setup.sphere_radius) || !(setup.sphere_gap < setup.board_distance))
    throw std::invalid_argument("experiment_I_replica: invalid setup");

  const std::size_t wanted[2] = { setup.board_points, setup.sphere_points };
  // A first step that gives roughly the wanted density on the board.
  double step = setup.board_size / setup.board_distance / std::sqrt(double(setup.board_points));
  std::vector<std::pair<std::array<double, 3>, internal::Ray_hit> > hits;
  for (;; step *= 0.995)
  {
    hits = internal::scan(setup, step);
    std::size_t count[2] = { 0, 0 };
    for (const auto& h : hits)
      ++count[h.second.label];
    if (count[0] >= wanted[0] && count[1] >= wanted[1])
      break;
  }

  internal::Portable_random random(setup.seed);
  for (int label : { board_label, sphere_label })
  {
    std::vector<std::size_t> of_label;
    for (std::size_t i = 0; i < hits.size(); ++i)
      if (hits[i].second.label == label)
        of_label.push_back(i);
    // a partial Fisher-Yates shuffle picks the hits to drop
    const std::size_t surplus = of_label.size() - wanted[label];
    for (std::size_t i = 0; i < surplus; ++i)
    {
      std::swap(of_label[i], of_label[i + random.below(of_label.size() - i)]);
      hits[of_label[i]].second.label = -1;
    }
  }

  for (const auto& h : hits)
  {
    if (h.second.label < 0)
      continue;
    const double range = h.second.range + setup.range_noise * random.gaussian();
    *output++ = std::make_pair(Point_3(range * h.first[0], range * h.first[1], range * h.first[2]),
                               h.second.label);
  }
  return output;
}

} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_EXPERIMENT_I_REPLICA_H
