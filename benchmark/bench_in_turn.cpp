// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One side of a timing in turn (benchmark/in_turn.sh): the default mode's
// direct call on one of the benchmark's inputs, timed `runs` times in this
// process. in_turn.sh builds it twice, against this commit's headers and an
// earlier commit's, and runs the two builds alternately, so that a slow
// spell of a shared machine falls on both. Only the public call is used,
// which every commit since issue 7 has.
//
// Usage: bench_in_turn DATA INPUT PERCENT RUNS THREADS
//   INPUT: replica_2mm, replica_1.2mm, lion (457,124 samples, as in the
//   quality tables) or lion_1M (1,000,000 samples, as in the Speed section).
// Prints, per run, the seconds and a hash of the kept input positions, which
// must agree between the two builds when the kept points are the same.

#include "bench_inputs.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/property_map.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

bench::Cloud input_named(const std::string& data, const std::string& name)
{
  if (name == "replica_2mm")
    return bench::replica(0.002);
  if (name == "replica_1.2mm")
    return bench::replica(0.0012);
  if (name == "lion")
    return bench::mesh_sample("lion", data + "/meshes/lion.off", 457124, false);
  if (name == "lion_1M")
    return bench::mesh_sample("lion", data + "/meshes/lion.off", 1000000, false);
  throw std::invalid_argument("unknown input " + name + " (replica_2mm, replica_1.2mm, lion, lion_1M)");
}

// FNV-1a over the sorted kept input positions.
std::uint64_t hash_of(std::vector<std::uint32_t> kept)
{
  std::sort(kept.begin(), kept.end());
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint32_t k : kept)
  {
    h ^= k;
    h *= 1099511628211ull;
  }
  return h;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    if (argc != 6)
      throw std::invalid_argument("usage: bench_in_turn DATA INPUT PERCENT RUNS THREADS");
    const double percent = std::stod(argv[3]);
    const int runs = std::stoi(argv[4]);
    const int threads = std::stoi(argv[5]);
    tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    const bench::Cloud cloud = input_named(argv[1], argv[2]);
    using Indexed = std::pair<bench::Point, std::uint32_t>;
    for (int r = 0; r < runs; ++r)
    {
      std::vector<Indexed> points;
      points.reserve(cloud.points.size());
      for (std::uint32_t i = 0; i < cloud.points.size(); ++i)
        points.emplace_back(cloud.points[i], i);
      const auto start = std::chrono::steady_clock::now();
      const auto end = CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
        points, 10,
        CGAL::parameters::select_percentage(percent).point_map(CGAL::First_of_pair_property_map<Indexed>()));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::vector<std::uint32_t> kept;
      for (auto p = points.begin(); p != end; ++p)
        kept.push_back(p->second);
      std::printf("%.4f %016llx\n", seconds, static_cast<unsigned long long>(hash_of(kept)));
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_in_turn: " << e.what() << '\n';
    return 1;
  }
}
