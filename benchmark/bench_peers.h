// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optional peer libraries whose simplifiers the build found: PCL's and
// Open3D's (ES_BENCH_WITH_PCL, ES_BENCH_WITH_OPEN3D, set by
// benchmark/CMakeLists.txt).

#ifndef ENTROPY_SIMPLIFICATION_BENCH_PEERS_H
#define ENTROPY_SIMPLIFICATION_BENCH_PEERS_H

#include "bench_methods.h"
#ifdef ES_BENCH_WITH_PCL
#include "bench_peers_pcl.h"
#endif
#ifdef ES_BENCH_WITH_OPEN3D
#include "bench_peers_open3d.h"
#endif

#include <vector>

namespace bench {

// The optional peers' methods that were built, PCL's then Open3D's.
inline std::vector<Method> optional_peer_methods([[maybe_unused]] Method_context& context)
{
  std::vector<Method> methods, peers;
#ifdef ES_BENCH_WITH_PCL
  peers = pcl_peers::methods(context);
  methods.insert(methods.end(), peers.begin(), peers.end());
#endif
#ifdef ES_BENCH_WITH_OPEN3D
  peers = open3d_peers::methods(context);
  methods.insert(methods.end(), peers.begin(), peers.end());
#endif
  return methods;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_PEERS_H
