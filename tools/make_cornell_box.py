#!/usr/bin/env python3
"""Writes assets/cornell-box.gltf: the classic Cornell box from its published measured data.

Run by hand (python3 tools/make_cornell_box.py [output.gltf]); the output is committed.
Python 3 standard library only.

Source: https://www.graphics.cornell.edu/online/box/data.html (millimetres, +y up, the box
open towards -z where the camera stands). Everything is written in metres. The light quad is
lowered 0.5 mm below the ceiling so that it is not coplanar with it. Every quad
(v0, v1, v2, v3) is split into (v0, v1, v2) and (v0, v2, v3): the red wall is slightly
non-planar in the published data, so the split changes the geometry and must match the
reference render. Vertex order makes every front face point into the box and the light's
front face point down; the light is one-sided, so it emits downwards only.
"""
import base64
import json
import math
import struct
import sys
from pathlib import Path

MM = 0.001
CEILING_Y = 548.8
LIGHT_Y = CEILING_Y - 0.5

# Linear-RGB albedos and the light's radiance, as given with the reference render.
ALBEDO = {
    "white": (0.885809, 0.698859, 0.666422),
    "red": (0.570068, 0.0430135, 0.0443706),
    "green": (0.105421, 0.37798, 0.076425),
}
LIGHT_RADIANCE = (18.387, 10.9873, 2.75357)

CAMERA_POSITION_MM = (278.0, 273.0, -800.0)
# 2 * atan(12.5 / 35): the published 35 mm lens in front of a 25 mm film.
CAMERA_YFOV_DEG = 39.3077

# (node and mesh name, material, quads in mm), in the order of the published table.
OBJECTS = [
    ("floor", "white", [
        [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]]),
    ("ceiling", "white", [
        [(556.0, CEILING_Y, 0.0), (556.0, CEILING_Y, 559.2), (0.0, CEILING_Y, 559.2),
         (0.0, CEILING_Y, 0.0)]]),
    ("back_wall", "white", [
        [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, CEILING_Y, 559.2),
         (556.0, CEILING_Y, 559.2)]]),
    ("right_wall_green", "green", [
        [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, CEILING_Y, 0.0), (0.0, CEILING_Y, 559.2)]]),
    ("left_wall_red", "red", [
        [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, CEILING_Y, 559.2),
         (556.0, CEILING_Y, 0.0)]]),
    ("short_block", "white", [
        [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)],
        [(290.0, 0.0, 114.0), (290.0, 165.0, 114.0), (240.0, 165.0, 272.0), (240.0, 0.0, 272.0)],
        [(130.0, 0.0, 65.0), (130.0, 165.0, 65.0), (290.0, 165.0, 114.0), (290.0, 0.0, 114.0)],
        [(82.0, 0.0, 225.0), (82.0, 165.0, 225.0), (130.0, 165.0, 65.0), (130.0, 0.0, 65.0)],
        [(240.0, 0.0, 272.0), (240.0, 165.0, 272.0), (82.0, 165.0, 225.0), (82.0, 0.0, 225.0)]]),
    ("tall_block", "white", [
        [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)],
        [(423.0, 0.0, 247.0), (423.0, 330.0, 247.0), (472.0, 330.0, 406.0), (472.0, 0.0, 406.0)],
        [(472.0, 0.0, 406.0), (472.0, 330.0, 406.0), (314.0, 330.0, 456.0), (314.0, 0.0, 456.0)],
        [(314.0, 0.0, 456.0), (314.0, 330.0, 456.0), (265.0, 330.0, 296.0), (265.0, 0.0, 296.0)],
        [(265.0, 0.0, 296.0), (265.0, 330.0, 296.0), (423.0, 330.0, 247.0), (423.0, 0.0, 247.0)]]),
    ("light", "light", [
        [(343.0, LIGHT_Y, 227.0), (343.0, LIGHT_Y, 332.0), (213.0, LIGHT_Y, 332.0),
         (213.0, LIGHT_Y, 227.0)]]),
]

FLOAT = 5126
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


def materials():
    """The glTF materials, in the order MATERIAL_INDEX gives."""
    out = []
    for name, albedo in ALBEDO.items():
        # Two-sided like the reference: the walls are never seen from behind anyway. Ideal
        # diffuse like the reference's walls (a glTF dielectric would add a specular coat).
        out.append({
            "name": name,
            "doubleSided": True,
            "pbrMetallicRoughness": {
                "baseColorFactor": [*albedo, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
            "extras": {"wavepath": {"bsdf": "lambert"}},
        })
    strength = max(LIGHT_RADIANCE)
    out.append({
        "name": "light",
        "doubleSided": False,
        "pbrMetallicRoughness": {
            "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
        "emissiveFactor": [c / strength for c in LIGHT_RADIANCE],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": strength}},
        # Black Lambert: it emits and reflects nothing, as in the reference.
        "extras": {"wavepath": {"bsdf": "lambert"}},
    })
    return out


MATERIAL_INDEX = {"white": 0, "red": 1, "green": 2, "light": 3}


def float32(x):
    """x rounded to the float32 the buffer stores, so min/max match the data exactly."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def build():
    blob = bytearray()
    buffer_views, accessors, meshes, nodes = [], [], [], []

    def add_view(data, target):
        buffer_views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                             "target": target})
        blob.extend(data)
        return len(buffer_views) - 1

    for name, material, quads in OBJECTS:
        positions = [tuple(float32(c * MM) for c in v) for quad in quads for v in quad]
        indices = []
        for q in range(len(quads)):
            base = 4 * q
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        # 12-byte positions and 6 two-byte indices per quad keep every view 4-byte aligned.
        position_view = add_view(b"".join(struct.pack("<3f", *p) for p in positions),
                                 ARRAY_BUFFER)
        index_view = add_view(struct.pack(f"<{len(indices)}H", *indices), ELEMENT_ARRAY_BUFFER)
        accessors.append({
            "bufferView": position_view, "componentType": FLOAT, "count": len(positions),
            "type": "VEC3",
            "min": [min(p[i] for p in positions) for i in range(3)],
            "max": [max(p[i] for p in positions) for i in range(3)],
        })
        accessors.append({"bufferView": index_view, "componentType": UNSIGNED_SHORT,
                          "count": len(indices), "type": "SCALAR"})
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1,
            "material": MATERIAL_INDEX[material], "mode": 4}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    # glTF cameras look down their local -z; half a turn about y makes this one look down +z.
    nodes.append({"name": "camera", "camera": 0,
                  "translation": [c * MM for c in CAMERA_POSITION_MM],
                  "rotation": [0.0, 1.0, 0.0, 0.0]})

    return {
        "asset": {"version": "2.0", "generator": "wavepath tools/make_cornell_box.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "cornell-box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials(),
        "cameras": [{"name": "camera", "type": "perspective", "perspective": {
            "yfov": math.radians(CAMERA_YFOV_DEG), "aspectRatio": 1.0, "znear": 0.01}}],
        "accessors": accessors,
        "bufferViews": buffer_views,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode("ascii")}],
    }


def main():
    repo = Path(__file__).resolve().parent.parent
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else repo / "assets" / "cornell-box.gltf"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(build(), indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
