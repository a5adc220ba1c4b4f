#!/usr/bin/python3
"""Converts an SSNP121 MED mesh (from lunaster-meshgen) into a CalculiX input deck.

The scene is SSNP121's: E = 2e6 Pa, nu = 0, frictionless contact between the two
blocks, imposed displacement -0.1 on the top face, bottom face fixed (2D plane
strain: CD / GH and AB / EF; 3D: SURCHA / ENCAST and SURESC / SURMAI).

    med2inp.py MESH.med OUT.inp --contact {nts,sts,mortar} [--penalty K] [--slab]

Besides OUT.inp it writes OUT.json: the coordinates of the nodes of the slave face, the
master face and the points A, O, B (2D) or A21, A22, A23 (3D), the element numbers of the
body under each face (the two faces have coincident nodes) and the normal component, so that ccx_run.py computes the errors on the same nodes as lunaster.
Results go to the .frd: nodal displacements, nodal stresses (extrapolated and averaged at
the nodes, as lunaster's SIGM_NOEU) and the contact pressure at the slave nodes.

nts    *CONTACT PAIR, TYPE=NODE TO SURFACE  (penalty, PRESSURE-OVERCLOSURE=LINEAR, slope K)
sts    *CONTACT PAIR, TYPE=SURFACE TO SURFACE (penalty, same law)
mortar *CONTACT PAIR, TYPE=MORTAR (PRESSURE-OVERCLOSURE=HARD)
Slave = the upper block's face (AB / SURESC, as lunaster's CONTINUE decks), master = the other.
Reads the mesh with meshio (Debian python3-meshio), which keeps MED's node order inside
3D cells: HEXA8/HEXA20 are permuted to VTK (= CalculiX) order here (../shared/spec/med-facts.md).
PENTA15 meshes are not readable by it.
"""
import argparse
import json
import sys

import meshio

# meshio (VTK order, which equals Abaqus/CalculiX order for these types) -> CalculiX element, faces.
# Faces: corner-node indices (0-based) of each face, in CalculiX face order S1, S2, ...
ELEMENTS = {
    "quad": ("CPE4", [(0, 1), (1, 2), (2, 3), (3, 0)]),
    "quad8": ("CPE8", [(0, 1), (1, 2), (2, 3), (3, 0)]),
    "hexahedron": ("C3D8", [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]),
    "hexahedron20": ("C3D20", [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)]),
}
# For each VTK position i, the MED position to read (vtk[i] = med[p[i]]).
MED_TO_VTK = {
    "hexahedron": [0, 3, 2, 1, 4, 7, 6, 5],
    "hexahedron20": [0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17],
}
# Hertz scene (lunaster-meshgen --hertz): 2D element names for plane strain and axisymmetry.
AXIS_ELEMENTS = {"quad": "CAX4", "quad8": "CAX8"}
SCENES = {
    2: dict(bodies=("PLAQUE1", "PLAQUE2"), top="CD", bottom="GH", slave="AB", master="EF", normal=2,
            points=("A", "O", "B")),
    3: dict(bodies=("V1", "V2"), top="SURCHA", bottom="ENCAST", slave="SURESC", master="SURMAI", normal=3,
            points=("A21", "A22", "A23")),
}


def to_vtk_order(mesh):
    """Permutes the 3D cells meshio read from MED into VTK node order, in place."""
    for block in mesh.cells:
        p = MED_TO_VTK.get(block.type)
        if p is not None:
            block.data[:] = block.data[:, p]


def extrude(mesh):
    """2D QUAD4 mesh -> one layer of HEXA8 (thickness 1/N of the slave face), same group names;
    edge groups become the face groups of the layer, node groups keep their z = 0 node."""
    n = len(mesh.points)
    edge_count = sum(len(c.data) for c in mesh.cells if c.type == "line")
    t = 1.0 / max(1.0, edge_count / 8.0)
    pts = [[x[0], x[1], 0.0] for x in mesh.points] + [[x[0], x[1], t] for x in mesh.points]
    cells, tags = [], []
    for b, block in enumerate(mesh.cells):
        if block.type == "quad":
            data = [[*q, *(int(k) + n for k in q)] for q in block.data]
            cells.append(("hexahedron", data))
        elif block.type == "line":
            data = [[e[0], e[1], int(e[1]) + n, int(e[0]) + n] for e in block.data]
            cells.append(("quad", data))
        else:
            sys.exit(f"med2inp: --slab handles QUAD4 meshes only, got {block.type}")
        tags.append(mesh.cell_data["cell_tags"][b])
    point_tags = list(mesh.point_data["point_tags"]) + [0] * n
    out = meshio.Mesh(pts, cells, cell_data={"cell_tags": tags}, point_data={"point_tags": point_tags})
    out.cell_tags, out.point_tags = mesh.cell_tags, mesh.point_tags
    return out


def groups(mesh):
    """cell group -> list of (block index, cell index); node group -> node indices."""
    cells, nodes = {}, {}
    for b, block in enumerate(mesh.cells):
        for i, tag in enumerate(mesh.cell_data["cell_tags"][b]):
            for name in mesh.cell_tags.get(int(tag), []):
                cells.setdefault(name, []).append((b, i))
    for n, tag in enumerate(mesh.point_data["point_tags"]):
        for name in mesh.point_tags.get(int(tag), []):
            nodes.setdefault(name, []).append(n)
    return cells, nodes


def face_surface(mesh, cells, group, volume_groups):
    """(element id, face number) for each boundary cell of `group`, found on the volume cells."""
    corner_index = {}
    for gname in volume_groups:
        for b, i in cells[gname]:
            ctype = mesh.cells[b].type
            elem_id = element_ids[(b, i)]
            conn = mesh.cells[b].data[i]
            for f, face in enumerate(ELEMENTS[ctype][1]):
                corner_index[frozenset(int(conn[k]) for k in face)] = (elem_id, f + 1)
    out = []
    for b, i in cells[group]:
        conn = mesh.cells[b].data[i]
        ncorner = {"line": 2, "line3": 2, "quad": 4, "quad8": 4}[mesh.cells[b].type]
        key = frozenset(int(n) for n in conn[:ncorner])
        if key not in corner_index:
            sys.exit(f"med2inp: face of {group} not found on a volume cell")
        out.append(corner_index[key])
    return out


element_ids = {}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--contact", choices=("nts", "sts", "mortar"), default="sts")
    ap.add_argument("--penalty", type=float, default=1e9, help="LINEAR pressure-overclosure slope (Pa/m)")
    ap.add_argument("--hertz", metavar="Q",  type=float,
                    help="Hertz scene (ball on block, groups BALL, BLOCK, ...): the pressure Q on BALL_TOP")
    ap.add_argument("--axis", action="store_true", help="Hertz 2D meshes: axisymmetric CAX4/CAX8 instead of CPE4/CPE8")
    ap.add_argument("--slab", action="store_true",
                    help="2D meshes: one layer of C3D8 with DZ = 0 everywhere instead of CPE4 (CalculiX's mortar "
                         "contact refuses the MPCs of its own 2D expansion)")
    a = ap.parse_args()
    mesh = meshio.read(a.mesh)
    to_vtk_order(mesh)
    if a.hertz is not None:
        return hertz(mesh, a)
    sc = SCENES[3 if any(c.type.startswith("hexa") for c in mesh.cells) else 2]
    # Node numbers of the faces and points in the mesh as read (extrusion keeps them).
    cells, nodes = groups(mesh)
    face_nodes = {name: sorted({int(n) + 1 for b, i in cells[name] for n in mesh.cells[b].data[i]})
                  for name in (sc["slave"], sc["master"])}
    def where(ids):
        return [[float(v) for v in mesh.points[n - 1][:sc["normal"]]] for n in ids]
    points = [nodes[p][0] + 1 for p in sc["points"]]
    sidecar = dict(normal=sc["normal"], points=list(sc["points"]), slave=where(face_nodes[sc["slave"]]),
                   master=where(face_nodes[sc["master"]]), point_xyz=where(points))
    if a.slab:
        mesh = extrude(mesh)
        cells, nodes = groups(mesh)
    dim = 3 if any(c.type.startswith("hexa") for c in mesh.cells) else 2
    lines = ["*HEADING", f"SSNP121 {dim}D from {a.mesh} (lunaster tests/bench/study)", "*NODE, NSET=NALL"]
    for n, x in enumerate(mesh.points):
        z = x[2] if dim == 3 else 0.0
        lines.append(f"{n + 1}, {x[0]:.12g}, {x[1]:.12g}, {z:.12g}")
    body_range, next_id = element_cards(mesh, cells, sc["bodies"], lambda ctype: ELEMENTS[ctype][0], element_ids,
                                        lines)
    for name in (sc["top"], sc["bottom"], sc["slave"], sc["master"]):
        members = sorted({int(n) + 1 for b, i in cells[name] for n in mesh.cells[b].data[i]})
        lines.append(f"*NSET, NSET=N{name}")
        lines += [", ".join(map(str, members[k:k + 12])) for k in range(0, len(members), 12)]
    name_role = {sc["slave"]: "slave", sc["master"]: "master"}
    for name in (sc["slave"], sc["master"]):
        faces = face_surface(mesh, cells, name, sc["bodies"])
        owner = next(b for b, (lo, hi) in body_range.items() if lo <= faces[0][0] <= hi)
        sidecar[name_role[name] + "_elements"] = body_range[owner]
        lines.append(f"*SURFACE, NAME=S{name}, TYPE=ELEMENT")
        lines += [f"{e}, S{f}" for e, f in faces]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "2.0e6, 0.0"]
    for body in sc["bodies"]:
        lines.append(f"*SOLID SECTION, ELSET={body}, MATERIAL=STEEL")
        if dim == 2:
            lines.append("1.")
    # CalculiX 2.20 turns HARD into LINEAR (K = 1e8 by default, with a warning) for every
    # pair type, mortar included: the penalty slope is given explicitly instead.
    lines += ["*SURFACE INTERACTION, NAME=SI1", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
              f"{a.penalty:.6g}"]
    ctype = {"nts": "NODE TO SURFACE", "sts": "SURFACE TO SURFACE", "mortar": "MORTAR"}[a.contact]
    lines += [f"*CONTACT PAIR, INTERACTION=SI1, TYPE={ctype}", f"S{sc['slave']}, S{sc['master']}"]
    top, bottom = "N" + sc["top"], "N" + sc["bottom"]
    normal = sc["normal"]
    lines += ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY", f"{bottom}, 1, {dim}, 0.", f"{top}, 1, 1, 0.",
              f"{top}, {normal}, {normal}, -0.1"]
    if dim == 3 and normal == 3:
        lines.append(f"{top}, 2, 2, 0.")
    if a.slab:
        lines.append("NALL, 3, 3, 0.")
    # OUTPUT=3D: in 2D, CalculiX expands the mesh to one layer of 3D elements and writes the
    # node-to-surface contact results on the expanded nodes; asking for the expanded mesh puts
    # their coordinates in the .frd, and ccx_run.py maps every result back by coordinates.
    out3d = ", OUTPUT=3D" if dim == 2 else ""
    lines += [f"*NODE FILE{out3d}", "U", f"*EL FILE{out3d}", "S", "*CONTACT FILE", "CSTR", "*END STEP"]
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(a.out[:-4] + ".json", "w") as f:
        json.dump(sidecar, f)
    print(f"{a.out}: {len(mesh.points)} nodes, {next_id - 1} elements, contact {ctype}")


def element_cards(mesh, cells, bodies, element_name, element_ids, lines):
    """*ELEMENT cards of the cells of `bodies` (one ELSET per body, one card per cell type named
    by element_name(meshio type)), numbered from 1; fills element_ids[(block, index)] and returns
    ({body: [first, last]}, next free number). At most 16 entries per line: a C3D20 continues on
    a second line."""
    next_id, body_range = 1, {}
    for body in bodies:
        first = next_id
        by_type = {}
        for b, i in cells[body]:
            by_type.setdefault(mesh.cells[b].type, []).append((b, i))
        for ctype, members in by_type.items():
            lines.append(f"*ELEMENT, TYPE={element_name(ctype)}, ELSET={body}")
            for b, i in members:
                element_ids[(b, i)] = next_id
                entries = [str(next_id)] + [str(int(n) + 1) for n in mesh.cells[b].data[i]]
                lines += [", ".join(entries[k:k + 16]) + ("," if k + 16 < len(entries) else "")
                          for k in range(0, len(entries), 16)]
                next_id += 1
        body_range[body] = [first, next_id - 1]
    return body_range, next_id


def hertz(mesh, a):
    """The Hertz scene of testcases/hertz_*.lua: ball (BALL) pressed by Q on BALL_TOP onto the
    block (BLOCK, bottom fixed), symmetry on x = 0 (2D: AXIS_*; 3D: SYMX_* and SYMY_* on y = 0),
    E = 1e9 Pa, nu = 0.3, frictionless; slave BLOCK_TOP, master BALL_SURF. The ball is held by
    the contact alone. The sidecar gives the point O_BLOCK and the elements of the block."""
    cells, nodes = groups(mesh)
    dim = 3 if any(c.type.startswith("hexa") for c in mesh.cells) else 2
    lines = ["*HEADING", f"Hertz {dim}D from {a.mesh} (lunaster tests/bench/study)", "*NODE, NSET=NALL"]
    for n, x in enumerate(mesh.points):
        z = x[2] if dim == 3 else 0.0
        lines.append(f"{n + 1}, {x[0]:.12g}, {x[1]:.12g}, {z:.12g}")
    body_range, next_id = element_cards(mesh, cells, ("BALL", "BLOCK"),
                                        lambda ctype: AXIS_ELEMENTS[ctype] if a.axis else ELEMENTS[ctype][0],
                                        element_ids, lines)
    fixed = {"BLOCK_BOTTOM": (1, dim)}
    if dim == 2:
        fixed.update(AXIS_BALL=(1, 1), AXIS_BLOCK=(1, 1))
    else:
        fixed.update(SYMX_BALL=(1, 1), SYMX_BLOCK=(1, 1), SYMY_BALL=(2, 2), SYMY_BLOCK=(2, 2))
    for name in fixed:
        members = sorted({int(n) + 1 for b, i in cells[name] for n in mesh.cells[b].data[i]})
        lines.append(f"*NSET, NSET=N{name}")
        lines += [", ".join(map(str, members[k:k + 12])) for k in range(0, len(members), 12)]
    lines.append("*SURFACE, NAME=SBLOCK_TOP, TYPE=ELEMENT")
    lines += [f"{e}, S{f}" for e, f in face_surface(mesh, cells, "BLOCK_TOP", ["BLOCK"])]
    lines.append("*SURFACE, NAME=SBALL_SURF, TYPE=ELEMENT")
    lines += [f"{e}, S{f}" for e, f in face_surface(mesh, cells, "BALL_SURF", ["BALL"])]
    lines += ["*MATERIAL, NAME=MAT", "*ELASTIC", "1.0e9, 0.3"]
    for body in ("BALL", "BLOCK"):
        lines.append(f"*SOLID SECTION, ELSET={body}, MATERIAL=MAT")
        if dim == 2 and not a.axis:
            lines.append("1.")
    lines += ["*SURFACE INTERACTION, NAME=SI1", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
              f"{a.penalty:.6g}"]
    ctype = {"nts": "NODE TO SURFACE", "sts": "SURFACE TO SURFACE", "mortar": "MORTAR"}[a.contact]
    lines += [f"*CONTACT PAIR, INTERACTION=SI1, TYPE={ctype}", "SBLOCK_TOP, SBALL_SURF"]
    lines += ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY"]
    lines += [f"N{name}, {lo}, {hi}, 0." for name, (lo, hi) in fixed.items()]
    lines.append("*DLOAD")
    lines += [f"{e}, P{f}, {a.hertz:.12g}" for e, f in face_surface(mesh, cells, "BALL_TOP", ["BALL"])]
    out3d = ", OUTPUT=3D" if dim == 2 else ""
    lines += [f"*NODE FILE{out3d}", "U", "*CONTACT FILE", "CSTR", "*END STEP"]
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    o = nodes["O_BLOCK"][0]
    with open(a.out[:-4] + ".json", "w") as f:
        json.dump(dict(hertz=True, o_xyz=[float(v) for v in mesh.points[o][:dim]],
                       slave_elements=body_range["BLOCK"]), f)
    print(f"{a.out}: {len(mesh.points)} nodes, {next_id - 1} elements, contact {ctype}")


if __name__ == "__main__":
    main()
