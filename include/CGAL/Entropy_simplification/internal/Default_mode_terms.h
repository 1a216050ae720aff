// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The terms the default mode is made of, each of which can be switched off
// to measure what it contributes.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_TERMS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_TERMS_H

#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// What the default mode is made of, besides the entropy term itself
// (Options::feature_weight, 0 to switch it off). Every public function runs
// with all of them; the benchmark's ablation (benchmark/bench_ablation.cpp)
// switches each off in turn, and the tests check each switch against the
// independent reference.
struct Default_mode_terms
{
  // the elimination is the greedy coverage elimination (see
  // Coverage_elimination), rather than Yuksel's weighted sample elimination
  // (2015) with a radius that follows the input's density (see
  // density_scale), in stages that halve the count (see next_stage)
  bool coverage_elimination = true;
  // the feature strength is the greater of the fine and the coarse scale's
  // (see coarse_feature_strength), rather than the fine scale's alone
  bool coarse_scale = true;
  // the feature weight is lowered where features cover much of the area
  // (see budgeted_feature_weight)
  bool feature_budget = true;
  // while more than 35% of the points are present, the greedy coverage
  // elimination weighs with the square of the feature strength (see
  // coverage_weights), so that weak features take fewer points
  bool strong_features_first = true;
  // the kept points are relocated in Lloyd's manner (see relocate_within_input);
  // a ranking's level boundaries are relocated either way (see Level_cells)
  bool relocation = true;
  // the relocation's cells keep their medians (see cell_median), rather than
  // their members nearest the centroids; a ranking's level boundaries take
  // medians either way (see Level_cells)
  bool medians = true;
  // no median moves a cell's radius beyond the greatest of the members
  // nearest the centroids (see greatest_squared_radius_about_centroids)
  bool radius_bound = true;
  // the relocated points end with a few swaps of the points farthest from
  // them for the most crowded of them (see swap_farthest_for_crowded); with
  // weighted sample elimination, a ranking's level boundaries are swapped
  // either way (see swap_among_neighbors)
  bool coverage_swaps = true;
};

// The terms with one of them switched off, and the name of that term.
struct Term_switched_off
{
  const char* term;
  Default_mode_terms terms;
};

// Each term switched off in turn, the elimination last: what the ablation
// runs.
inline std::vector<Term_switched_off> each_term_switched_off()
{
  std::vector<Term_switched_off> each;
  const auto off = [&each](const char* term, bool Default_mode_terms::*which) {
    Default_mode_terms terms;
    terms.*which = false;
    each.push_back({ term, terms });
  };
  off("coarse scale of the feature strength", &Default_mode_terms::coarse_scale);
  off("feature budget", &Default_mode_terms::feature_budget);
  off("square of the strength while most points are present", &Default_mode_terms::strong_features_first);
  off("relocation", &Default_mode_terms::relocation);
  off("medians (members nearest the centroids)", &Default_mode_terms::medians);
  off("radius bound of the medians", &Default_mode_terms::radius_bound);
  off("coverage swaps", &Default_mode_terms::coverage_swaps);
  off("greedy coverage elimination (weighted sample elimination)", &Default_mode_terms::coverage_elimination);
  return each;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_TERMS_H
