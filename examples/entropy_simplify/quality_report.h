// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --report: the quality of the kept rows measured against the whole cloud,
// through the library, on row numbers rather than copies of the points.

#ifndef ENTROPY_SIMPLIFY_QUALITY_REPORT_H
#define ENTROPY_SIMPLIFY_QUALITY_REPORT_H

#include "point_files.h"
#include "simplify_cloud.h"

#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <cmath>
#include <cstdio>
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

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_QUALITY_REPORT_H
