#!/usr/bin/env python3
"""Writes the hostile-input corpus: scene, mesh and tet files that must each be
refused (exit 2) or stopped (exit 3) with a message naming the file and the
field, within a bounded time and memory. Usage: make_corpus.py OUT_DIR

OUT_DIR receives the files and cases.json: a list of
{"name", "args", "exit", "expect": [substrings of stderr]}, where "args" is
the recoil command line with {dir} standing for OUT_DIR. Commands run in an
empty working folder and give no -o, so a file written outside output/NAME/
shows.
"""
import copy
import json
import os
import sys

out_dir = sys.argv[1]
os.makedirs(out_dir, exist_ok=True)
cases = []


def base_scene():
    return {
        "recoil": 1,
        "name": "hostile",
        "simulation": {"dt": 0.01, "duration": 0.05},
        "bodies": [
            {"name": "ground", "type": "plane"},
            {"name": "box", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]},
             "transform": {"position": [0, 0.2, 0]}},
        ],
    }


def soft_scene():
    s = base_scene()
    s["bodies"][1] = {"name": "jelly", "type": "deformable", "primitive": {"box": [0.1, 0.1, 0.1]},
                      "tets": {"resolution": 2}, "transform": {"position": [0, 0.2, 0]}}
    return s


def set_path(doc, pointer, value):
    """Sets doc at a JSON pointer such as /bodies/1/velocity/1."""
    parts = [p for p in pointer.split("/") if p]
    node = doc
    for p, after in zip(parts[:-1], parts[1:]):
        key = int(p) if isinstance(node, list) else p
        if not isinstance(node, list) and key not in node:
            node[key] = [0, 0, 0] if after.isdigit() else {}
        node = node[key]
    last = int(parts[-1]) if isinstance(node, list) else parts[-1]
    node[last] = value


def write(name, text):
    with open(os.path.join(out_dir, name), "w", encoding="utf-8") as f:
        f.write(text)


def add(name, text, pointer, exit_code=2, command="run", extra="--no-render", more=()):
    write(name, text)
    args = f"{command} {{dir}}/{name} {extra}".strip()
    expect = [name] + ([pointer] if pointer else []) + list(more)
    cases.append({"name": name, "args": args, "exit": exit_code, "expect": expect})


def scene_case(name, pointer, value, make=base_scene, **kw):
    s = make()
    set_path(s, pointer, value)
    add(name, json.dumps(s, indent=1), pointer, **kw)


# Numbers beyond double range: the JSON parser itself overflows.
def overflow_case(name, pointer, literal, make=base_scene):
    s = make()
    set_path(s, pointer, "@@OVERFLOW@@")
    add(name, json.dumps(s, indent=1).replace('"@@OVERFLOW@@"', literal), pointer)


for i, (ptr, lit) in enumerate([
        ("/simulation/dt", "1e400"), ("/simulation/dt", "-1e400"), ("/simulation/duration", "1e400"),
        ("/simulation/gravity", "[0, -1e400, 0]"), ("/bodies/1/velocity", "[1e999, 0, 0]"),
        ("/bodies/1/transform/position", "[0, 1e400, 0]"), ("/bodies/1/density", "1e500"),
        ("/render/fps", "1e400"), ("/recoil", "1e400")]):
    overflow_case(f"overflow-{i:02d}.json", ptr, lit)

# Finite but absurd magnitudes, every numeric field.
huge = 1e308
tiny = 1e-300
rigid_fields = [
    ("/simulation/dt", tiny), ("/simulation/dt", 1e-12), ("/simulation/gravity/1", -huge),
    ("/simulation/solver/tolerance", tiny), ("/simulation/contact/margin", tiny),
    ("/bodies/1/velocity/1", huge), ("/bodies/1/velocity/0", -1e6), ("/bodies/1/angular_velocity/1", huge),
    ("/bodies/1/angular_velocity/2", 1e7), ("/bodies/1/transform/position/0", 1e300),
    ("/bodies/1/transform/position/1", -1e12), ("/bodies/1/transform/rotation/2", huge),
    ("/bodies/1/transform/scale", huge), ("/bodies/1/transform/scale", tiny),
    ("/bodies/1/transform/scale", [1, 1e300, 1]), ("/bodies/1/transform/scale", [1, tiny, 1]),
    ("/bodies/1/density", huge), ("/bodies/1/density", tiny),
    ("/bodies/1/primitive/box", [1e300, 0.1, 0.1]), ("/bodies/1/primitive/box", [tiny, 0.1, 0.1]),
    ("/bodies/0/point/1", huge), ("/bodies/0/normal", [huge, huge, 0]),
    ("/render/fps", tiny), ("/render/camera/fov", huge), ("/render/camera/azimuth", huge),
    ("/render/camera/distance", huge), ("/render/camera/target/0", huge),
]
for i, (ptr, value) in enumerate(rigid_fields):
    scene_case(f"range-rigid-{i:02d}.json", ptr, value)

soft_fields = [
    ("/bodies/1/material/youngs_modulus", huge), ("/bodies/1/material/youngs_modulus", tiny),
    ("/bodies/1/material/density", huge), ("/bodies/1/material/density", tiny),
    ("/bodies/1/velocity/1", -huge), ("/bodies/1/pinned", {"min": [-huge, 0, 0], "max": [0, 0, 0]}),
    ("/bodies/1/collision", {"edge_length": tiny}), ("/bodies/1/collision", {"triangles": 2147483647}),
    ("/bodies/1/tets/resolution", 100000),
]
for i, (ptr, value) in enumerate(soft_fields):
    scene_case(f"range-soft-{i:02d}.json", ptr, value, make=soft_scene)

# A kinematic body's motion and the camera of an orbit.
s = base_scene()
s["bodies"][1]["type"] = "kinematic"
s["bodies"][1]["motion"] = {"velocity": [0, 0, huge]}
add("range-kinematic.json", json.dumps(s), "/bodies/1/motion/velocity/2")
s = base_scene()
s["render"] = {"camera": {"mode": "orbit", "turns": huge}}
add("range-orbit-turns.json", json.dumps(s), "/render/camera/turns")
s = base_scene()
s["render"] = {"camera": {"mode": "orbit", "distance": huge}}
add("range-orbit-distance.json", json.dumps(s), "/render/camera/distance")

# Work that cannot fit: too many frames, steps, tetrahedra or pixels.
s = base_scene()
s["simulation"]["duration"] = 1e6
s["render"] = {"fps": 1000}
add("work-frames.json", json.dumps(s), "/simulation/duration")
s = base_scene()
s["simulation"].update({"dt": 1e-6, "duration": 1e5})
add("work-steps.json", json.dumps(s), "/simulation/duration")
s = soft_scene()
s["bodies"][1]["tets"]["resolution"] = 256
add("work-tets.json", json.dumps(s), "/bodies/1/tets/resolution", more=["GiB"])
s = base_scene()
s["render"] = {"resolution": [16384, 16384], "msaa": 4}
add("work-pixels.json", json.dumps(s), "/render/resolution", extra="", more=["GiB"])

# Names that are not safe folder names.
for i, name in enumerate(["..", ".", "a/b", "", "tab\there", "bell\u0007", "x" * 300, "nul\u0000byte"]):
    s = base_scene()
    s["name"] = name
    add(f"name-{i:02d}.json", json.dumps(s), "/name")
for i, name in enumerate(["line\nbreak", "esc\u001b[31m", ""]):
    s = base_scene()
    s["bodies"][1]["name"] = name
    add(f"body-name-{i:02d}.json", json.dumps(s), "/bodies/1/name")

# Types, structure and syntax.
structural = {
    "syntax-truncated.json": ('{"recoil": 1, "bodies": [', None),
    "syntax-empty.json": ("", None),
    "syntax-nul.json": ("\u0000", None),
    "syntax-bom-garbage.json": ("\ufeff\u00ff\u00fe", None),
    "syntax-deep.json": ("[" * 100000 + "]" * 100000, None),
    "type-root-array.json": ("[1, 2, 3]", "/"),
    "type-bodies-object.json": ('{"recoil": 1, "bodies": {}}', "/bodies"),
    "type-dt-string.json": (json.dumps({**base_scene(), "simulation": {"dt": "0.01"}}), "/simulation/dt"),
    "type-velocity-short.json": (None, "/bodies/1/velocity"),
    "type-recoil-float.json": (json.dumps({**base_scene(), "recoil": 1.5}), "/recoil"),
    "type-recoil-huge-int.json": (json.dumps(base_scene()).replace('"recoil": 1', '"recoil": 123456789012345678901234567890'), "/recoil"),
}
for name, (text, pointer) in structural.items():
    if text is None:
        s = base_scene()
        s["bodies"][1]["velocity"] = [1, 2]
        text = json.dumps(s)
    add(name, text, pointer)

# Files named by a scene that are not meshes: missing, a folder, a device.
for i, target in enumerate(["missing.obj", ".", "/dev/zero", "/dev/null", "/proc/self/mem"]):
    s = base_scene()
    s["bodies"][1] = {"name": "m", "type": "rigid", "mesh": target}
    add(f"mesh-path-{i:02d}.json", json.dumps(s), "/bodies/1/mesh")

# Mesh files with hostile content.
obj_files = {
    "huge-coords.obj": "v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n",
    "nan-coords.obj": "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n",
    "inf-coords.obj": "v 0 0 0\nv inf 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n",
    "bad-index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
    "no-faces.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n",
    "degenerate.obj": "v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n",
    "garbage.obj": "\u00ff\u00fe binary \u0000\u0001 garbage\n" * 20,
}
for i, (mesh, text) in enumerate(obj_files.items()):
    write(mesh, text)
    for kind in ("rigid", "deformable"):
        s = base_scene()
        s["bodies"][1] = {"name": "m", "type": kind, "mesh": mesh}
        add(f"mesh-{os.path.splitext(mesh)[0]}-{kind}.json", json.dumps(s), "/bodies/1/mesh")

# Tetrahedral files with hostile content, each read through a scene.
tet_files = {
    "nodes-1e9.node": "1000000000 3 0 0\n1 0 0 0\n",
    "nodes-negative.node": "-5 3 0 0\n",
    "nodes-nan.node": "4 3 0 0\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n",
    "nodes-huge.node": "4 3 0 0\n1 0 0 0\n2 1e300 0 0\n3 0 1 0\n4 0 0 1\n",
    "nodes-truncated.node": "4 3 0 0\n1 0 0 0\n2 1 0\n",
    "nodes-empty.node": "",
    "gmsh-1e9.msh": "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n3 1 0 1000000000\n1\n0 0 0\n$EndNodes\n",
    "gmsh-v2-1e9.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000000000\n1 0 0 0\n$EndNodes\n",
    "gmsh-bad-index.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 0 1 2 3 99\n$EndElements\n",
    "gmsh-flat.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n$EndNodes\n$Elements\n1\n1 4 0 1 2 3 4\n$EndElements\n",
    "gmsh-binary.msh": "$MeshFormat\n2.2 1 8\n\u0001\u0000\u0000\u0000\n$EndMeshFormat\n",
    "gmsh-garbage.msh": "\u00ff" * 500,
    "gmsh-no-end.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n",
}
for mesh, text in tet_files.items():
    write(mesh, text)
    stem = os.path.splitext(mesh)[0]
    # A coordinate of 1e300 makes its tetrahedron's volume overflow: the .ele
    # line that uses it is named.
    named = stem + ".ele" if stem == "nodes-huge" else mesh
    if mesh.endswith(".node"):
        # TetGen pairs FILE.node with FILE.ele.
        write(stem + ".ele", "1 4 0\n1 1 2 3 4\n")
    s = base_scene()
    s["bodies"][1] = {"name": "t", "type": "deformable", "mesh": mesh}
    add(f"tet-{stem}.json", json.dumps(s), "/bodies/1/mesh", more=[named])
ele_files = {
    "ele-1e9.ele": "1000000000 4 0\n1 1 2 3 4\n",
    "ele-bad-index.ele": "1 4 0\n1 1 2 3 99\n",
    "ele-negative.ele": "1 4 0\n1 -1 2 3 4\n",
}
good_node = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
for ele, text in ele_files.items():
    stem = os.path.splitext(ele)[0]
    write(ele, text)
    write(stem + ".node", good_node)
    s = base_scene()
    s["bodies"][1] = {"name": "t", "type": "deformable", "mesh": ele}
    add(f"tet-{stem}.json", json.dumps(s), "/bodies/1/mesh", more=[ele])

# An inverted tetrahedron is turned the right way, not refused: the run succeeds.
write("ele-inverted.ele", "1 4 0\n1 1 3 2 4\n")
write("ele-inverted.node", good_node)
s = base_scene()
s["bodies"][1] = {"name": "t", "type": "deformable", "mesh": "ele-inverted.ele"}
add("tet-ele-inverted.json", json.dumps(s), "", exit_code=0)
cases[-1]["expect"] = []

# Special files in place of a tet file: a FIFO and /dev/zero behind a symlink.
os.mkfifo(os.path.join(out_dir, "fifo.ele"))
write("fifo.node", good_node)
os.symlink("/dev/zero", os.path.join(out_dir, "zero.ele"))
write("zero.node", good_node)
for special in ("fifo.ele", "zero.ele"):
    s = base_scene()
    s["bodies"][1] = {"name": "t", "type": "deformable", "mesh": special}
    add(f"tet-{os.path.splitext(special)[0]}.json", json.dumps(s), "/bodies/1/mesh")

# Many bodies: a million are refused by the file's size, 10 001 by their
# count, and 10 000 whose last is invalid after a linear-time parse.
def many_bodies(name, count, last):
    bodies = ['{"name": "ground", "type": "plane"}']
    for i in range(1, count):
        bodies.append(f'{{"name": "b{i}", "type": "rigid", "primitive": {{"box": [0.02, 0.02, 0.02]}}, '
                      f'"transform": {{"position": [{i % 1000 * 0.03}, {i // 1000 * 0.03 + 0.1}, 0]}}}}')
    bodies.append(last)
    write(name, '{"recoil": 1, "name": "many", "bodies": [' + ",".join(bodies) + "]}")


many_bodies("million-bodies.json", 1000000, '{"name": "last", "type": "rigid", "primitive": {"box": [1, 1, 1]}}')
cases.append({"name": "million-bodies.json", "args": "run {dir}/million-bodies.json --no-render", "exit": 2,
              "expect": ["million-bodies.json", "MiB; at most 32 MiB"]})
write("too-many-bodies.json", '{"recoil": 1, "bodies": [' + ",".join(['{"type": "plane"}'] * 10001) + "]}")
cases.append({"name": "too-many-bodies.json", "args": "run {dir}/too-many-bodies.json --no-render", "exit": 2,
              "expect": ["too-many-bodies.json", "/bodies", "at most 10000"]})
many_bodies("last-body-invalid.json", 9999, '{"name": "last", "type": "rigid", "primitive": {"sphere": -1}}')
cases.append({"name": "last-body-invalid.json", "args": "run {dir}/last-body-invalid.json --no-render", "exit": 2,
              "expect": ["last-body-invalid.json", "/bodies/9999/primitive/sphere"]})

# Runs that go wrong after they start: exit 3 naming the scene file.
s = base_scene()
s["bodies"].append({"name": "box2", "type": "rigid", "primitive": {"box": [0.1, 0.1, 0.1]},
                    "transform": {"position": [0, 0.22, 0]}})
add("start-interpenetrating.json", json.dumps(s), "", more=["'box'", "'box2'"])

# A soft bunny thrown at the ground at 2 km/s folds through itself on impact:
# the runaway contact search stops the run (exit 3) at its second step, with
# several times the candidates it allows. (At 80 m/s the contact solve holds
# the crushed bunny to 16-18 candidates a vertex, and the run ends on its
# inverted elements after 0.1 s: 20 steps of 7-10 s each.)
bunny = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "assets", "meshes", "bunny.obj")
s = base_scene()
s["simulation"] = {"dt": 0.005, "duration": 0.5}
s["bodies"][1] = {"name": "bunny", "type": "deformable", "mesh": os.path.abspath(bunny), "tets": {"resolution": 10},
                  "transform": {"scale": 0.3, "position": [0, 0.3, 0]}, "velocity": [0, -2000, 0],
                  "material": {"youngs_modulus": 2e5, "damping": 0.02}}
add("runaway-fast-bunny.json", json.dumps(s), "", exit_code=3, more=["'bunny'", "contact candidates"])

# Command-line options out of range.
write("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n")
for i, option in enumerate(["--camera-distance 1e308", "--fps 1e-300", "--resolution 99999999x2",
                            "--seconds 1e308", "--height 1e308", "--count 1000000000"]):
    command = "drop" if any(k in option for k in ("--seconds", "--height", "--count")) else "turntable"
    flag = option.split()[0]
    cases.append({"name": f"option-{i:02d}", "args": f"{command} {{dir}}/cube.obj {option}",
                  "exit": 2, "expect": [flag]})

with open(os.path.join(out_dir, "cases.json"), "w") as f:
    json.dump(cases, f, indent=1)
print(f"{len(cases)} cases, {len(os.listdir(out_dir))} files in {out_dir}")
