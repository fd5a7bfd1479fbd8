#!/usr/bin/env python3
"""A square hopper as an ASCII STL (metres): four walls converging at `angle` degrees from the
horizontal down to a square orifice of side `orifice` centred on the y axis at y = 0, and above them
a square box of inside width `width` and height `height`, open at the top. Normals point into the
hopper. The orifice's lip (the walls' lower edges) is an open edge of the mesh: polyhedra meet it
as a rim edge (polyhedron_shape.hpp collide_mesh), spheres as edge contacts (mesh_surface.hpp).
  make_hopper_stl.py --width 0.16 --height 0.3 --angle 60 --orifice 0.03 --out hopper.stl"""
import argparse
import math
import sys


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


def normal(t):
    u = [t[1][i] - t[0][i] for i in range(3)]
    v = [t[2][i] - t[0][i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(c * c for c in n))
    return [c / length for c in n]


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
    with open(a.out, "w") as f:
        f.write("solid hopper\n")
        for t in tris:
            n = normal(t)
            f.write(f"  facet normal {n[0]:.9e} {n[1]:.9e} {n[2]:.9e}\n    outer loop\n")
            for v in t:
                f.write(f"      vertex {v[0]:.9e} {v[1]:.9e} {v[2]:.9e}\n")
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid hopper\n")
    print(f"{a.out}: {len(tris)} triangles (hopper {a.width} m wide, walls at {a.angle} deg rising {rise:.4f} m, "
          f"box to {rise + a.height:.4f} m, orifice {a.orifice} m)")


if __name__ == "__main__":
    main()
