// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode against its targets (issue 4): per input and ratio, its
// metrics as ratios to CGAL's grid, hierarchy and WLOP, each target checked;
// then the same metrics against the best peer of every library built.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_TARGETS_H
#define ENTROPY_SIMPLIFICATION_BENCH_TARGETS_H

#include "bench_report.h"

#include <algorithm>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace bench {

const std::vector<std::string> cgal_peers = { "CGAL grid", "CGAL hierarchy", "CGAL WLOP" };
const std::vector<double> target_ratios = { 10., 20., 50. };

// The smallest value of a metric among the CGAL peers that ran, and whose it is.
template <typename Metric>
std::pair<double, std::string> best_peer(const Report& r, const std::string& input, double ratio, const Metric& metric)
{
  std::pair<double, std::string> best{ std::numeric_limits<double>::infinity(), "" };
  for (const std::string& peer : cgal_peers)
    if (const Quality_row* q = find_row(r, input, peer, ratio))
      if (metric(q->quality) < best.first)
        best = { metric(q->quality), peer.substr(5) };
  return best;
}

inline std::string checked(double value, double limit, bool at_most = true)
{
  const bool met = at_most ? value <= limit : value >= limit;
  return fixed(value, 3) + (met ? " ✓" : " **miss**");
}

// The share of kept points labelled 1, over the input's share.
inline double share_ratio(const Input_summary& s, const Quality_row& q)
{
  return (double(q.quality.labelled) / double(q.count)) / (double(s.labelled) / double(s.size));
}

// The table of one group of inputs, then a line on each miss; returns the
// number of misses.
inline int targets_table(std::ostream& md, const Report& r, const std::vector<const Input_summary*>& inputs)
{
  int misses = 0;
  std::vector<std::string> explained;
  md << "| input | kept | mean / best CGAL (≤ 1.1) | Hausdorff / grid (≤ 1.5) | point-to-plane / best CGAL (≤ 1.05) "
        "| lowest point-to-plane of all four | feature share / input's | without entropy term: mean, "
        "point-to-plane, share |\n|---|---:|---|---|---|---|---|---|\n";
  for (const Input_summary* s : inputs)
    for (double ratio : target_ratios)
    {
      const Quality_row* q = find_row(r, s->name, "package default", ratio);
      const Quality_row* grid = find_row(r, s->name, "CGAL grid", ratio);
      if (!q || !grid)
        continue;
      const auto mean = best_peer(r, s->name, ratio, [](const Quality& x) { return x.mean; });
      const auto p2p = best_peer(r, s->name, ratio, [](const Quality& x) { return x.point_to_plane; });
      const double mean_ratio = q->quality.mean / mean.first;
      const double hausdorff_ratio = q->quality.max / grid->quality.max;
      const double p2p_ratio = q->quality.point_to_plane / p2p.first;
      misses += (mean_ratio > 1.1) + (hausdorff_ratio > 1.5) + (p2p_ratio > 1.05);
      const Quality_row* w = find_row(r, s->name, "default without entropy term", ratio);
      const std::string cell = s->name + ", " + fixed(ratio, 0) + "%: ";
      if (mean_ratio > 1.1 && w)
        explained.push_back(cell + "mean distance " + fixed(mean_ratio, 3) + " times " + mean.second +
                            "'s; without the entropy term " + fixed(w->quality.mean / mean.first, 3) + ".");
      if (hausdorff_ratio > 1.5 && w)
        explained.push_back(cell + "Hausdorff distance " + fixed(hausdorff_ratio, 3) + " times grid's; without the "
                            "entropy term " + fixed(w->quality.max / grid->quality.max, 3) + ".");
      if (p2p_ratio > 1.05 && w)
      {
        const double without = w->quality.point_to_plane / p2p.first;
        explained.push_back(cell + "point-to-plane error " + fixed(p2p_ratio, 3) + " times " + p2p.second +
                            "'s; without the entropy term " + fixed(without, 3) +
                            (without > p2p_ratio ? ": the term helps, not enough here."
                                                 : ": the term makes it worse here."));
      }

      std::string share = "";
      if (s->labelled > 0)
      {
        const double sr = share_ratio(*s, *q);
        if (s->name == "fandisk")
        {
          const double limit = ratio < 50. ? 2. : 1.6;
          share = checked(sr, limit, false) + " (≥ " + fixed(limit, 1) + ")";
          misses += sr < limit;
          if (sr < limit && w)
            explained.push_back(
              cell + "sharp-edge share " + fixed(sr, 3) + " times the input's, " + fixed(share_ratio(*s, *w), 3) +
              " without the entropy term. Reaching " + fixed(limit, 1) + " means keeping " +
              fixed(100. * limit * ratio / 100., 0) + "% of the points labelled near an edge (within 0.5% of the "
              "diagonal); the entropy sees an edge only within k neighbours of it, and the band's farther points are "
              "likely thinned as flat ones (not measured separately).");
        }
        else if (s->name == "replica_1.2mm" && ratio == 10.)
        {
          const double rmse = q->quality.plane_rmse / s->original.plane_rmse;
          share = checked(sr, 1.3, false) + " (≥ 1.3); plane RMSE / input's " + checked(rmse, 1.02) + " (≤ 1.02)";
          misses += (sr < 1.3) + (rmse > 1.02);
          if (sr < 1.3 || rmse > 1.02)
            explained.push_back(cell + "ball share " + fixed(sr, 3) + ", plane RMSE " + fixed(rmse, 3) +
                                " times the input's.");
        }
        else
          share = fixed(sr, 3);
      }
      std::string plain = "";
      if (w)
        plain = fixed(w->quality.mean / mean.first, 3) + ", " + fixed(w->quality.point_to_plane / p2p.first, 3) +
                (s->labelled > 0 ? ", " + fixed(share_ratio(*s, *w), 3) : "");
      md << "| " << s->name << " | " << ratio << "% | " << checked(mean_ratio, 1.1) << " (" << mean.second << ") | "
         << checked(hausdorff_ratio, 1.5) << " | " << checked(p2p_ratio, 1.05) << " (" << p2p.second << ") | "
         << (p2p_ratio < 1. ? "yes" : "no") << " | " << share << " | " << plain << " |\n";
    }
  md << "\n";
  for (const std::string& line : explained)
    md << "- Miss: " << line << "\n";
  if (!explained.empty())
    md << "\n";
  return misses;
}

// A peer's name, marked when it could not reach the count (see the header).
inline std::string peer_name(const Quality_row& peer)
{
  return peer.method + (peer.count < peer.target ? ", short" : "");
}

// The smallest value of a metric among every library peer that ran in the
// cell (CGAL's, PCL's, Open3D's), and its row.
template <typename Metric>
const Quality_row* best_library_peer(const Report& r, const std::string& input, double ratio, const Metric& metric)
{
  const Quality_row* best = nullptr;
  for (const std::string& peer : library_peers(r))
    if (const Quality_row* q = find_row(r, input, peer, ratio))
      if (!best || metric(q->quality) < metric(best->quality))
        best = q;
  return best;
}

// The default mode against the best peer of every library built, at the
// targets' ratios: the same comparison as the targets', widened to every
// peer, without changing the targets.
inline void write_best_peer(std::ostream& md, const Report& r)
{
  const std::vector<std::string> peers = library_peers(r);
  struct Metric_column
  {
    std::string title;
    double (*value)(const Quality&);
  };
  const std::vector<Metric_column> metrics = {
    { "mean distance", [](const Quality& q) { return q.mean; } },
    { "Hausdorff distance", [](const Quality& q) { return q.max; } },
    { "point-to-plane error", [](const Quality& q) { return q.point_to_plane; } },
  };
  std::ostringstream table;
  int cells = 0;
  std::vector<int> better(metrics.size(), 0), not_cgal(metrics.size(), 0);
  std::map<std::string, std::vector<int> > wins; // peer -> cells where it is the best, per metric
  bool any_short = false;
  for (const Input_summary& s : r.inputs)
    for (double ratio : target_ratios)
    {
      const Quality_row* q = find_row(r, s.name, "package default", ratio);
      if (!q || !best_library_peer(r, s.name, ratio, metrics[0].value))
        continue;
      ++cells;
      table << "| " << s.name << role_mark(s.role) << " | " << ratio << "% |";
      for (std::size_t k = 0; k < metrics.size(); ++k)
      {
        const Quality_row* best = best_library_peer(r, s.name, ratio, metrics[k].value);
        const double ratio_to_best = metrics[k].value(q->quality) / metrics[k].value(best->quality);
        better[k] += ratio_to_best < 1.;
        not_cgal[k] += best->family != "CGAL";
        wins[best->method].resize(metrics.size(), 0);
        ++wins[best->method][k];
        any_short = any_short || best->count < best->target;
        table << ' ' << fixed(ratio_to_best, 3) << " (" << peer_name(*best) << ") |";
      }
      table << "\n";
    }
  if (cells == 0)
    return;
  md << "## The default mode against the best peer of every library\n\n"
     << "`package default` at 10, 20 and 50% kept against the best, cell by cell and metric by metric, of every "
        "peer library's simplifier that ran in the cell (";
  for (std::size_t i = 0; i < peers.size(); ++i)
    md << (i ? ", " : "") << peers[i];
  md << "; which families were built: the header), named in brackets. Ratios below 1: the package is better. The "
        "targets above compare with CGAL's grid, hierarchy and WLOP only, as they were set; this section widens the "
        "comparison and changes no target.\n\n"
     << "| input | kept |";
  for (const Metric_column& m : metrics)
    md << ' ' << m.title << " / best peer's |";
  md << "\n|---|---:|---|---|---|\n" << table.str() << "\n";
  if (any_short)
    md << "*short*: that peer could not reach the count and kept fewer points (see the header).\n\n";
  md << "Over these " << cells << " cells the package is below the best peer's";
  for (std::size_t k = 0; k < metrics.size(); ++k)
    md << (k == 0 ? " " : k + 1 == metrics.size() ? " and " : ", ") << metrics[k].title << " in " << better[k];
  md << ". The best peer is not one of CGAL's in";
  for (std::size_t k = 0; k < metrics.size(); ++k)
    md << (k == 0 ? " " : k + 1 == metrics.size() ? " and " : ", ") << not_cgal[k] << " cells for the "
       << metrics[k].title;
  md << ". Cells where each peer is the best (" ;
  for (std::size_t k = 0; k < metrics.size(); ++k)
    md << (k ? ", " : "") << metrics[k].title;
  md << "):";
  bool first = true;
  for (const std::string& peer : peers)
    if (wins.count(peer))
    {
      md << (first ? " " : "; ") << peer << " " << wins[peer][0] << ", " << wins[peer][1] << ", " << wins[peer][2];
      first = false;
    }
  md << ".\n\n";
}

// One group of inputs, with its count of missed targets.
inline void targets_group(std::ostream& md, const Report& r, const std::vector<const Input_summary*>& group,
                          const std::string& heading)
{
  if (group.empty())
    return;
  md << heading;
  const int misses = targets_table(md, r, group);
  md << misses << " target" << (misses == 1 ? "" : "s") << " missed.\n\n";
}

// The inputs where the default mode ran at 10%, by their role in its tuning.
struct Inputs_by_role
{
  std::vector<const Input_summary*> tuned, held_out, held_out_anew, held_out_next;
  bool empty() const { return tuned.empty() && held_out.empty() && held_out_anew.empty() && held_out_next.empty(); }
};

inline Inputs_by_role inputs_by_role(const Report& r)
{
  Inputs_by_role by_role;
  for (const Input_summary& s : r.inputs)
    if (find_row(r, s.name, "package default", 10.))
      (s.role == Input_role::tuned           ? by_role.tuned
       : s.role == Input_role::held_out      ? by_role.held_out
       : s.role == Input_role::held_out_anew ? by_role.held_out_anew
                                             : by_role.held_out_next)
        .push_back(&s);
  return by_role;
}

// The section: the inputs the default mode was tuned on, then those held
// out, those held out anew and those held out for the next term.
inline void write_targets(std::ostream& md, const Report& r)
{
  const Inputs_by_role groups = inputs_by_role(r);
  if (groups.empty())
    return;
  md << "## The default mode against its targets\n\n"
     << "`package default` (`Mode::weighted_elimination`, `feature_weight` 3, k = 10) at 10, 20 and 50% kept. "
        "Ratios below 1 are better than the peer. *Best CGAL* is the best of grid, hierarchy and WLOP in that cell "
        "(named in brackets); WLOP's skipped cells leave grid and hierarchy. The last column is the same mode with "
        "`feature_weight = 0` (the entropy term switched off), as ratios to the same peers. The targets were set "
        "against CGAL's simplifiers; the next section compares with every peer built.\n\n";
  targets_group(md, r, groups.tuned, "### Inputs the mode was tuned on\n\n");
  targets_group(md, r, groups.held_out,
                "### Held-out inputs\n\nSet aside before tuning and never used for it: they test whether the "
                "default generalises.\n\n");
  targets_group(md, r, groups.held_out_anew,
                "### Inputs held out anew\n\nNamed before the work on anisotropy (issue 12) began, and never used "
                "for it: the earlier held-out inputs had been read in every report since.\n\n");
  targets_group(md, r, groups.held_out_next,
                "### Inputs held out for the next term\n\nNamed before any term is designed from the diagnosis of "
                "rotor's thin walls (rotor, held out anew, was diagnosed), and never used for it.\n\n");
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_TARGETS_H
