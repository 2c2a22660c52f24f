#!/usr/bin/env python3
"""Writes the committed seed inputs of the fuzz targets into seeds/TARGET (scripts/fuzz-seeds copies them into every
corpus and scripts/fuzz-replay runs each once): light arrays for fuzz_preset and fuzz_export (the preset loader
already validates every light, so light arrays are seeds there rather than a target of their own) and axis texts for
fuzz_sweep_axes. Small on purpose: the fuzzer grows them. Run again after changing it."""
import json, os, shutil

here = os.path.dirname(os.path.abspath(__file__))

def target(name):
    d = os.path.join(here, "seeds", name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return lambda file, text: open(os.path.join(d, file), "w").write(text)

def preset(lights, **top):
    return json.dumps({"schema": "shadowlab-preset", "schemaVersion": 2, **top, "lights": lights}, indent=1)

sun = {"type": "directional", "direction": [-0.5, -1, -0.25]}
spot = {"type": "spot", "position": [2, 6, 3], "direction": [-0.3, -1, -0.5], "spotConeDeg": 70, "range": 20}
point = {"type": "point", "position": [1, 4, 1], "range": 7,
         "shadow": {"resolution": 256, "depthFormat": "d16", "reversedZ": True}}
mixed = [sun, spot, point,
         {**spot, "shadow": {"resolution": 512, "depthFormat": "d24", "receiverPlaneBias": True}},
         {**sun, "enabled": False}, {**point, "castsShadows": False}]

light_arrays = {
    "lights-empty.json": preset([]),
    "lights-mixed.json": preset(mixed, filter={"kind": "pcf", "kernel": 5}),
    "lights-32.json": preset([dict(spot, position=[i % 5, 6, i // 5]) for i in range(32)]),
    "lights-33.json": preset([sun] * 33),                                  # one over kMaxLights
    "lights-odd-entries.json": preset([sun, {}, None, 7, "spot", [1], {"type": "spot", "range": 1e-5}]),
    "lights-tiny-range.json": preset([{**point, "range": 0.0005}, {**spot, "range": 1e300}]),
    "lights-fixed-projection.json": preset([{**sun, "projection": {"autoFit": False, "orthoSize": 0.001,
                                                                    "near": 5, "far": 5.0001}}]),
    "lights-not-array.json": preset({"0": sun}),
    "lights-scene.json": preset([], useSceneLights=True, scene="builtin:courtyard"),
    "lights-set.txt": preset([sun]) + "\n--set\nlights.1.type=point\nlights.1.range=0.0005\nlights.2.type=spot\n"
                      "lights.0.enabled=false\nlights.5.type=spot\nuseSceneLights=true\n",
}
write = target("preset")  # fuzz_export is seeded from the same folder (scripts/fuzz-seeds)
for name, text in light_arrays.items():
    write(name, text)

write = target("sweep_axes")
write("resolution.txt", "shadow.resolution=512,1024,2048")
write("joint-filter.txt", "filter.kind,filter.kernel=pcf:3,pcf:9,point:1\nlights.0.shadow.depthBias=0,1.5,2")
write("alias-and-key.txt", "light.type=spot,point\nlights.0.type=directional,spot")
write("vector-values.txt", "lights.0.direction=[0,-1,0.2],[1,-1,0]\ncamera.fovYDeg=30,60")
write("new-light.txt", preset([sun, spot]) + "\n--axis\nlights.2.type=spot,point\nlights.1.range=5,0.0005")
write("many-lights.txt", preset(mixed) + "\n--axis\nlights.5.shadow.resolution=256,512\n"
      "lights.3.shadow.depthFormat=d16,d24,d32f\nview=lit,shadow")
write("duplicate-value.txt", "shadow.resolution=1024,1024.0,1e3")
write("too-many.txt", "shadow.resolution=" + ",".join(str(64 * i) for i in range(1, 65)) +
      "\nlights.0.shadow.depthBias=" + ",".join(str(i) for i in range(65)))
