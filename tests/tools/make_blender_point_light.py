#!/usr/bin/env python3
"""Writes samples/scenes/blender-point-light.gltf: the scene of issue 11 as Blender's glTF
exporter (lighting mode "Standard", PBR_WATTS_TO_LUMENS = 683) writes it. A 40 m x 40 m
ground plane (base colour 0.8, roughness 1), a glossy and a glass sphere (KHR_materials_
transmission), and a 3000 W point light 8 m above the plane's centre, exported as
3000 / (4 pi) * 683 = 163053.5 cd. Run from the repository root; the output is committed."""
import base64, json, math, struct

def sphere(cx, cy, cz, r, rings=12, segs=24):
    pos, nor, idx = [], [], []
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segs + 1):
            ph = 2 * math.pi * j / segs
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            nor.append(n)
            pos.append((cx + r * n[0], cy + r * n[1], cz + r * n[2]))
    for i in range(rings):
        for j in range(segs):
            a, b = i * (segs + 1) + j, (i + 1) * (segs + 1) + j
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nor, idx

def plane(h):
    pos = [(-h, 0, -h), (-h, 0, h), (h, 0, h), (h, 0, -h)]
    return pos, [(0, 1, 0)] * 4, [0, 1, 2, 0, 2, 3]

buf, views, accessors, meshes = bytearray(), [], [], []
def add(data, fmt, target, acc_type, comp, count, minmax=None):
    while len(buf) % 4: buf.append(0)
    off = len(buf)
    for item in data: buf.extend(struct.pack(fmt, *item) if isinstance(item, tuple) else struct.pack(fmt, item))
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(buf) - off, "target": target})
    a = {"bufferView": len(views) - 1, "componentType": comp, "count": count, "type": acc_type}
    if minmax: a["min"], a["max"] = minmax
    accessors.append(a)
    return len(accessors) - 1

def mesh(name, geo, material):
    pos, nor, idx = geo
    lo = [min(p[k] for p in pos) for k in range(3)]
    hi = [max(p[k] for p in pos) for k in range(3)]
    p = add(pos, "<3f", 34962, "VEC3", 5126, len(pos), (lo, hi))
    n = add(nor, "<3f", 34962, "VEC3", 5126, len(nor))
    i = add(idx, "<I", 34963, "SCALAR", 5125, len(idx))
    meshes.append({"name": name, "primitives": [{"attributes": {"POSITION": p, "NORMAL": n}, "indices": i, "material": material}]})

mesh("Plane", plane(20.0), 0)
mesh("GlossySphere", sphere(-2.0, 1.0, 0.0, 1.0), 1)
mesh("GlassSphere", sphere(2.0, 1.0, 0.0, 1.0), 2)
pitch = math.atan2(6.0, 14.0)  # camera at (0, 6, 14) looking at the origin
gltf = {
    "asset": {"version": "2.0", "generator": "tests/tools/make_blender_point_light.py (Blender exporter conventions)"},
    "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_transmission"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"name": "Point", "type": "point", "color": [1, 1, 1], "intensity": 3000 / (4 * math.pi) * 683}]}},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
    "nodes": [
        {"name": "Plane", "mesh": 0},
        {"name": "GlossySphere", "mesh": 1},
        {"name": "GlassSphere", "mesh": 2},
        {"name": "Point", "translation": [0, 8, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "Camera", "camera": 0, "translation": [0, 6, 14], "rotation": [-math.sin(pitch / 2), 0, 0, math.cos(pitch / 2)]},
    ],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6911, "aspectRatio": 1.3333, "znear": 0.1, "zfar": 100}}],
    "materials": [
        {"name": "Ground", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0, "roughnessFactor": 1}},
        {"name": "Glossy", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1], "metallicFactor": 0, "roughnessFactor": 0.2}},
        {"name": "Glass", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
         "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}}},
    ],
    "meshes": meshes, "accessors": accessors, "bufferViews": views,
    "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
}
with open("samples/scenes/blender-point-light.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
