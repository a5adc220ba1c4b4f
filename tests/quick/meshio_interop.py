#!/usr/bin/env python3
"""MED interoperability with an independent implementation (meshio + h5py).

(a) meshio writes MED meshes (with groups, one family listing two groups);
    lunaster reads them (`lunaster-meshgen --info FILE`) and must report the
    same node count, cell counts per type and group sizes.
(b) lunaster writes a mesh and an analytic result (`--test-result`); meshio
    reads it back and every value must match the formulas (see meshgen.cpp).

usage: meshio_interop.py PATH/TO/lunaster-meshgen [SCRATCH_DIR]
Needs python3-meshio and python3-h5py (Debian packages).
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
import meshio

checks = {"passed": 0, "failed": 0}


def check(condition, what):
    if condition:
        checks["passed"] += 1
    else:
        checks["failed"] += 1
        print("FAIL:", what)


def info(meshgen, path):
    """Parses `lunaster-meshgen --info` into a dict."""
    out = subprocess.run([meshgen, "--info", path], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"--info {path} failed: {out.stderr}")
    result = {"cells": {}, "cell_group": {}, "node_group": {}}
    for line in out.stdout.splitlines():
        words = line.split()
        if words[0] in ("cells", "cell_group", "node_group"):
            result[words[0]][words[1]] = int(words[2])
        else:
            result[words[0]] = words[1]
    return result


def group_sizes(tags, tag_names):
    """Group name -> number of entities, from family numbers and family -> groups."""
    sizes = {}
    values, counts = np.unique(np.asarray(tags), return_counts=True)
    for value, count in zip(values, counts):
        for name in tag_names.get(int(value), []):
            sizes[name] = sizes.get(name, 0) + int(count)
    return sizes


def part_a_2d(meshgen, folder):
    points = np.array([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1], [3, 0.5]], dtype=float)
    quads = np.array([[0, 1, 4, 3], [1, 2, 5, 4]])
    tris = np.array([[2, 6, 5]])
    lines = np.array([[0, 1], [1, 2], [5, 4], [4, 3]])
    mesh = meshio.Mesh(points, [("quad", quads), ("triangle", tris), ("line", lines)])
    mesh.cell_data["cell_tags"] = [np.array([-1, -1]), np.array([-2]), np.array([-3, -3, -4, -4])]
    mesh.cell_tags = {-1: ["SQUARES"], -2: ["TRIANGLE"], -3: ["BOTTOM", "EDGES"], -4: ["TOP", "EDGES"]}
    mesh.point_data["point_tags"] = np.array([1, 0, 0, 2, 0, 0, 2])
    mesh.point_tags = {1: ["ORIGIN"], 2: ["CORNERS"]}
    path = os.path.join(folder, "meshio_2d.med")
    meshio.write(path, mesh, file_format="med")
    got = info(meshgen, path)
    check(got["nodes"] == "7", f"2D nodes: {got['nodes']}")
    check(got["dim"] == "2", f"2D dim: {got['dim']}")
    check(got["cells"] == {"QUAD4": 2, "TRIA3": 1, "SEG2": 4}, f"2D cells: {got['cells']}")
    expected = {"SQUARES": 2, "TRIANGLE": 1, "BOTTOM": 2, "TOP": 2, "EDGES": 4}
    check(got["cell_group"] == expected, f"2D cell groups: {got['cell_group']}")
    check(got["node_group"] == {"ORIGIN": 1, "CORNERS": 2}, f"2D node groups: {got['node_group']}")


def part_a_3d(meshgen, folder):
    # one HEXA8 in MED order (meshio writes connectivity as given) and its bottom face
    points = np.array([[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0],
                       [0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]], dtype=float)
    mesh = meshio.Mesh(points, [("hexahedron", np.array([[0, 1, 2, 3, 4, 5, 6, 7]])),
                                ("quad", np.array([[0, 1, 2, 3]]))])
    mesh.cell_data["cell_tags"] = [np.array([-1]), np.array([-2])]
    mesh.cell_tags = {-1: ["CUBE"], -2: ["BASE"]}
    path = os.path.join(folder, "meshio_3d.med")
    meshio.write(path, mesh, file_format="med")
    got = info(meshgen, path)
    check(got["nodes"] == "8" and got["dim"] == "3", f"3D nodes/dim: {got}")
    check(got["cells"] == {"HEXA8": 1, "QUAD4": 1}, f"3D cells: {got['cells']}")
    check(got["cell_group"] == {"CUBE": 1, "BASE": 1}, f"3D groups: {got['cell_group']}")


def part_b(meshgen, folder, args, name):
    path = os.path.join(folder, name)
    subprocess.run([meshgen] + args + ["--test-result", "-o", path], check=True, capture_output=True)
    mesh = meshio.read(path)
    got = info(meshgen, path)
    check(len(mesh.points) == int(got["nodes"]), f"{name}: node count")
    x = np.zeros((len(mesh.points), 3))
    x[:, : mesh.points.shape[1]] = mesh.points
    dim = int(got["dim"])
    # groups: meshio's families against lunaster's own reading
    sizes = {}
    for block_tags in mesh.cell_data["cell_tags"]:
        for k, v in group_sizes(block_tags, mesh.cell_tags).items():
            sizes[k] = sizes.get(k, 0) + v
    check(sizes == got["cell_group"], f"{name}: cell groups {sizes} vs {got['cell_group']}")
    check(group_sizes(mesh.point_data["point_tags"], mesh.point_tags) == got["node_group"], f"{name}: node groups")
    depl = [k for k in mesh.point_data if k.startswith("RESU____DEPL")]
    check(len(depl) == 2, f"{name}: two DEPL steps, got {depl}")
    for key in depl:
        t = float(key.split("-")[-1])
        values = mesh.point_data[key]
        expected = [t * x[:, 0], t * (x[:, 0] + 2 * x[:, 1])]
        if dim == 3:
            expected.append(t * x[:, 2])
        expected.append(np.where(x[:, 0] >= 0, -1e5 * t, 0.0))
        check(np.allclose(values, np.stack(expected, axis=1), rtol=1e-14, atol=1e-12), f"{name}: {key}")
    # ELNO: meshio 7 reshapes multi-point values with the cell index fastest, but
    # MED stores them component by component, each cell with all its points
    # (component, cell, point): read the raw datasets with h5py instead.
    import h5py

    med_types = {"quad": "QU4", "quad8": "QU8", "line": "SE2", "line3": "SE3",
                 "hexahedron": "HE8", "hexahedron20": "H20", "triangle": "TR3", "triangle6": "TR6"}
    with h5py.File(path, "r") as f:
        field = f["CHA/RESU____SIGM_ELNO"]
        check(len(field) == 2, f"{name}: two SIGM_ELNO steps")
        for step in field.values():
            t = float(step.attrs["PDT"])
            for block in mesh.cells:
                data = step["NOE." + med_types[block.type]]["MED_NO_PROFILE_INTERNAL"]
                n_cells, n_points = int(data.attrs["NBR"]), int(data.attrs["NGA"])
                values = data["CO"][()].reshape(2, n_cells, n_points).transpose(1, 2, 0)
                nodes = block.data  # (n_cells, n_nodes) in the file's (MED) order
                k = np.arange(nodes.shape[1])[None, :]
                expected = np.stack([t * x[nodes, 0], t * (x[nodes, 1] + 10 * k)], axis=2)
                check(np.allclose(values, expected, rtol=1e-14, atol=1e-12), f"{name}: ELNO t={t} on {block.type}")


def main():
    meshgen = sys.argv[1]
    folder = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="lunaster-meshio-")
    os.makedirs(folder, exist_ok=True)
    part_a_2d(meshgen, folder)
    part_a_3d(meshgen, folder)
    part_b(meshgen, folder, ["--upper", "quad4:3", "--lower", "quad8:2"], "result_2d.med")
    part_b(meshgen, folder, ["--v1", "hexa8:2x2x1", "--v2", "hexa20:1x1x1"], "result_3d.med")
    print(f"meshio_interop: {checks['passed']} passed, {checks['failed']} failed")
    return 1 if checks["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
