#!/usr/bin/python3
"""Reads a particle .vtu with meshio and prints what the C++ test compares against what it wrote:
point count, sum of radii, sum of |velocity|, sum of ids, vertex cell count."""
import sys
import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
vertex_cells = sum(len(block.data) for block in mesh.cells if block.type == "vertex")
print(len(mesh.points), float(np.sum(mesh.point_data["radius"])),
      float(np.sum(np.linalg.norm(mesh.point_data["velocity"], axis=1))),
      int(np.sum(mesh.point_data["id"])), vertex_cells, float(np.sum(mesh.points[:, 1])))
