#!/usr/bin/env python3
"""Data for the thesis's performance figures (make fig-2.14 ... fig-3.26): reads the benchmark CSVs
(bench/results/*.csv from one device, default the newest GPU measurement of each case) and writes
plots/perf/data/fig-X.dat, one block per series (first line: its title), for plots/perf/fig-X.gp.
Linear law, float, skin 0.2 radii, each pair from both sides. Usage: tools/perf_figures.py [DEVICE_PREFIX]  (default "NVIDIA")."""
import csv
import glob
import os
import sys

OUT = "plots/perf/data"
POLY = ("cube", "octahedron", "dodecahedron")


def rows(prefix, any_pairs=False):
    """Newest row of each case (shape, scene, N, surfaces) measured on a device named prefix...
    (pairs from both sides only, unless any_pairs)."""
    best = {}
    for path in sorted(glob.glob("bench/results/*.csv")):
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                if not r.get("device", "").startswith(prefix) or r.get("law") != "linear" or r["precision"] != "float":
                    continue
                if "@" in r["shape"] or float(r.get("skin_over_radius") or 0.2) != 0.2 or "scene" not in r:
                    continue
                if not any_pairs and (r.get("pairs") or "both_sides") != "both_sides":
                    continue  # one mode for every N: the sweeps were measured with pairs from both sides
                key = (r["shape"], r["scene"], int(float(r["N"])), int(r["world_surfaces"] or 0))
                if key not in best or r["date"] > best[key]["date"]:
                    best[key] = dict(r, source=os.path.basename(path))
    return best


def write(fig, series, note):
    os.makedirs(OUT, exist_ok=True)
    with open(f"{OUT}/{fig}.dat", "w") as f:
        f.write(f"# {fig}: {note}\n")
        for title, points in series:
            if not points:
                continue
            f.write(f'"{title}" "y"\n')
            for x, y in sorted(points):
                f.write(f"{x:g} {y:g}\n")
            f.write("\n\n")
    print(f"wrote {OUT}/{fig}.dat ({sum(1 for _, p in series if p)} series)")


def main():
    prefix = sys.argv[1] if len(sys.argv) > 1 else "NVIDIA"
    best = rows(prefix)
    if not best:
        sys.exit(f"no benchmark rows from a device named {prefix}* in bench/results (make bench --cases ...)")
    pick = lambda shape, scene, surfaces=None: [r for (s, sc, n, w), r in best.items()
                                                if s == shape and sc == scene and (surfaces is None or w == surfaces)]
    f = lambda r, c: float(r[c])
    n = lambda r: int(float(r["N"]))
    ms_step = lambda r: 1e3 / f(r, "steps_per_s")
    base = lambda shape, scene: [r for r in pick(shape, scene) if int(r["world_surfaces"]) <= 6]  # the six-wall box
    write("fig-2.14", [(f"{s}, falling" if s != "octahedron" else "octahedra (8 faces), falling", [(n(r), ms_step(r)) for r in base(s, "free-fall")])
                       for s in ("octahedron", "cube", "dodecahedron")], "time per step (ms) vs N")
    # issue 20: the same sweep with meshes, from one device (the one of the newest mesh row): packed
    # cubes on a floor of 1 polygon or a mesh of 1e3-1e5 triangles, and the dense sphere bed in a box
    # of 6 polygons or one mesh of 1e3-1e6 triangles
    mesh_rows = [r for r in best.values() if r["scene"] in ("packed-mesh-floor", "dense-bed-mesh") and n(r) == 1000000]
    device = max(mesh_rows, key=lambda r: r["date"])["device"] if mesh_rows else None
    on_device = rows(device, any_pairs=True) if device else {}  # the world phase: either pair mode
    mesh = lambda shape, scenes: [(int(r["world_surfaces"]), f(r, "ms_per_step_walls")) for r in on_device.values()
                                  if r["shape"] == shape and r["scene"] in scenes and n(r) == 1000000]
    tag = device.split(" (")[0] if device else ""
    write("fig-3.21", [(f"{s}, packed, N = 1e6", [(int(r["world_surfaces"]), f(r, "ms_per_step_walls")) for r in pick(s, "packed") if n(r) == 1000000])
                       for s in ("cube", "dodecahedron")] +
          [(f"cube, packed, N = 1e6, floor a mesh of triangles ({tag})", mesh("cube", ("packed", "packed-mesh-floor"))),
           (f"sphere dense bed, N = 1e6, box a mesh of triangles ({tag})", mesh("sphere", ("dense-bed-walls", "dense-bed-mesh")))],
          "world contact (ms per step) vs world surfaces (polygons, or a mesh's triangles)")
    series = [(f"{s}, falling", [(n(r), f(r, "ms_per_step_walls")) for r in base(s, "free-fall")]) for s in POLY]
    series += [(f"{s}, packed", [(n(r), f(r, "ms_per_step_walls")) for r in base(s, "packed")]) for s in ("cube", "dodecahedron")]
    write("fig-3.22", series, "world contact (ms per step) vs N, by shape")
    series = [(f"{s}, falling", [(n(r), f(r, "ms_per_step_contacts")) for r in base(s, "free-fall")]) for s in POLY]
    series += [(f"{s}, packed", [(n(r), f(r, "ms_per_step_contacts")) for r in base(s, "packed")]) for s in ("cube", "dodecahedron")]
    write("fig-3.23", series, "polyhedron-polyhedron contact (ms per step) vs N, by shape")
    for fig, col, what in (("fig-3.24", "ms_per_step_contacts", "polyhedron-polyhedron contact (ms per step)"),
                           ("fig-3.25", "ms_per_step_walls", "polyhedron-world contact (ms per step)"),
                           ("fig-3.26", "ms_per_rebuild", "broad phase (ms per rebuild)")):
        series = [("cubes, packed", [(n(r), f(r, col)) for r in base("cube", "packed")])]
        if fig == "fig-3.26":
            series.append(("spheres, dense bed", [(n(r), f(r, col)) for r in pick("sphere", "dense-bed")]))
        write(fig, series, f"{what} vs N")
    sources = sorted({r["source"] + " (" + r["commit"] + ")" for r in best.values()})
    with open(f"{OUT}/sources.txt", "w") as out:
        out.write("\n".join(sources) + "\n")


if __name__ == "__main__":
    main()
