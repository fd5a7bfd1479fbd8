#!/usr/bin/python3
"""Reads a .vtu with an independent reader and compares it with a reference dump written by the C++
test (verification/test_output.cpp).

Usage: read_vtu.py meshio|vtk FILE.vtu REFERENCE.txt [RTOL]
REFERENCE lines: "<section> <name> <components> v1 v2 ...", section one of points, cells
(name connectivity, offsets or types), point, cell. Values must match exactly (binary data), or
within RTOL relative to the array's largest magnitude when given.
Prints "ok <arrays compared>" or "mismatch: ..." (exit status 1).
"""
import sys

import numpy as np


def read_meshio(path):
    import meshio
    mesh = meshio.read(path)
    vtk_id = {"vertex": 1, "triangle": 5, "polygon": 7, "quad": 9}
    conn, offsets, types, end = [], [], [], 0
    for block in mesh.cells:
        for cell in block.data:
            conn.extend(int(k) for k in cell)
            end += len(cell)
            offsets.append(end)
            types.append(vtk_id.get(block.type.rstrip("0123456789"), -1))
    out = {("points", "points"): np.asarray(mesh.points, dtype=float).ravel(),
           ("cells", "connectivity"): np.array(conn, dtype=float), ("cells", "offsets"): np.array(offsets, dtype=float),
           ("cells", "types"): np.array(types, dtype=float)}
    for name, data in mesh.point_data.items():
        out[("point", name)] = np.asarray(data, dtype=float).ravel()
    for name, blocks in mesh.cell_data.items():
        out[("cell", name)] = np.concatenate([np.asarray(b, dtype=float).ravel() for b in blocks])
    return out


def read_vtk(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or reader.GetErrorCode() != 0:
        raise RuntimeError("VTK could not read " + path)
    cells = grid.GetCells()
    out = {("points", "points"): vtk_to_numpy(grid.GetPoints().GetData()).astype(float).ravel()
           if grid.GetNumberOfPoints() else np.zeros(0),
           ("cells", "connectivity"): vtk_to_numpy(cells.GetConnectivityArray()).astype(float),
           ("cells", "offsets"): vtk_to_numpy(cells.GetOffsetsArray()).astype(float)[1:],
           ("cells", "types"): vtk_to_numpy(grid.GetCellTypesArray()).astype(float)}
    for data, section in ((grid.GetPointData(), "point"), (grid.GetCellData(), "cell")):
        for k in range(data.GetNumberOfArrays()):
            out[(section, data.GetArrayName(k))] = vtk_to_numpy(data.GetArray(k)).astype(float).ravel()
    return out


def main():
    reader, path, ref_path = sys.argv[1], sys.argv[2], sys.argv[3]
    rtol = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
    got = read_meshio(path) if reader == "meshio" else read_vtk(path)
    compared = 0
    with open(ref_path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            key, expected = (fields[0], fields[1]), np.array([float(v) for v in fields[3:]])
            if key not in got:
                print(f"mismatch: {reader} has no {key[0]} array '{key[1]}'; it has {sorted(got)}")
                return 1
            value = got[key]
            if value.shape != expected.shape:
                print(f"mismatch: {key}: {value.size} values, expected {expected.size}")
                return 1
            scale = np.max(np.abs(expected)) if expected.size else 0.0
            worst = np.max(np.abs(value - expected)) if expected.size else 0.0
            if worst > rtol * scale:
                k = int(np.argmax(np.abs(value - expected)))
                print(f"mismatch: {key} value {k}: {value[k]!r}, expected {expected[k]!r}")
                return 1
            compared += 1
    print(f"ok {compared}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
