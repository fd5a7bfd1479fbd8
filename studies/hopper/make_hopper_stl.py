#!/usr/bin/env python3
"""A square hopper as an ASCII STL (metres): four walls converging at `angle` degrees from the
horizontal down to a square orifice of side `orifice` centred on the y axis at y = 0, and above them
a square box of inside width `width` and height `height`, open at the top. Normals point into the
hopper. The orifice's lip (the walls' lower edges) is an open edge of the mesh: polyhedra meet it
as a rim edge (polyhedron_shape.hpp collide_mesh), spheres as edge contacts (mesh_surface.hpp).
  make_hopper_stl.py --width 0.16 --height 0.3 --angle 60 --orifice 0.03 --out hopper.stl"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from stl_ascii import normal, write_stl  # noqa: E402


def hopper_triangles(width, height, angle, orifice):
    a, o = width / 2, orifice / 2
    rise = (a - o) * math.tan(math.radians(angle))  # the converging walls' height
    square = lambda h, y: [(h, y, h), (-h, y, h), (-h, y, -h), (h, y, -h)]
    lip, shoulder, top = square(o, 0.0), square(a, rise), square(a, rise + height)
    centre = (0.0, rise / 2, 0.0)  # inside the hopper: every normal points towards it
    tris = []
    for lower, upper in ((lip, shoulder), (shoulder, top)):
        for k in range(4):
            k1 = (k + 1) % 4
            for t in ((lower[k], lower[k1], upper[k1]), (lower[k], upper[k1], upper[k])):
                n = normal(t)
                c = [sum(v[i] for v in t) / 3 for i in range(3)]
                inward = sum(n[i] * (centre[i] - c[i]) for i in range(3)) > 0
                tris.append(t if inward else (t[0], t[2], t[1]))
    return tris, rise



def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--width", type=float, required=True, help="m, the box's inside width (x and z)")
    p.add_argument("--height", type=float, required=True, help="m, the box's height above the converging walls")
    p.add_argument("--angle", type=float, default=60, help="degrees from the horizontal of the converging walls (10 to 89)")
    p.add_argument("--orifice", type=float, required=True, help="m, the square orifice's side, 0 < orifice < width")
    p.add_argument("--out", required=True)
    a = p.parse_args()
    if not (0 < a.orifice < a.width and a.height > 0 and 10 <= a.angle <= 89):
        sys.exit("make_hopper_stl.py: need 0 < orifice < width, height > 0, 10 <= angle <= 89")
    tris, rise = hopper_triangles(a.width, a.height, a.angle, a.orifice)
    write_stl(a.out, "hopper", tris)
    print(f"{a.out}: {len(tris)} triangles (hopper {a.width} m wide, walls at {a.angle} deg rising {rise:.4f} m, "
          f"box to {rise + a.height:.4f} m, orifice {a.orifice} m)")


if __name__ == "__main__":
    main()
