// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --report: the quality of the kept rows measured against the whole cloud,
// through the library, on row numbers rather than copies of the points;
// with --lod, that of the prefixes at the level boundaries.

#ifndef ENTROPY_SIMPLIFY_QUALITY_REPORT_H
#define ENTROPY_SIMPLIFY_QUALITY_REPORT_H

#include "point_files.h"
#include "simplify_cloud.h"

#include <CGAL/Entropy_simplification/internal/Level_cells.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <vector>

namespace entropy_simplify {

template <typename ConcurrencyTag>
CGAL::Entropy_simplification::Quality_report quality_of(const Cloud& cloud, const std::vector<std::size_t>& kept)
{
  const std::vector<std::size_t> rows = all_rows<std::size_t>(cloud.size());
  const Row_point_map<std::size_t> points = point_map_of<std::size_t>(cloud);
  return CGAL::measure_simplification_quality<ConcurrencyTag>(rows, kept, CGAL::parameters::point_map(points),
                                                              CGAL::parameters::point_map(points));
}

inline void print_quality_report(const CGAL::Entropy_simplification::Quality_report& r)
{
  std::printf("entropy_simplify: quality of the %zu kept points against the %zu input points, distances over the "
              "bounding-box diagonal (%.6g):\n",
              r.kept_size, r.input_size, r.diagonal);
  std::printf("  mean distance   %.6g\n", r.mean_distance);
  std::printf("  max distance    %.6g\n", r.max_distance);
  if (std::isnan(r.point_to_plane))
    std::printf("  point-to-plane  none (fewer than 3 points kept span no plane)\n");
  else
    std::printf("  point-to-plane  %.6g\n", r.point_to_plane);
}

// --lod --report: the quality of the first m rows by rank, for m at each
// level boundary the ranks relocate, from 50 to 1%, and at the level asked
// for (if any),
// largest first, so that one run shows what each ratio would keep.
template <typename ConcurrencyTag>
std::vector<CGAL::Entropy_simplification::Quality_report>
prefix_reports(const Cloud& cloud, const std::vector<std::size_t>& by_rank, std::optional<std::size_t> level)
{
  namespace ES = CGAL::Entropy_simplification::internal;
  const std::size_t n = by_rank.size(), one_percent = ES::kept_count_from_percentage(n, 1.);
  std::vector<std::size_t> sizes;
  for (std::size_t m = ES::level_boundary_below(n, n); m > 0 && m >= one_percent; m = ES::level_boundary_below(m, n))
    sizes.push_back(m);
  if (level && *level > 0)
    sizes.push_back(*level);
  std::sort(sizes.begin(), sizes.end(), std::greater<std::size_t>());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  std::vector<CGAL::Entropy_simplification::Quality_report> reports;
  for (std::size_t m : sizes)
    reports.push_back(quality_of<ConcurrencyTag>(
      cloud, std::vector<std::size_t>(by_rank.begin(), by_rank.begin() + std::ptrdiff_t(m))));
  return reports;
}

inline void print_prefix_reports(const std::vector<CGAL::Entropy_simplification::Quality_report>& reports)
{
  if (reports.empty())
    return;
  std::printf("entropy_simplify: quality of the first points by rank against the %zu input points, distances over "
              "the bounding-box diagonal (%.6g):\n",
              reports.front().input_size, reports.front().diagonal);
  std::printf("  %12s %9s  %-14s %-14s %s\n", "points", "share", "mean distance", "max distance", "point-to-plane");
  for (const CGAL::Entropy_simplification::Quality_report& r : reports)
  {
    char plane[32] = "none";
    if (!std::isnan(r.point_to_plane))
      std::snprintf(plane, sizeof plane, "%.6g", r.point_to_plane);
    std::printf("  %12zu %8.4g%%  %-14.6g %-14.6g %s\n", r.kept_size,
                100. * double(r.kept_size) / double(r.input_size), r.mean_distance, r.max_distance, plane);
  }
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_QUALITY_REPORT_H
