// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The field the default mode's elimination follows: each point's normal and
// the factor of its interaction radius, from the entropy of the normals of
// its neighbourhood at two scales and from the input's local density.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ELIMINATION_FIELD_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ELIMINATION_FIELD_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_terms.h>
#include <CGAL/Entropy_simplification/internal/Feature_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// What the elimination needs of each point, computed once on the input from
// its k nearest neighbours: the factor of its interaction radius (1 off
// features, smaller on them). The normals it is computed from are not kept:
// only the kept points' are written, estimated again at the end.
struct Elimination_field
{
  Array<double> scale;
  // the area the points sample, each point's share weighted by the density
  // its scale asks for (1 / scale^2)
  double effective_area = 0.;
  // the feature weight w after the budget (see budgeted_feature_weight)
  double feature_weight = 0.;
};

// The entropy of the normals of each point of `subset`'s neighbourhood,
// `neighbors(i)` giving the k nearest neighbours of point `i` nearest first;
// the normals, estimated on each point and its neighbours, go to `normals`.
// Both are stored at `slot(i)`, so that a subset needs arrays of its size.
template <typename ConcurrencyTag, typename NeighborsOf, typename SlotOf, typename Progress>
bool estimate_normal_entropy(const Indexed_points& points, const Array<Index>& subset, unsigned int k,
                             Normal_estimation estimation, const NeighborsOf& neighbors, const SlotOf& slot,
                             Array<Working_vector>& normals, Array<double>& entropy,
                             const Progress& progress)
{
  const std::size_t m = subset.size();
  if (!for_each_index<ConcurrencyTag>(
        m,
        [&](std::size_t r) {
          const Index i = subset[r];
          normals[slot(i)] = neighborhood_normal(points, i, neighbors(i), k, estimation);
        },
        [&](std::size_t done) { return progress(0.5 * double(done) / double(m)); }))
    return false;
  return for_each_index<ConcurrencyTag>(
    m,
    [&](std::size_t r) {
      const Index i = subset[r];
      const Index* near = neighbors(i);
      entropy[slot(i)] = normal_tensor_entropy(k + 1, [&](std::size_t j) -> const Working_vector& {
        return normals[slot(j == 0 ? i : near[j - 1])];
      });
    },
    [&](std::size_t done) { return progress(0.5 + 0.5 * double(done) / double(m)); });
}

// The feature strength at a coarse scale, for every point, to `strength`:
// that of its nearest point of `coarse`, whose normals and entropies are
// computed among the coarse points only, times coarse_strength_share. Their
// neighbourhoods are wider, so that a smooth curvature that scanner noise
// hides at the fine scale shows there. With a large k this takes seconds, hence the progress: its three
// passes count for a third each; returns false when it asked to stop.
template <typename ConcurrencyTag, typename Progress>
bool coarse_feature_strength(const Indexed_points& points, const Array<Index>& coarse, unsigned int k,
                             Normal_estimation estimation, Array<double>& strength, const Progress& progress)
{
  const std::size_t n = points.size();
  strength.assign(n, 0.);
  if (coarse.size() < std::size_t(k) + 1)
    return progress(1.);
  const Point_tree tree(points, coarse.begin(), coarse.end(), ConcurrencyTag());
  Array<Index> knn;
  if (!nearest_neighbor_table<ConcurrencyTag>(tree, coarse, k, knn, [&](std::size_t done) {
        return progress(double(done) / double(coarse.size()) / 3.);
      }))
    return false;
  // the position of each coarse point in `coarse`, one past the end for the others
  Array<Index> slot(n, Index(coarse.size()));
  for (std::size_t r = 0; r < coarse.size(); ++r)
    slot[coarse[r]] = Index(r);
  // the coarse points' normals and entropies, by slot
  Array<Working_vector> normals(coarse.size(), CGAL::NULL_VECTOR);
  Array<double> entropy(coarse.size(), 0.);
  if (!estimate_normal_entropy<ConcurrencyTag>(
        points, coarse, k, estimation, [&](Index i) { return &knn[std::size_t(slot[i]) * k]; },
        [&](Index i) { return slot[i]; }, normals, entropy, [&](double f) { return progress((1. + f) / 3.); }))
    return false;
  const double floor = entropy_noise_floor(entropy);
  return for_each_index<ConcurrencyTag>(
    n,
    [&](std::size_t i) {
      // a coarse point is its own nearest, which the search leaves out
      const Index c = slot[i] == coarse.size() ? tree.nearest_one(Index(i)) : Index(i);
      strength[i] = coarse_strength_share * feature_strength(entropy[slot[c]], floor);
    },
    [&](std::size_t done) { return progress((2. + double(done) / double(n)) / 3.); });
}

// The area each point samples: k points in a disc of the radius of its k-th
// nearest neighbour.
template <typename ConcurrencyTag, typename NeighborsOf>
Array<double> sampled_areas(const Indexed_points& points, unsigned int k, const NeighborsOf& neighbors)
{
  Array<double> area(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) {
      area[i] = CGAL_PI * squared_distance(points.points[i], points.points[neighbors(Index(i))[k - 1]]) / double(k);
    },
    [](std::size_t) { return true; });
  return area;
}

// The most a point's sampled area counts for, in medians. An isolated point,
// such as a stray return far from a scan, samples a disc as wide as its
// distance to the rest; counted in full, one such point widens every stage's
// radius until each point reaches most others, and the run turns quadratic
// in time and memory. The sparsest points of the benchmark's real scans
// sample up to 812 medians (radar), which the cap leaves counted in full.
constexpr double largest_area_in_medians = 1000.;

// Lowers the areas above `largest_area_in_medians` medians to that bound.
template <typename ConcurrencyTag>
void cap_isolated_areas(Array<double>& area)
{
  if (area.empty())
    return;
  const double largest = largest_area_in_medians * median(area);
  for_each_index<ConcurrencyTag>(
    area.size(), [&](std::size_t i) { area[i] = (std::min)(area[i], largest); }, [](std::size_t) { return true; });
}

// `x` with its significand rounded to 30 bits, a relative change below
// 1e-9. The scales are rounded so because, computed by other means (the
// tests' reference) or with other floating-point contractions, they differ
// in their last bits: the integer weights built from them then round
// differently, and a tie of weight sums, as on a regular grid, may break the
// other way. Rounded, they agree unless one lies within those last bits of a
// rounding boundary.
inline double with_30_bit_significand(double x)
{
  int exponent = 0;
  const double significand = std::frexp(x, &exponent);
  return std::ldexp(std::round(std::ldexp(significand, 30)), exponent - 30);
}

// The factor of each point's interaction radius: the feature term, whose
// weight the budget may lower (unless `terms` switch the budget off), times
// the density term with weighted sample elimination only (the greedy
// coverage elimination's sum of distances follows the input's density
// itself), rounded to 30 bits. Also sets the effective area, the
// sampled area weighted by the density each scale asks for (1 / scale^2),
// summed in input order so that it does not depend on the internal order.
template <typename ConcurrencyTag>
void set_scales(const Indexed_points& points, const Array<double>& area, const Array<double>& strength,
                double feature_weight, const Default_mode_terms& terms, Elimination_field& field)
{
  const std::size_t n = points.size();
  double total_area = 0., feature_area = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    total_area += area[i];
    feature_area += area[i] * strength[i];
  }
  const double weight =
    terms.feature_budget ? budgeted_feature_weight(feature_weight, feature_area, total_area) : feature_weight;
  const double typical_area = median(area);

  field.feature_weight = weight;
  field.scale.resize(n);
  Array<double> weighted_area(n);
  for_each_index<ConcurrencyTag>(
    n,
    [&](std::size_t i) {
      field.scale[i] = with_30_bit_significand(interaction_scale(strength[i], weight) *
                                               (terms.coverage_elimination ? 1. : density_scale(area[i], typical_area)));
      weighted_area[points.input_position[i]] = area[i] / (field.scale[i] * field.scale[i]);
    },
    [](std::size_t) { return true; });
  field.effective_area = 0.;
  for (double a : weighted_area)
    field.effective_area += a;
}

// The k nearest neighbours of every point, nearest first (those of point i
// at knn[i * k]).
template <typename ConcurrencyTag, typename Progress>
bool nearest_neighbors_of_all(const Indexed_points& points, unsigned int k, Array<Index>& knn,
                              const Progress& progress)
{
  const Array<Index> all = all_indices(points.size());
  const Point_tree tree(points, all.begin(), all.end(), ConcurrencyTag());
  return nearest_neighbor_table<ConcurrencyTag>(tree, all, k, knn, [&](std::size_t done) {
    return progress(double(done) / double(points.size()));
  });
}

// The entropy of the normals of every point's neighbourhood, from `knn`;
// the normals are estimated on the way and not kept.
template <typename ConcurrencyTag, typename Progress>
bool normal_entropy_of_all(const Indexed_points& points, unsigned int k, Normal_estimation estimation,
                           const Array<Index>& knn, Array<double>& entropy, const Progress& progress)
{
  const std::size_t n = points.size();
  Array<Working_vector> normals(n, CGAL::NULL_VECTOR);
  entropy.assign(n, 0.);
  return estimate_normal_entropy<ConcurrencyTag>(
    points, all_indices(n), k, estimation, [&](Index i) { return &knn[std::size_t(i) * k]; },
    [](Index i) { return i; }, normals, entropy, progress);
}

// The points of the coarse scale: from each block of `coarse_stride` points
// of the kd order, the one whose input position scrambles lowest.
inline Array<Index> coarse_points(const Indexed_points& points)
{
  Array<Index> coarse;
  for (std::size_t first = 0; first < points.size(); first += coarse_stride)
  {
    Index drawn = Index(first);
    for (std::size_t i = first + 1; i < (std::min)(points.size(), first + coarse_stride); ++i)
      if (scrambled(points.input_position[i]) < scrambled(points.input_position[drawn]))
        drawn = Index(i);
    coarse.push_back(drawn);
  }
  return coarse;
}

// The feature strength of every point, to `strength`, from the entropy of
// the normals of its neighbourhood: the greater of that of `entropy`, at the
// scale of k, and that of the coarse scale (see coarse_points), unless
// `with_coarse_scale` is false. `progress` receives the fraction done;
// returns false when it asked to stop.
template <typename ConcurrencyTag, typename Progress>
bool feature_strengths(const Indexed_points& points, unsigned int k, Normal_estimation estimation,
                       const Array<double>& entropy, bool with_coarse_scale, Array<double>& strength,
                       const Progress& progress)
{
  if (!with_coarse_scale)
    strength.assign(points.size(), 0.);
  else if (!coarse_feature_strength<ConcurrencyTag>(points, coarse_points(points), k, estimation, strength,
                                                    progress))
    return false;
  const double floor = entropy_noise_floor(entropy);
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) { strength[i] = (std::max)(feature_strength(entropy[i], floor), strength[i]); },
    [](std::size_t) { return true; });
  return true;
}

// What an elimination keeps of the k nearest neighbours of each point: the
// first `count`, those of point i at columns[i * count], and the first
// neighbours as offsets (see Neighbor_offsets); none when count is 0 or
// above k.
struct First_neighbors
{
  Array<Index> columns;
  Neighbor_offsets offsets;
};

template <typename ConcurrencyTag>
First_neighbors first_neighbors(const Array<Index>& knn, unsigned int k, std::size_t count)
{
  if (count == 0 || count > k)
    return {};
  First_neighbors first{ Array<Index>(knn.size() / k * count), Neighbor_offsets(knn, k, ConcurrencyTag()) };
  for_each_index<ConcurrencyTag>(
    knn.size() / k,
    [&](std::size_t i) {
      std::copy_n(knn.begin() + std::ptrdiff_t(i * k), count, first.columns.begin() + std::ptrdiff_t(i * count));
    },
    [](std::size_t) { return true; });
  return first;
}

// The field from `knn`, the k nearest neighbours of each point nearest first
// (those of point i at knn[i * k]), which it frees once used, keeping to
// `first` what an elimination that follows `first_count` neighbours of
// each point needs of them (see first_neighbors), once the normals it
// estimated on the way are freed too: the feature strengths and the areas
// the points sample make the scales, with the `terms` switched on. The
// entropies count for 60% of the progress, the coarse scale for the rest.
template <typename ConcurrencyTag, typename Progress>
bool compute_elimination_field(const Indexed_points& points, unsigned int k, const Options& options,
                               const Default_mode_terms& terms, Array<Index> knn, std::size_t first_count,
                               First_neighbors& first, Elimination_field& field, const Progress& progress)
{
  Array<double> entropy;
  if (!normal_entropy_of_all<ConcurrencyTag>(points, k, options.normal_estimation, knn, entropy,
                                             [&](double f) { return progress(0.6 * f); }))
    return false;
  Array<double> area =
    sampled_areas<ConcurrencyTag>(points, k, [&](Index i) { return &knn[std::size_t(i) * k]; });
  cap_isolated_areas<ConcurrencyTag>(area);
  first = first_neighbors<ConcurrencyTag>(knn, k, first_count);
  Array<Index>().swap(knn);
  Array<double> strength;
  if (!feature_strengths<ConcurrencyTag>(points, k, options.normal_estimation, entropy, terms.coarse_scale, strength,
                                         [&](double f) { return progress(0.6 + 0.4 * f); }))
    return false;
  Array<double>().swap(entropy);
  set_scales<ConcurrencyTag>(points, area, strength, options.feature_weight, terms, field);
  return true;
}

// The feature strength of every point, which is the default mode's
// importance, computed as the field computes it; empty when `progress`
// asked to stop.
template <typename ConcurrencyTag, typename Progress>
Array<double> feature_strength_of_all(const Indexed_points& points, unsigned int k, const Options& options,
                                            const Progress& progress)
{
  Array<Index> knn;
  Array<double> entropy, strength;
  if (!nearest_neighbors_of_all<ConcurrencyTag>(points, k, knn, [&](double f) { return progress(0.4 * f); }) ||
      !normal_entropy_of_all<ConcurrencyTag>(points, k, options.normal_estimation, knn, entropy,
                                             [&](double f) { return progress(0.4 + 0.3 * f); }))
    return {};
  Array<Index>().swap(knn);
  if (!feature_strengths<ConcurrencyTag>(points, k, options.normal_estimation, entropy,
                                         Default_mode_terms().coarse_scale, strength,
                                         [&](double f) { return progress(0.7 + 0.3 * f); }))
    return {};
  return strength;
}

// The normal of each point of `subset`, estimated on it and its k nearest
// neighbours among all the points, as the field estimates it.
template <typename ConcurrencyTag>
Array<Working_vector> estimate_normals(const Indexed_points& points, const Array<Index>& subset,
                                             unsigned int k, Normal_estimation estimation)
{
  const Array<Index> all = all_indices(points.size());
  const Point_tree tree(points, all.begin(), all.end(), ConcurrencyTag());
  Array<Index> knn;
  nearest_neighbor_table<ConcurrencyTag>(tree, subset, k, knn, [](std::size_t) { return true; });
  Array<Working_vector> normals(subset.size());
  for_each_index<ConcurrencyTag>(
    subset.size(),
    [&](std::size_t r) { normals[r] = neighborhood_normal(points, subset[r], &knn[r * k], k, estimation); },
    [](std::size_t) { return true; });
  return normals;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ELIMINATION_FIELD_H
