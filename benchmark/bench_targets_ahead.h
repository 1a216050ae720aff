// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode against issue 12's targets, cell by cell: ahead of the
// best peer of every library on mean distance and point-to-plane error, of
// grid on Hausdorff distance, and the feature shares of the labelled inputs.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_TARGETS_AHEAD_H
#define ENTROPY_SIMPLIFICATION_BENCH_TARGETS_AHEAD_H

#include "bench_report.h"
#include "bench_targets.h"

#include <ostream>
#include <string>
#include <vector>

namespace bench {

// Issue 12's bounds.
constexpr double ahead_mean = 1.0, ahead_point_to_plane = 0.9, ahead_hausdorff = 1.0;

// The share a labelled input must keep at a ratio, or 0 where none is set:
// fandisk's sharp edges, and the ball of the 1.2 mm replica at 10%.
inline double share_bound(const std::string& input, double ratio)
{
  if (input == "fandisk")
    return ratio < 50. ? 2.5 : 1.7;
  if (input == "replica_1.2mm" && ratio == 10.)
    return 1.6;
  return 0.;
}

// Misses, per metric, in one group of inputs.
struct Ahead_count
{
  int cells = 0, mean = 0, point_to_plane = 0, hausdorff = 0, share = 0, shares_set = 0;
};

// One row per cell of the group; returns its misses.
inline Ahead_count ahead_table(std::ostream& md, const Report& r, const std::vector<const Input_summary*>& group)
{
  Ahead_count count;
  md << "| input | kept | mean / best peer (≤ 1.0) | point-to-plane / best peer (≤ 0.9) | Hausdorff / grid (≤ 1.0) "
        "| labelled share / input's |\n|---|---:|---|---|---|---|\n";
  const auto mean = [](const Quality& q) { return q.mean; };
  const auto plane = [](const Quality& q) { return q.point_to_plane; };
  for (const Input_summary* s : group)
    for (double ratio : target_ratios)
    {
      const Quality_row* q = find_row(r, s->name, "package default", ratio);
      const Quality_row* grid = find_row(r, s->name, "CGAL grid", ratio);
      const Quality_row* best_mean = best_library_peer(r, s->name, ratio, mean);
      const Quality_row* best_plane = best_library_peer(r, s->name, ratio, plane);
      if (!q || !grid || !best_mean || !best_plane)
        continue;
      ++count.cells;
      const double m = q->quality.mean / best_mean->quality.mean;
      const double p = q->quality.point_to_plane / best_plane->quality.point_to_plane;
      const double h = q->quality.max / grid->quality.max;
      count.mean += m > ahead_mean;
      count.point_to_plane += p > ahead_point_to_plane;
      count.hausdorff += h > ahead_hausdorff;
      std::string share;
      if (s->labelled > 0)
      {
        const double ratio_of_shares = share_ratio(*s, *q), bound = share_bound(s->name, ratio);
        share = bound > 0. ? checked(ratio_of_shares, bound, false) + " (≥ " + fixed(bound, 1) + ")"
                           : fixed(ratio_of_shares, 3) + " (no target)";
        count.shares_set += bound > 0.;
        count.share += bound > 0. && ratio_of_shares < bound;
      }
      md << "| " << s->name << " | " << ratio << "% | " << checked(m, ahead_mean) << " (" << peer_name(*best_mean)
         << ") | " << checked(p, ahead_point_to_plane) << " (" << peer_name(*best_plane) << ") | "
         << checked(h, ahead_hausdorff) << " | " << share << " |\n";
    }
  md << "\n";
  return count;
}

inline void ahead_group(std::ostream& md, const Report& r, const std::vector<const Input_summary*>& group,
                        const std::string& heading)
{
  if (group.empty())
    return;
  md << heading;
  const Ahead_count c = ahead_table(md, r, group);
  md << "Met in " << c.cells - c.mean << " of " << c.cells << " cells for the mean distance, "
     << c.cells - c.point_to_plane << " for the point-to-plane error and " << c.cells - c.hausdorff
     << " for the Hausdorff distance";
  if (c.shares_set > 0)
    md << "; " << c.shares_set - c.share << " of " << c.shares_set << " share targets";
  md << ".\n\n";
}

// The section, the inputs of each role apart.
inline void write_targets_ahead(std::ostream& md, const Report& r)
{
  const Inputs_by_role groups = inputs_by_role(r);
  if (groups.empty())
    return;
  md << "## The default mode against issue 12's targets\n\n"
     << "Issue 12 sets the bar higher than the targets above: in every cell, a mean distance at most the best "
        "peer's and a point-to-plane error at most 0.9 times it, the peers being every library's simplifier that "
        "ran in the cell (as in the previous section), a Hausdorff distance at most grid's, and on the labelled "
        "inputs at least 2.5 times the input's share of points near fandisk's sharp edges at 10 and 20% (1.7 at "
        "50%) and 1.6 times its share on the 1.2 mm replica's ball at 10%. The other labelled shares are reported "
        "without a target. Why the mean distance and the shares pull against each other: section \"Feature "
        "emphasis against coverage\"; what the point-to-plane error rewards on noisy inputs: section "
        "\"Point-to-plane error and noise\".\n\n";
  ahead_group(md, r, groups.tuned, "### Inputs the mode was tuned on\n\n");
  ahead_group(md, r, groups.held_out, "### Held-out inputs\n\n");
  ahead_group(md, r, groups.held_out_anew, "### Inputs held out anew\n\n");
  ahead_group(md, r, groups.held_out_next, "### Inputs held out for the next term\n\n");
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_TARGETS_AHEAD_H
