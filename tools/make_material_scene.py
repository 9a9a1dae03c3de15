#!/usr/bin/env python3
"""Writes assets/materials.gltf: rows of analytic spheres showing wavepath's materials.

Run by hand (python3 tools/make_material_scene.py [--plastics] [output.gltf]); the output is
committed. --plastics writes the variant of docs/materials.md's Fresnel-blending figure instead:
every row plastic (red, white, blue) at increasing roughness. Python 3 standard library only.

Back row: gold, roughness increasing to the right; middle row: copper, the same; front row:
red and blue plastic, white ceramic (smooth white plastic), clear glass, rough glass and
tinted glass (Beer's law absorption). The spheres stand on a Lambertian floor (an analytic
plane) under one rectangular area light; there is no other light.
"""
import base64
import json
import math
import struct
import sys
from pathlib import Path

ROUGHNESS = [0.0, 0.15, 0.3, 0.45, 0.6, 0.8]
GOLD = [1.0, 0.766, 0.336]    # F0 of gold and copper, linear RGB (as in Filament's table)
COPPER = [0.955, 0.638, 0.538]
RADIUS = 0.42
SPACING = 1.1
ROWS_Z = [-1.3, 0.0, 1.3]
LIGHT = {"y": 4.0, "half_x": 2.5, "half_z": 1.2, "radiance": 5.0}
CAMERA = {"position": [0.0, 3.4, 8.2], "target": [0.0, 0.3, 0.1], "yfov_deg": 30.0, "aspect": 1.6}


def lambert(name, albedo):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*albedo, 1.0],
            "metallicFactor": 0.0, "roughnessFactor": 1.0}, "extras": {"wavepath": {"bsdf": "lambert"}}}


def pbr(name, base, metallic, roughness, extensions=None):
    material = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*base, 1.0],
                "metallicFactor": metallic, "roughnessFactor": roughness}}
    if extensions:
        material["extensions"] = extensions
    return material


def glass(name, roughness, attenuation=None):
    extensions = {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                  "KHR_materials_ior": {"ior": 1.5}}
    if attenuation:
        extensions["KHR_materials_volume"] = {"attenuationColor": attenuation, "attenuationDistance": 0.3}
    return pbr(name, [1.0, 1.0, 1.0], 0.0, roughness, extensions)


def plastic_rows():
    """Rows of plastics at increasing roughness, back row first."""
    colours = {"red": [0.8, 0.05, 0.05], "white": [0.8, 0.8, 0.8], "blue": [0.05, 0.15, 0.7]}
    return [[pbr(f"{name}-{r}", colour, 0.0, r) for r in ROUGHNESS] for name, colour in colours.items()]


def sphere_materials():
    """Rows of (name, material), back row first."""
    gold = [pbr(f"gold-{r}", GOLD, 1.0, r) for r in ROUGHNESS]
    copper = [pbr(f"copper-{r}", COPPER, 1.0, r) for r in ROUGHNESS]
    front = [pbr("red-plastic", [0.8, 0.05, 0.05], 0.0, 0.2),
             pbr("blue-plastic", [0.05, 0.15, 0.7], 0.0, 0.6),
             pbr("ceramic", [0.9, 0.9, 0.88], 0.0, 0.0),
             glass("clear-glass", 0.0),
             glass("rough-glass", 0.3),
             glass("tinted-glass", 0.0, [0.2, 0.75, 0.35])]
    return [gold, copper, front]


def look_at_quaternion(position, target):
    """Rotation (x, y, z, w) turning the glTF camera's -z towards target: yaw, then pitch."""
    d = [t - p for t, p in zip(target, position)]
    yaw = math.atan2(-d[0], -d[2])
    pitch = math.atan2(d[1], math.hypot(d[0], d[2]))
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    # q = q_yaw(about y) * q_pitch(about x)
    return [cy * sp, sy * cp, -sy * sp, cy * cp]


def light_mesh():
    """A one-sided quad facing down, as one embedded buffer, accessors and views."""
    y, hx, hz = LIGHT["y"], LIGHT["half_x"], LIGHT["half_z"]
    positions = [(-hx, y, -hz), (hx, y, -hz), (hx, y, hz), (-hx, y, hz)]
    indices = [0, 1, 2, 0, 2, 3]
    blob = b"".join(struct.pack("<3f", *p) for p in positions) + struct.pack("<6H", *indices)
    return blob, positions, indices


def build(rows):
    materials = [lambert("floor", [0.5, 0.5, 0.5]),
                 {"name": "light", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1],
                  "metallicFactor": 0.0, "roughnessFactor": 1.0}, "emissiveFactor": [1.0, 1.0, 1.0],
                  "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": LIGHT["radiance"]}}}]
    nodes = [{"name": "floor", "extras": {"wavepath": {"shape": "plane", "material": 0}}},
             {"name": "light", "mesh": 0}]
    for row, z in zip(rows, ROWS_Z):
        for column, material in enumerate(row):
            x = (column - (len(row) - 1) / 2) * SPACING
            materials.append(material)
            nodes.append({"name": material["name"], "translation": [x, RADIUS, z],
                          "extras": {"wavepath": {"shape": "sphere", "radius": RADIUS,
                                                  "material": len(materials) - 1}}})
    nodes.append({"name": "camera", "camera": 0, "translation": CAMERA["position"],
                  "rotation": look_at_quaternion(CAMERA["position"], CAMERA["target"])})
    blob, positions, indices = light_mesh()
    return {
        "asset": {"version": "2.0", "generator": "wavepath tools/make_material_scene.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_ior",
                           "KHR_materials_transmission", "KHR_materials_volume"],
        "scene": 0,
        "scenes": [{"name": "materials", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": [{"name": "light", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1,
                                                     "material": 1, "mode": 4}]}],
        "materials": materials,
        "cameras": [{"name": "camera", "type": "perspective", "perspective": {
            "yfov": math.radians(CAMERA["yfov_deg"]), "aspectRatio": CAMERA["aspect"], "znear": 0.01}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [min(p[i] for p in positions) for i in range(3)],
             "max": [max(p[i] for p in positions) for i in range(3)]},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12, "target": 34963}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(blob).decode("ascii")}],
    }


def main():
    repo = Path(__file__).resolve().parent.parent
    args = sys.argv[1:]
    plastics = "--plastics" in args
    paths = [a for a in args if a != "--plastics"]
    out = Path(paths[0]) if paths else repo / "assets" / "materials.gltf"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(build(plastic_rows() if plastics else sphere_materials()), indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
