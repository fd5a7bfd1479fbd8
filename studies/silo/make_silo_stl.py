#!/usr/bin/env python3
"""A flat-bottomed cylindrical silo as an ASCII STL (metres): the shell, a cylinder of radius R and
height H about the y axis, open at the top, and the floor, the annulus between the orifice's radius
r_o and R at y = 0 (a circular orifice in the middle). Both polygons have `segments` sides
(inscribed: the mesh's orifice is a regular polygon with its vertices on the circle); the floor is
split into rings no wider than about its segment length, so no triangle is a sliver. Normals point
into the silo (up from the floor, towards the axis from the shell).
  make_silo_stl.py --radius 0.075 --height 0.35 --orifice-radius 0.02 --segments 96 --out silo.stl"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from stl_ascii import write_stl  # noqa: E402


def silo_triangles(radius, height, orifice_radius, segments):
    ring = lambda r, y: [(r * math.cos(2 * math.pi * k / segments), y, r * math.sin(2 * math.pi * k / segments))
                         for k in range(segments)]
    tris = []
    # Floor: rings from the orifice out to the shell; normal +y.
    width = 2 * math.pi * radius / segments
    n_rings = max(1, math.ceil((radius - orifice_radius) / width))
    radii = [orifice_radius + (radius - orifice_radius) * j / n_rings for j in range(n_rings + 1)]
    for j in range(n_rings):
        a, b = ring(radii[j], 0.0), ring(radii[j + 1], 0.0)
        for k in range(segments):
            k1 = (k + 1) % segments
            # angles grow from +x towards +z, i.e. clockwise seen from +y: (a_k, a_k1, b_k1) faces up
            tris.append((a[k], a[k1], b[k1]))
            tris.append((a[k], b[k1], b[k]))
    # Shell: normal towards the axis.
    lo, hi = ring(radius, 0.0), ring(radius, height)
    for k in range(segments):
        k1 = (k + 1) % segments
        tris.append((lo[k], lo[k1], hi[k1]))
        tris.append((lo[k], hi[k1], hi[k]))
    return tris



def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--radius", type=float, required=True, help="m, the shell's inside radius")
    p.add_argument("--height", type=float, required=True, help="m, the shell's height")
    p.add_argument("--orifice-radius", type=float, required=True, help="m, 0 < r_o < radius")
    p.add_argument("--segments", type=int, default=96, help="sides of the shell's and the orifice's polygons (>= 8)")
    p.add_argument("--out", required=True)
    a = p.parse_args()
    if not (0 < a.orifice_radius < a.radius and a.height > 0 and a.segments >= 8):
        sys.exit("make_silo_stl.py: need 0 < orifice-radius < radius, height > 0, segments >= 8")
    tris = silo_triangles(a.radius, a.height, a.orifice_radius, a.segments)
    write_stl(a.out, "silo", tris)
    print(f"{a.out}: {len(tris)} triangles (silo R = {a.radius} m, H = {a.height} m, orifice r = {a.orifice_radius} m)")


if __name__ == "__main__":
    main()
