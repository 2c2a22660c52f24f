#!/usr/bin/env python3
"""Writes the hostile inputs of issue 12 into regressions/preset and regressions/gltf (committed; scripts/test
replays every file there through the sanitized fuzz targets). Run again after changing it."""
import base64, json, os, struct

here = os.path.dirname(os.path.abspath(__file__))
P = lambda name: os.path.join(here, "regressions", "preset", name)
G = lambda name: os.path.join(here, "regressions", "gltf", name)

def write(path, data):
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

head = '{"schema": "shadowlab-preset", "schemaVersion": 1'
write(P("deep-array.json"), head + ', "light": {"direction": ' + "[" * 10000 + "]" * 10000 + "}}")
write(P("deep-object.json"), head + ', "light": ' + '{"a":' * 10000 + "1" + "}" * 10000 + "}")
write(P("deep-set.txt"), head + "}\n--set\nlight.direction=" + "[" * 10000 + "]" * 10000 + "\n")
write(P("non-utf8-set.txt"), (head + "}\n--set\n").encode() + b"view=\xff\nlight.type=\xfe\xfe\n")
write(P("non-utf8-key.json"), (head + ', "shadow": {"depth').encode() + b"\xff\xfe" + b'Bias": 1}}')
write(P("huge-key.json"), head + ', "' + "k" * 100000 + '": 1}')
write(P("schema-version-float.json"), '{"schema": "shadowlab-preset", "schemaVersion": 1.0, "view": "shadow"}')
write(P("resolution-zero.json"), head + ', "shadow": {"resolution": 0}}')

tri = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
def gltf(nodes, scenes=True, buffer=None, extra=None, accessors=None, materials=None):
    doc = {"asset": {"version": "2.0"},
           "buffers": [buffer or {"byteLength": len(tri), "uri": "data:application/octet-stream;base64," +
                                  base64.b64encode(tri).decode()}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(tri)}],
           "accessors": accessors or [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                                       "min": [0, 0, 0], "max": [1, 1, 0]}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "nodes": nodes}
    if scenes: doc["scenes"] = [{"nodes": [0]}]; doc["scene"] = 0
    if materials: doc["materials"] = materials; doc["meshes"][0]["primitives"][0]["material"] = 0
    if extra: doc.update(extra)
    return json.dumps(doc)

text = gltf([{"mesh": 0}])
write(G("deep-extras.gltf"), text[:-1] + ', "extras": ' + "[" * 20000 + "]" * 20000 + "}")
write(G("repeated-children.gltf"), gltf([{"children": [i + 1, i + 1]} for i in range(22)] + [{"mesh": 0}]))
write(G("zero-accessor.gltf"), gltf([{"mesh": 0}], accessors=[{"componentType": 5126, "count": 2**26 - 1,
                                                                 "type": "VEC3"}]))
write(G("negative-offset.gltf"), gltf([{"mesh": 0}], accessors=[{"bufferView": 0, "byteOffset": -4,
                                                                   "componentType": 5126, "count": 3, "type": "VEC3"}]))
write(G("alpha-cutoff-huge.gltf"), gltf([{"mesh": 0}], materials=[{"alphaMode": "MASK", "alphaCutoff": 1e308}]))
payload = base64.b64encode(tri * 1000).decode()
write(G("data-uri-mismatch.gltf"), gltf([{"mesh": 0}], buffer={"byteLength": 36, "uri":
                                           "data:application/octet-stream;base64," + payload}))
write(G("no-root.gltf"), gltf([{"mesh": 0, "children": [1]}, {"children": [0]}], scenes=False))
write(G("huge-bounds.gltf"), gltf([{"mesh": 0, "scale": [1e19, 1e19, 1e19]}]))
write(G("far-spot.gltf"), gltf([{"mesh": 0, "children": [1]}, {"translation": [1e30, 0, 0],
                                 "extensions": {"KHR_lights_punctual": {"light": 0}}}],
                               extra={"extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual":
                                      {"lights": [{"type": "spot", "spot": {}}]}}}))
png = b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" + struct.pack(">II", 100000, 100000) + bytes([8, 6, 0, 0, 0]) + b"\0" * 4
write(G("png-huge.gltf"), gltf([{"mesh": 0}], materials=[{"alphaMode": "MASK", "pbrMetallicRoughness": {
    "baseColorTexture": {"index": 0}}}], extra={"textures": [{"source": 0}], "images": [{"uri":
    "data:image/png;base64," + base64.b64encode(png).decode()}]}))
# GLB: the same triangle, with the JSON chunk nested deep.
j = gltf([{"mesh": 0}]).replace('"uri": "data:application/octet-stream;base64,' + base64.b64encode(tri).decode() + '"', '"x": 0')
j = j[:-1] + ', "extras": ' + "{\"a\":" * 5000 + "1" + "}" * 5000 + "}"
j = j.encode() + b" " * (-len(j) % 4)
glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(j) + 8 + len(tri)) + struct.pack("<I", len(j)) + b"JSON" + j + \
      struct.pack("<I", len(tri)) + b"BIN\0" + tri
write(G("deep-extras.glb"), glb)
