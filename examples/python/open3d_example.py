#!/usr/bin/env python3
"""Simplifies an Open3D point cloud to 10% with the package's Python module,
keeping the points by rank, measures the result, and writes it.

    PYTHONPATH=build/python python3 examples/python/open3d_example.py INPUT.ply [OUTPUT.ply]

for example on CGAL's b9_training scan, which the build unpacks:
build/cgal_data/data/points_3/b9_training.ply. Uses Debian's python3-open3d."""

import sys

import numpy as np
import open3d as o3d

import entropy_simplification as es

if len(sys.argv) < 2:
    sys.exit(__doc__)
source = sys.argv[1]
target = sys.argv[2] if len(sys.argv) > 2 else "simplified.ply"

pcd = o3d.io.read_point_cloud(source)
points = np.asarray(pcd.points)  # a view of Open3D's float64 points: no copy is made
if len(points) == 0:
    sys.exit("cannot read points from " + source)

kept = es.simplify(points, ratio=0.1)  # int64 indices, the most important first
quality = es.report(points, kept)
print("kept %d of %d points; mean distance %.3g, point-to-plane %.3g of the diagonal"
      % (len(kept), len(points), quality["mean_distance"], quality["point_to_plane"]))

# Open3D keeps colours and normals with select_by_index, in the order given:
# the output's first m points are the m most important.
simplified = pcd.select_by_index(kept.tolist())
o3d.io.write_point_cloud(target, simplified)
print("wrote " + target)
