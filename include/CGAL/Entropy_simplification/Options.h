// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own options, shared by every function of the package.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_OPTIONS_H
#define CGAL_ENTROPY_SIMPLIFICATION_OPTIONS_H

#include <array>
#include <optional>

namespace CGAL {
namespace Entropy_simplification {

/*!
  \ingroup PkgEntropySimplificationRef
  Which end of the importance order (Eq. 5) is removed first.

  The paper's text says that a large entropy marks a feature point and that the
  least important point is removed first, which is `lowest_entropy_first`.
  Eq. 5 is largest where the normal angles of a neighbourhood are all equal, so
  that reading removes curved regions first; the user manual reports what both
  orders keep on the replica of the paper's Experiment I.
*/
enum class Removal_order
{
  lowest_entropy_first,  ///< remove the point of least entropy first (the paper's text)
  highest_entropy_first  ///< remove the point of greatest entropy first
};

/*!
  \ingroup PkgEntropySimplificationRef
  How a normal is estimated from a point and its `k` nearest neighbours.
*/
enum class Normal_estimation
{
  pca, ///< the plane fitted by least squares (Eq. 1-2), as `CGAL::pca_estimate_normals()`
  jet  ///< a jet of degree 2 fitted with `CGAL::Monge_via_jet_fitting`, as `CGAL::jet_estimate_normals()`; needs `k >= 5`
};

/*!
  \ingroup PkgEntropySimplificationRef
  The simplification method.
*/
enum class Mode
{
  /// The default: a greedy elimination that removes the points whose removal
  /// raises least the distances from the input to the kept points, weighted
  /// up where the entropy of the normals of a neighbourhood marks a feature,
  /// so that features keep more points and flat regions thin evenly,
  /// without holes. (The name is that of the weighted sample elimination,
  /// Yuksel 2015, that the mode ran before; see the user manual.)
  weighted_elimination,
  /// The method of the paper (Eq. 1-5), with exact progressive updates.
  paper
};

/*!
  \ingroup PkgEntropySimplificationRef
  The package's own options, all in one place.

  Every function of the package takes an `Options` as its last, optional
  argument; the fields it does not use are documented as such. An option is a
  member, so a misspelt option is a compilation error rather than an option
  silently ignored.
*/
struct Options
{
  /// the simplification method
  Mode mode = Mode::weighted_elimination;

  /// `Mode::paper` only: which end of the importance order is removed first
  Removal_order removal_order = Removal_order::lowest_entropy_first;

  /// how normals are estimated (in `Mode::paper`, also after each removal)
  Normal_estimation normal_estimation = Normal_estimation::pca;

  /*!
    `Mode::weighted_elimination` only: how much denser features are kept. The
    kept density grows by up to `1 + feature_weight` where the entropy of the
    normals marks a feature. Where more than 15% of the area, counted by
    feature strength, is marked (on noisy scans, a third of the area can have
    a high entropy), the weight is scaled down in proportion, so that the
    features take at most `0.15 * feature_weight` more points than the flat
    regions would: 45% at the default. A greater weight therefore always
    raises the density aimed at on features, at a cost in mean distance that
    `benchmark/RESULTS.md` measures (section "Feature emphasis against
    coverage"). 0 switches the entropy term off: every input point then
    weighs the same in the distances the elimination keeps low. Must lie in
    [0, 100].
  */
  double feature_weight = 3.;

  /// the largest `feature_weight` accepted
  static constexpr double largest_feature_weight = 100.;

  /*!
    `Mode::paper` and the accuracy indicator only: the normal of the reference
    plane of Eq. 4. When empty (the default), it is
    the normal of the plane that `CGAL::linear_least_squares_fitting_3()` fits
    to all the points given to the function (Eq. 3), computed once. Set it, for
    example, to measure several simplified clouds against the plane of their
    common input. It need not be unit; it must not be null.
  */
  std::optional<std::array<double, 3> > reference_normal;
};

} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_OPTIONS_H
