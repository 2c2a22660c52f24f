#!/usr/bin/env python3
"""Writes animated_boxes.gltf (tests/unit/test_scene_animation.cpp, tests/e2e/animation_cli_test.sh, the editor's
timeline test, the fuzz corpus): a floor and boxes driven by three animations with every channel path and
interpolation, each value chosen so the test can state the pose by hand. Run again after changing it."""
import base64, json, os, struct

here = os.path.dirname(os.path.abspath(__file__))
blob = bytearray()
views, accessors = [], []

def add(values, fmt, type_, count, minmax=False):
    while len(blob) % 4: blob.append(0)
    offset = len(blob)
    blob.extend(struct.pack("<%d%s" % (len(values), fmt), *values))
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
    a = {"bufferView": len(views) - 1, "componentType": 5126 if fmt == "f" else 5125, "count": count, "type": type_}
    if minmax:
        a["min"], a["max"] = [min(values)], [max(values)]
    accessors.append(a)
    return len(accessors) - 1

# A unit cube centred on its origin, and a 24 x 24 floor.
c = [(x, y, z) for z in (-0.5, 0.5) for y in (-0.5, 0.5) for x in (-0.5, 0.5)]
cube_idx = [0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5]
cube_pos = add([v for p in c for v in p], "f", "VEC3", 8)
accessors[cube_pos]["min"], accessors[cube_pos]["max"] = [-0.5] * 3, [0.5] * 3
cube_ind = add(cube_idx, "I", "SCALAR", len(cube_idx))
floor = [(-12, 0, -12), (12, 0, -12), (12, 0, 12), (-12, 0, 12)]
floor_pos = add([v for p in floor for v in p], "f", "VEC3", 4)
accessors[floor_pos]["min"], accessors[floor_pos]["max"] = [-12, 0, -12], [12, 0, 12]
floor_ind = add([0, 2, 1, 0, 3, 2], "I", "SCALAR", 6)

def keys(times):
    return add(times, "f", "SCALAR", len(times), minmax=True)

def vec(values, type_):
    n = 3 if type_ == "VEC3" else 4
    return add([v for t in values for v in t], "f", type_, len(values))

s = 0.7071067811865476
move_t = keys([0.0, 1.0, 2.0])
move_v = vec([(-4, 1, 0), (4, 1, 0), (4, 1, 4)], "VEC3")            # Mover: LINEAR translation
grow_t = keys([0.0, 1.0, 2.0])
grow_v = vec([(1, 1, 1), (0.5, 3, 0.5), (1, 1, 1)], "VEC3")          # Grower: STEP scale
spin_t = keys([0.0, 1.0, 2.0])
spin_v = vec([(0, 0, 0, 1), (0, s, 0, s), (0, -s, 0, -s)], "VEC4")   # Spinner: LINEAR rotation; key 2 = key 1 negated
lift_t = keys([0.0, 2.0])
# Lifter: CUBICSPLINE translation, per key in-tangent, value, out-tangent.
lift_v = vec([(0, 0, 0), (6, 1, 6), (0, 3, 0), (0, -1, 0), (6, 2, 6), (0, 0, 0)], "VEC3")
roll_t = keys([0.0, 2.0])
# Roller: CUBICSPLINE rotation about x from 0 to 90 degrees, zero tangents.
roll_v = vec([(0, 0, 0, 0), (0, 0, 0, 1), (0, 0, 0, 0), (0, 0, 0, 0), (s, 0, 0, s), (0, 0, 0, 0)], "VEC4")

doc = {
    "asset": {"version": "2.0", "generator": "tests/data/scenes/make_animated_boxes.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 3, 4, 5, 6]}],
    "nodes": [
        {"name": "Floor", "mesh": 1},
        {"name": "Mover", "mesh": 0, "translation": [0, 1, -4], "children": [2]},
        {"name": "Rider", "mesh": 0, "translation": [0, 2, 0]},
        {"name": "Grower", "mesh": 0, "translation": [-6, 0.5, -6]},
        {"name": "Spinner", "mesh": 0, "translation": [6, 2, -6], "scale": [3, 0.5, 0.5]},
        {"name": "Lifter", "mesh": 0, "translation": [6, 1, 6]},
        {"name": "Roller", "mesh": 0, "translation": [-6, 1, 6], "scale": [0.5, 0.5, 4]},
    ],
    "meshes": [{"name": "cube", "primitives": [{"attributes": {"POSITION": cube_pos}, "indices": cube_ind}]},
               {"name": "floor", "primitives": [{"attributes": {"POSITION": floor_pos}, "indices": floor_ind}]}],
    "animations": [
        {"name": "Move", "samplers": [{"input": move_t, "output": move_v, "interpolation": "LINEAR"},
                                      {"input": grow_t, "output": grow_v, "interpolation": "STEP"}],
         "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}},
                      {"sampler": 1, "target": {"node": 3, "path": "scale"}}]},
        {"name": "Spin", "samplers": [{"input": spin_t, "output": spin_v}],
         "channels": [{"sampler": 0, "target": {"node": 4, "path": "rotation"}}]},
        {"name": "Cubic", "samplers": [{"input": lift_t, "output": lift_v, "interpolation": "CUBICSPLINE"},
                                       {"input": roll_t, "output": roll_v, "interpolation": "CUBICSPLINE"}],
         "channels": [{"sampler": 0, "target": {"node": 5, "path": "translation"}},
                      {"sampler": 1, "target": {"node": 6, "path": "rotation"}}]},
    ],
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
}
with open(os.path.join(here, "animated_boxes.gltf"), "w") as f:
    json.dump(doc, f, indent=1)
    f.write("\n")

# The fuzz corpus (tests/fuzz/regressions/gltf, replayed by scripts/fuzz-replay): the file itself and hostile
# animations, each of which the loader must skip with a message while the rest of the file loads.
import copy
regressions = os.path.join(here, "..", "..", "fuzz", "regressions", "gltf")

def variant(name, change):
    d = copy.deepcopy(doc)
    change(d)
    with open(os.path.join(regressions, name), "w") as f:
        json.dump(d, f, indent=1)
        f.write("\n")

def extra_accessor(d, values, type_):
    data = struct.pack("<%df" % len(values), *values)
    d["buffers"].append({"byteLength": len(data),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()})
    d["bufferViews"].append({"buffer": len(d["buffers"]) - 1, "byteLength": len(data)})
    n = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[type_]
    d["accessors"].append({"bufferView": len(d["bufferViews"]) - 1, "componentType": 5126,
                           "count": len(values) // n, "type": type_})
    return len(d["accessors"]) - 1

variant("anim-boxes.gltf", lambda d: None)
variant("anim-not-increasing.gltf", lambda d: d["animations"][1]["samplers"][0].update(
    input=extra_accessor(d, [0.0, 2.0, 1.0], "SCALAR")))
variant("anim-count-mismatch.gltf", lambda d: d["animations"][0]["samplers"][0].update(input=lift_t))
variant("anim-nan-key.gltf", lambda d: d["animations"][2]["samplers"][0].update(
    input=extra_accessor(d, [0.0, float("nan")], "SCALAR")))
variant("anim-nan-value.gltf", lambda d: d["animations"][0]["samplers"][1].update(
    output=extra_accessor(d, [1, 1, 1, float("nan"), 1, 1, 1, 1, 1], "VEC3")))
variant("anim-missing-node.gltf", lambda d: d["animations"][0]["channels"][0]["target"].update(node=99))
variant("anim-matrix-node.gltf", lambda d: d["nodes"][4].update(matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]))
variant("anim-bad-sampler.gltf", lambda d: d["animations"][1]["channels"][0].update(sampler=7))
variant("anim-huge-count.gltf", lambda d: d["accessors"][spin_t].update(count=1 << 30, bufferView=None) or
        d["accessors"][spin_t].pop("bufferView"))
