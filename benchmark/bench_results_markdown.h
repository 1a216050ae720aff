// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RESULTS.md: every table beside the paper's figures, and what the data says
// about the paper's claims. Every number and every verdict is computed here
// from the measurements of the run.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_RESULTS_MARKDOWN_H
#define ENTROPY_SIMPLIFICATION_BENCH_RESULTS_MARKDOWN_H

#include "bench_report.h"
#include "bench_feature_sweep.h"
#include "bench_targets.h"
#include "bench_targets_ahead.h"

namespace bench {

namespace paper {
// The paper's figures (Tables 1-4); methods in its order.
const std::vector<std::string> methods = { "proposed", "equidistant", "bounding sphere", "curvature" };
const double table1_seconds[4] = { 15.258, 14.107, 37.34, 58.516 };
const std::size_t table2[4][3] = { { 18220, 12529, 5691 }, { 18215, 14662, 3553 }, { 18224, 13829, 4395 },
                                   { 18218, 12944, 5274 } };
const double table3[4][2] = { { 0.1209, 0.0018 }, { 0.1220, 0.0014 }, { 0.1215, 0.0015 }, { 0.1210, 0.0018 } };
const double table4_seconds[4] = { 35.891, 30.430, 98.135, 122.551 };
} // namespace paper

// Which of our methods stands for each of the paper's.
inline std::vector<std::string> ours_for(const std::string& paper_method)
{
  if (paper_method == "proposed")
    return { "entropy, lowest first", "entropy, highest first" };
  if (paper_method == "equidistant")
    return { "equidistant E1 (every i-th)", "equidistant E2 (spacing)" };
  return { paper_method };
}

inline double metric_of(const Quality& q, const std::string& metric)
{
  if (metric == "mean")
    return q.mean;
  if (metric == "max")
    return q.max;
  if (metric == "p99")
    return q.p99;
  return q.point_to_plane;
}

// A table per metric: rows are methods, columns ratios; the best of each
// column in bold.
inline void quality_table(std::ostream& md, const Report& r, const std::string& input, const std::string& metric)
{
  const std::vector<double> ratios = ratios_of(r, input);
  md << "| method |";
  for (double ratio : ratios)
    md << ' ' << ratio << "% |";
  md << "\n|---|";
  for (std::size_t i = 0; i < ratios.size(); ++i)
    md << "---:|";
  md << "\n";
  std::map<double, double> best;
  for (double ratio : ratios)
  {
    best[ratio] = std::numeric_limits<double>::infinity();
    for (const std::string& m : methods_of(r))
      if (const Quality_row* q = find_row(r, input, m, ratio))
        best[ratio] = (std::min)(best[ratio], metric_of(q->quality, metric));
  }
  for (const std::string& m : methods_of(r))
  {
    md << "| " << m << " |";
    for (double ratio : ratios)
    {
      const Quality_row* q = find_row(r, input, m, ratio);
      if (!q)
      {
        md << " skipped |";
        continue;
      }
      const double v = metric_of(q->quality, metric);
      md << (v == best[ratio] ? " **" + scientific(v) + "** |" : " " + scientific(v) + " |");
    }
    md << "\n";
  }
  md << "\n";
}

// Whether a method has a row (it was built and ran somewhere).
inline bool find_peer(const Report& r, const std::string& method)
{
  return !family_of(r, method).empty();
}

// The methods whose output is new points, which Tables 2 and 3 label by the
// nearest input point.
inline std::string new_point_methods(const Report& r)
{
  std::string s = "WLOP moves points";
  if (find_peer(r, "PCL voxel grid") || find_peer(r, "Open3D voxel down-sample"))
    s = std::string("WLOP moves points, and ") +
        (find_peer(r, "PCL voxel grid") && find_peer(r, "Open3D voxel down-sample")
           ? "PCL's voxel grid and Open3D's voxel down-sample keep"
           : find_peer(r, "PCL voxel grid") ? "PCL's voxel grid keeps" : "Open3D's voxel down-sample keeps") +
        " the centroids of voxels";
  return s;
}

// For each peer, the cells (input, ratio) where a package method is better
// on a metric.
inline void peer_summary(std::ostream& md, const Report& r, const std::string& ours)
{
  std::vector<std::string> peers = library_peers(r);
  peers.push_back("equidistant E2 (spacing)");
  peers.push_back("curvature");
  md << "| `" << ours << "` against | mean distance: better in | Hausdorff: better in | point-to-plane: better in |"
     << " median ratio of mean distances (ours / peer) |\n|---|---:|---:|---:|---:|\n";
  for (const std::string& peer : peers)
  {
    int cells = 0, better[3] = { 0, 0, 0 };
    std::vector<double> ratio_of_means;
    for (const Input_summary& s : r.inputs)
      for (double ratio : ratios_of(r, s.name))
      {
        const Quality_row* a = find_row(r, s.name, ours, ratio);
        const Quality_row* b = find_row(r, s.name, peer, ratio);
        if (!a || !b)
          continue;
        ++cells;
        better[0] += a->quality.mean < b->quality.mean;
        better[1] += a->quality.max < b->quality.max;
        better[2] += a->quality.point_to_plane < b->quality.point_to_plane;
        ratio_of_means.push_back(a->quality.mean / b->quality.mean);
      }
    if (cells == 0)
      continue;
    std::sort(ratio_of_means.begin(), ratio_of_means.end());
    md << "| " << peer << " | " << better[0] << " / " << cells << " | " << better[1] << " / " << cells << " | "
       << better[2] << " / " << cells << " | " << fixed(ratio_of_means[ratio_of_means.size() / 2], 2) << " |\n";
  }
  md << "\n";
}

// The cells where a method kept fewer points than asked, because no value
// of its size parameter reaches the count: comparisons there are not at
// equal counts.
inline std::string short_cells(const Report& r)
{
  std::ostringstream out;
  std::size_t cells = 0;
  for (const Quality_row& row : r.quality)
    if (!row.skipped && row.count < row.target)
    {
      out << (cells++ ? "; " : "") << row.method << " on " << row.input << " at " << fixed(row.ratio, 0)
          << "% (" << row.count << " of " << row.target << ")";
    }
  if (cells == 0)
    return "Every method reached the count. ";
  return "In " + std::to_string(cells) + " cells a method could not reach the count and kept fewer points, so "
         "these comparisons are not at equal counts: " + out.str() + ". ";
}

// `figures` is the path from the Markdown file to the results directory.
inline void write_results_markdown(const Report& r, const std::string& file, const std::string& figures)
{
  std::ofstream md(file);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));

  md << "# Benchmark results\n\n"
     << "Produced by `bash benchmark/run.sh" << (r.quick ? " --quick" : "") << "` on " << date << " in "
     << fixed(r.total_seconds / 60., 1) << " minutes.\n\n"
     << "Machine: " << machine_description() << ".\n\n";
  if (r.quick)
    md << "**This is a `--quick` run**: inputs divided in size by 8, fewer ratios, one timing run. Its figures "
          "check the pipeline; they are not the results.\n\n";
  md << "Every method is asked for the same number of points, `ceil(n p / 100)` for `p` percent of `n` input "
        "points. Methods with a size parameter reach it by a search of that parameter, then drop their surplus "
        "uniformly at random (seed 1); `quality.csv` gives the count each reached before that trim. "
     << short_cells(r)
     << "The paper's mode is progressive: one run to the smallest ratio serves every ratio; the default mode runs "
        "once per ratio. All distances are divided by the diagonal of the input's bounding box. Times are medians of "
     << r.repeats << " runs; speed is given as the ratio to one sequential pass of `CGAL::pca_estimate_normals` "
     << "(k = 10) on the same input in the same run. Cells where WLOP" << (find_peer(r, "Open3D farthest point")
                                                                              ? " or Open3D's farthest point sampling"
                                                                              : "")
     << " was predicted to take more than " << fixed(r.skip_seconds, 0)
     << " s are skipped and listed at the end. Definitions: `benchmark/README.md`.\n\n";
  md << "Peers: CGAL 5.5's simplifiers (always built)";
  for (const std::string& p : r.peers_built)
    md << "; " << p;
  md << ".";
  for (const std::string& p : r.peers_not_built)
    md << " Not built: " << p << ", which CMake did not find; its methods are absent from every table.";
  md << "\n\n";

  md << "## Inputs\n\n| input | description | points | pca_estimate_normals (s) |\n|---|---|---:|---:|\n";
  for (const Input_summary& s : r.inputs)
    md << "| " << s.name << " | " << s.description << " | " << thousands(s.size) << " | " << fixed(s.pca_seconds, 3)
       << role_mark(s.role) << " |\n";
  md << "\n";
  write_targets(md, r);
  write_best_peer(md, r);
  write_targets_ahead(md, r);
  write_feature_sweep(md, r, figures);

  // ---------------------------------------------------------------- Experiment I
  std::vector<const Input_summary*> replicas;
  for (const Input_summary& s : r.inputs)
    if (s.is_replica)
      replicas.push_back(&s);
  if (!replicas.empty())
  {
    md << "## Experiment I: the replica at 10%\n\n### Table 2: points kept on the plane and on the ball\n\n"
       << "| method |";
    for (const Input_summary* s : replicas)
      md << ' ' << s->name << ": plane | ball | ball share |";
    md << " paper: plane | ball | ball share |\n|---|";
    for (std::size_t i = 0; i <= replicas.size(); ++i)
      md << "---:|---:|---:|";
    md << "\n| input |";
    for (const Input_summary* s : replicas)
      md << ' ' << thousands(s->size - s->labelled) << " | " << thousands(s->labelled) << " | "
         << percent(double(s->labelled) / double(s->size)) << " |";
    md << " 147,876 | 34,315 | 18.8% |\n";
    for (std::size_t p = 0; p < paper::methods.size(); ++p)
      for (const std::string& m : ours_for(paper::methods[p]))
      {
        md << "| " << m << " |";
        for (const Input_summary* s : replicas)
          if (const Quality_row* q = find_row(r, s->name, m, 10.))
            md << ' ' << thousands(q->count - q->quality.labelled) << " | " << thousands(q->quality.labelled) << " | "
               << percent(double(q->quality.labelled) / double(q->count)) << " |";
          else
            md << " | | |";
        md << ' ' << thousands(paper::table2[p][1]) << " | " << thousands(paper::table2[p][2]) << " | "
           << percent(double(paper::table2[p][2]) / double(paper::table2[p][0])) << " |\n";
      }
    for (const std::string& m : methods_of(r))
      if (is_library_peer(r, m) || m == "package default" || m == "default without entropy term")
      {
        md << "| " << m << " |";
        for (const Input_summary* s : replicas)
          if (const Quality_row* q = find_row(r, s->name, m, 10.))
            md << ' ' << thousands(q->count - q->quality.labelled) << " | " << thousands(q->quality.labelled) << " | "
               << percent(double(q->quality.labelled) / double(q->count)) << " |";
          else
            md << " skipped | | |";
        md << " | | |\n";
      }

    md << "\n### Table 3: radius of the sphere fitted to the kept ball points, RMSE of the plane fitted to the kept "
          "board points (m)\n\n| method |";
    for (const Input_summary* s : replicas)
      md << ' ' << s->name << ": radius | plane RMSE |";
    md << " paper: radius | plane RMSE |\n|---|";
    for (std::size_t i = 0; i <= replicas.size(); ++i)
      md << "---:|---:|";
    md << "\n| input |";
    for (const Input_summary* s : replicas)
      md << ' ' << fixed(s->original.sphere_radius, 4) << " | " << fixed(s->original.plane_rmse, 5) << " |";
    md << " 0.1205 | 0.0012 |\n";
    for (std::size_t p = 0; p < paper::methods.size(); ++p)
      for (const std::string& m : ours_for(paper::methods[p]))
      {
        md << "| " << m << " |";
        for (const Input_summary* s : replicas)
          if (const Quality_row* q = find_row(r, s->name, m, 10.))
            md << ' ' << fixed(q->quality.sphere_radius, 4) << " | " << fixed(q->quality.plane_rmse, 5) << " |";
          else
            md << " | |";
        md << ' ' << fixed(paper::table3[p][0], 4) << " | " << fixed(paper::table3[p][1], 4) << " |\n";
      }
    for (const std::string& m : methods_of(r))
      if (is_library_peer(r, m) || m == "package default" || m == "default without entropy term")
      {
        md << "| " << m << " |";
        for (const Input_summary* s : replicas)
          if (const Quality_row* q = find_row(r, s->name, m, 10.))
            md << ' ' << fixed(q->quality.sphere_radius, 4) << " | " << fixed(q->quality.plane_rmse, 5) << " |";
          else
            md << " skipped | |";
        md << " | |\n";
      }
    md << "\n" << new_point_methods(r)
       << ": the ball and board points are those whose nearest input point is on the ball or the board.\n\n";

    md << "### Table 1: time to keep 10%, in seconds and as a ratio to pca_estimate_normals\n\n| method |";
    for (const Input_summary* s : replicas)
      md << ' ' << s->name << ": s | ratio |";
    md << " paper (s) |\n|---|";
    for (std::size_t i = 0; i < replicas.size(); ++i)
      md << "---:|---:|";
    md << "---:|\n";
    for (const std::string& m : methods_of(r))
    {
      md << "| " << m << " |";
      for (const Input_summary* s : replicas)
        if (const Timing_row* t = find_timing(r, s->name, m, 10.))
          md << ' ' << fixed(t->timing.seconds, 3) << " | " << fixed(t->timing.seconds / t->pca_seconds, 2) << " |";
        else
          md << " skipped | |";
      std::string paper_seconds;
      for (std::size_t p = 0; p < paper::methods.size(); ++p)
        for (const std::string& o : ours_for(paper::methods[p]))
          if (o == m)
            paper_seconds = fixed(paper::table1_seconds[p], 3);
      md << ' ' << paper_seconds << " |\n";
    }
    md << "\nThe paper's times were measured on a 1.8 GHz laptop; only their order can be compared.\n\n";

    md << "### Fig. 4: the paper's mean entropy (Eq. 7, bits, the input's reference plane)\n\n| method |";
    for (const Input_summary* s : replicas)
      md << ' ' << s->name << " | rank |";
    md << "\n|---|";
    for (std::size_t i = 0; i < replicas.size(); ++i)
      md << "---:|---:|";
    md << "\n";
    for (const std::string& m : methods_of(r))
    {
      md << "| " << m << " |";
      for (const Input_summary* s : replicas)
      {
        const Quality_row* q = find_row(r, s->name, m, 10.);
        if (!q)
        {
          md << " skipped | |";
          continue;
        }
        int rank = 1;
        for (const std::string& other : methods_of(r))
          if (const Quality_row* o = find_row(r, s->name, other, 10.))
            rank += o->quality.mean_entropy > q->quality.mean_entropy;
        md << ' ' << fixed(q->quality.mean_entropy, 4) << " | " << rank << " |";
      }
      md << "\n";
    }
    md << "\nThe paper: the proposed method highest, then curvature, then equidistant and bounding sphere.\n\n";
    for (const Input_summary* s : replicas)
      md << "![" << s->name << "](" << figures << "/pictures_" << s->name << ".png)\n\n";
  }

  // ---------------------------------------------------------------- Experiment II
  if (const Input_summary* lion = find_input(r, "lion"))
  {
    md << "## Experiment II: the lion\n\n### Table 4: time to keep 20%, in seconds and as a ratio to "
          "pca_estimate_normals\n\n| method | s | ratio | paper (s) |\n|---|---:|---:|---:|\n";
    for (const std::string& m : methods_of(r))
    {
      const Timing_row* t = find_timing(r, "lion", m, 20.);
      std::string paper_seconds;
      for (std::size_t p = 0; p < paper::methods.size(); ++p)
        for (const std::string& o : ours_for(paper::methods[p]))
          if (o == m)
            paper_seconds = fixed(paper::table4_seconds[p], 3);
      md << "| " << m << " | " << (t ? fixed(t->timing.seconds, 3) : "skipped") << " | "
         << (t ? fixed(t->timing.seconds / t->pca_seconds, 2) : "") << " | " << paper_seconds << " |\n";
    }
    md << "\n### Fig. 7: the paper's mean entropy against the ratio kept\n\n";
    const std::vector<double> ratios = ratios_of(r, "lion");
    md << "| method |";
    for (double ratio : ratios)
      md << ' ' << ratio << "% |";
    md << "\n|---|";
    for (std::size_t i = 0; i < ratios.size(); ++i)
      md << "---:|";
    md << "\n| input | " << fixed(lion->original.mean_entropy, 4);
    for (std::size_t i = 1; i < ratios.size(); ++i)
      md << " | ";
    md << " |\n";
    for (const std::string& m : methods_of(r))
    {
      md << "| " << m << " |";
      for (double ratio : ratios)
        if (const Quality_row* q = find_row(r, "lion", m, ratio))
          md << ' ' << fixed(q->quality.mean_entropy, 4) << " |";
        else
          md << " skipped |";
      md << "\n";
    }
    md << "\nThe paper: the mean entropy decreases as fewer points are kept, and the proposed method has the "
          "highest at every ratio. ![mean entropy](" << figures << "/chart_mean_entropy.png)\n\n![lion](" << figures << "/pictures_lion.png)\n\n";
  }

  // ---------------------------------------------------------------- quality
  md << "## Quality at equal counts\n\nFor each input: the mean distance from the input points to the nearest kept "
        "point, its maximum (one-sided Hausdorff distance), and the point-to-plane RMS error of the input against "
        "the result, all divided by the diagonal; the best of each column in bold.\n\n";
  for (const Input_summary& s : r.inputs)
  {
    if (ratios_of(r, s.name).empty())
      continue;
    md << "### " << s.name << "\n\nMean distance:\n\n";
    quality_table(md, r, s.name, "mean");
    md << "Hausdorff distance:\n\n";
    quality_table(md, r, s.name, "max");
    md << "Point-to-plane error:\n\n";
    quality_table(md, r, s.name, "plane");
  }
  for (const char* chart : { "mean_distance", "hausdorff", "p99_distance", "point_to_plane", "uniformity" })
    md << "![" << chart << "](" << figures << "/chart_" << chart << ".png)\n\n";

  // the mesh samples whose points near sharp edges are labelled (the
  // replica's labels mark its ball)
  for (const Input_summary& input : r.inputs)
  {
    if (input.is_replica || input.labelled == 0)
      continue;
    const double input_share = double(input.labelled) / double(input.size);
    md << "### " << input.name << role_mark(input.role)
       << ": points near sharp edges\n\nShare of the kept points within 0.5% of the diagonal of an edge "
          "sharper than 30 degrees, divided by the input's share ("
       << percent(input_share) << "). At a ratio p the ratio cannot exceed min(1 / p, 1 / input share).\n\n| method |";
    const std::vector<double> ratios = ratios_of(r, input.name);
    for (double ratio : ratios)
      md << ' ' << ratio << "% |";
    md << "\n|---|";
    for (std::size_t i = 0; i < ratios.size(); ++i)
      md << "---:|";
    md << "\n";
    for (const std::string& m : methods_of(r))
    {
      md << "| " << m << " |";
      for (double ratio : ratios)
        if (const Quality_row* q = find_row(r, input.name, m, ratio))
          md << ' ' << fixed(double(q->quality.labelled) / double(q->count) / input_share, 2) << " |";
        else
          md << " skipped |";
      md << "\n";
    }
    md << "\n";
    if (input.name == "fandisk")
      md << "![sharp edges](" << figures << "/chart_fandisk_sharp_edges.png)\n\n";
  }

  // ---------------------------------------------------------------- speed
  md << "## Speed\n\nTime to keep 10%, as a ratio to one sequential `pca_estimate_normals` pass (k = 10) on the same "
        "input in the same run (seconds in parentheses). For the package"
     << (find_peer(r, "PCL normal space sampling") ? ", the curvature baseline and PCL's normal space sampling "
                                                     "(whose time includes PCL's NormalEstimation)"
                                                   : " and the curvature baseline")
     << ", `timing.csv` also gives the part spent estimating normals.\n\n| method |";
  std::vector<const Input_summary*> timed;
  for (const Input_summary& s : r.inputs)
    timed.push_back(&s);
  for (const Input_summary* s : timed)
    md << ' ' << s->name << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < timed.size(); ++i)
    md << "---:|";
  md << "\n";
  for (const std::string& m : methods_of(r))
  {
    md << "| " << m << " |";
    for (const Input_summary* s : timed)
      if (const Timing_row* t = find_timing(r, s->name, m, 10.))
        md << ' ' << fixed(t->timing.seconds / t->pca_seconds, 2) << " (" << fixed(t->timing.seconds, 2) << ") |";
      else
        md << " skipped |";
    md << "\n";
  }
  md << "\n";

  // ---------------------------------------------------------------- verdicts
  md << "## What the data says about the paper's claims\n\n";
  for (const Input_summary* s : replicas)
  {
    const Quality_row* low = find_row(r, s->name, "entropy, lowest first", 10.);
    const Quality_row* high = find_row(r, s->name, "entropy, highest first", 10.);
    if (!low || !high)
      continue;
    const double input_share = double(s->labelled) / double(s->size);
    auto share = [](const Quality_row* q) { return double(q->quality.labelled) / double(q->count); };
    md << "- **Table 2** (" << s->name << "): the paper keeps 31.2% of its points on the ball; the method as its "
       << "text describes (lowest entropy first) keeps " << percent(share(low)) << ", the reversed order "
       << percent(share(high)) << ", the input has " << percent(input_share) << ". "
       << (share(low) >= 0.28 || share(high) >= 0.28 ? "One order comes near the paper's share."
                                                      : "Neither order reproduces it at k = 10.")
       << "\n";
    int rank_low = 1;
    std::string top;
    double top_value = -1.;
    for (const std::string& m : methods_of(r))
      if (const Quality_row* o = find_row(r, s->name, m, 10.))
      {
        rank_low += o->quality.mean_entropy > low->quality.mean_entropy;
        if (o->quality.mean_entropy > top_value)
        {
          top_value = o->quality.mean_entropy;
          top = m;
        }
      }
    md << "- **Fig. 4** (" << s->name << "): the highest mean entropy is `" << top << "`'s; lowest-first ranks "
       << rank_low << ". The indicator is what lowest-first maximises, so its rank says nothing about quality.\n";
    md << "- **Table 3** (" << s->name << "): fitted radius " << fixed(low->quality.sphere_radius, 4) << " m "
       << "(lowest first) and " << fixed(high->quality.sphere_radius, 4) << " m (highest first) against 0.1205 m; "
       << "plane RMSE " << fixed(low->quality.plane_rmse * 1000., 2) << " and "
       << fixed(high->quality.plane_rmse * 1000., 2) << " mm against the input's "
       << fixed(s->original.plane_rmse * 1000., 2) << " mm (paper: 1.8 against 1.2).\n";
    const Timing_row* t_low = find_timing(r, s->name, "entropy, lowest first", 10.);
    const Timing_row* t_e2 = find_timing(r, s->name, "equidistant E2 (spacing)", 10.);
    if (t_low && t_e2)
      md << "- **Table 1** (" << s->name << "): the paper's method takes 1.08 times the equidistant method's time; "
         << "here " << fixed(t_low->timing.seconds / t_e2->timing.seconds, 1) << " times E2's.\n";
  }
  if (find_input(r, "lion"))
  {
    // the claim compares each method's entropy at the smallest and largest ratios
    const std::vector<double> ratios = ratios_of(r, "lion");
    std::string decreasing, not_decreasing;
    bool highest_everywhere = true;
    for (const std::string& m : methods_of(r))
    {
      const Quality_row* fewest = find_row(r, "lion", m, ratios.front());
      const Quality_row* most = find_row(r, "lion", m, ratios.back());
      if (!fewest || !most)
        continue;
      std::string& list = fewest->quality.mean_entropy < most->quality.mean_entropy - 1e-3 ? decreasing : not_decreasing;
      list += (list.empty() ? "`" : ", `") + m + "` (" + fixed(fewest->quality.mean_entropy, 4) + " at " +
              fixed(ratios.front(), 0) + "%, " + fixed(most->quality.mean_entropy, 4) + " at " +
              fixed(ratios.back(), 0) + "%)";
    }
    for (double ratio : ratios)
    {
      const Quality_row* low = find_row(r, "lion", "entropy, lowest first", ratio);
      for (const std::string& m : methods_of(r))
        if (const Quality_row* o = find_row(r, "lion", m, ratio))
          if (low && o->quality.mean_entropy > low->quality.mean_entropy)
            highest_everywhere = false;
    }
    md << "- **Fig. 7** (lion): \"the mean entropy decreases as fewer points are kept\" holds for "
       << (decreasing.empty() ? "no method" : decreasing) << "; it does not (it changes by less than 0.001 bit or "
       << "rises) for " << (not_decreasing.empty() ? "no method" : not_decreasing)
       << ": lowest-first removes whatever lowers the indicator, so it stays at its maximum. \"The proposed method "
       << "is highest at every ratio\" " << (highest_everywhere ? "holds" : "does not hold")
       << " for lowest-first, by construction.\n";
  }
  md << "\n### Where the package stands against each peer\n\nOver every input and ratio where both ran:\n\n";
  peer_summary(md, r, "package default");
  peer_summary(md, r, "entropy, lowest first");
  peer_summary(md, r, "entropy, highest first");

  md << "## Skipped cells\n\n";
  bool any = false;
  for (const Quality_row& q : r.quality)
    if (q.skipped)
    {
      md << "- " << q.method << " on " << q.input << " at " << q.ratio << "% (quality)\n";
      any = true;
    }
  for (const Timing_row& t : r.timing)
    if (t.skipped)
    {
      md << "- " << t.method << " on " << t.input << " at " << t.ratio << "% (timing)\n";
      any = true;
    }
  if (!any)
    md << "None.\n";
}

// Everything the run produces: CSV and figure scripts in `results_dir`, the
// Markdown report in `markdown_file`.
inline void write_report(const Report& r, const std::string& results_dir, const std::string& markdown_file,
                         const std::string& figures)
{
  write_csv(r, results_dir);
  write_charts(r, results_dir);
  write_sweep_files(r, results_dir);
  for (const Input_summary& s : r.inputs)
    if (s.is_replica)
      write_pictures(r, results_dir, s.name, 10., true);
  write_pictures(r, results_dir, "lion", 20., false);
  write_results_markdown(r, markdown_file, figures);
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_RESULTS_MARKDOWN_H
