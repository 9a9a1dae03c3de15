#!/usr/bin/env python3
"""Writes the benchmark's big instanced scene as one .glb: a 512x512-cell heightfield
(524,288 triangles) and 64 instances of one 20,000-triangle sphere on it (1.8 M triangles
rendered, 0.54 M stored), a camera and a sun lamp (KHR_lights_punctual), so that tools/benchmark
times traversal of a scene of real size with instancing, in wavepath and in Cycles.

    tools/make_instanced_scene.py big.glb

Python 3 standard library only.
"""
import argparse
import array
import json
import math
import struct

CELLS = 512            # heightfield cells a side: 2 * 512^2 triangles
SPHERE_SEGMENTS = 100  # around; with 101 rings: 2 * 100 * 100 = 20,000 triangles
SPHERE_RINGS = 101
GRID = 8               # 8 x 8 sphere instances
SIDE = 8.0             # the heightfield spans [-4, 4] in x and z


def height(x, z):
    """The heightfield's y at (x, z): rolling hills a few tenths high."""
    return 0.25 * math.sin(1.7 * x) * math.cos(1.3 * z) + 0.1 * math.sin(5.1 * x + 2.3 * z)


def heightfield():
    positions, normals, indices = array.array("f"), array.array("f"), array.array("I")
    step = SIDE / CELLS
    for j in range(CELLS + 1):
        z = -SIDE / 2 + j * step
        for i in range(CELLS + 1):
            x = -SIDE / 2 + i * step
            positions.extend((x, height(x, z), z))
            # Central differences of the height give the normal (-dy/dx, 1, -dy/dz).
            dx = (height(x + 1e-3, z) - height(x - 1e-3, z)) / 2e-3
            dz = (height(x, z + 1e-3) - height(x, z - 1e-3)) / 2e-3
            length = math.sqrt(dx * dx + 1.0 + dz * dz)
            normals.extend((-dx / length, 1.0 / length, -dz / length))
    for j in range(CELLS):
        for i in range(CELLS):
            a = j * (CELLS + 1) + i
            b, c, d = a + 1, a + CELLS + 1, a + CELLS + 2
            indices.extend((a, c, b, b, c, d))
    return positions, normals, indices


def sphere(radius):
    positions, normals, indices = array.array("f"), array.array("f"), array.array("I")
    for r in range(SPHERE_RINGS):
        theta = math.pi * r / (SPHERE_RINGS - 1)
        for s in range(SPHERE_SEGMENTS + 1):
            phi = 2.0 * math.pi * s / SPHERE_SEGMENTS
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            positions.extend(radius * c for c in n)
            normals.extend(n)
    for r in range(SPHERE_RINGS - 1):
        for s in range(SPHERE_SEGMENTS):
            a = r * (SPHERE_SEGMENTS + 1) + s
            b, c, d = a + 1, a + SPHERE_SEGMENTS + 1, a + SPHERE_SEGMENTS + 2
            indices.extend((a, b, c, b, d, c))
    return positions, normals, indices


class Buffer:
    """The .glb's binary chunk, with one buffer view and accessor per array."""

    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def add(self, values, kind, component, target, bounds=False):
        offset = len(self.data)
        self.data += values.tobytes()
        self.data += b"\0" * (-len(self.data) % 4)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(values) * values.itemsize,
                           "target": target})
        width = {"SCALAR": 1, "VEC3": 3}[kind]
        accessor = {"bufferView": len(self.views) - 1, "componentType": component, "count": len(values) // width,
                    "type": kind}
        if bounds:
            accessor["min"] = [min(values[k::3]) for k in range(3)]
            accessor["max"] = [max(values[k::3]) for k in range(3)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


def mesh_of(buffer, arrays, material):
    positions, normals, indices = arrays
    return {"primitives": [{"attributes": {"POSITION": buffer.add(positions, "VEC3", 5126, 34962, True),
                                           "NORMAL": buffer.add(normals, "VEC3", 5126, 34962)},
                            "indices": buffer.add(indices, "SCALAR", 5125, 34963), "material": material}]}


def quaternion_looking_down(pitch):
    """A rotation about +x by -pitch radians: what looks along -z (a camera, a sun) tilts down."""
    return [-math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    args = parser.parse_args()
    buffer = Buffer()
    meshes = [mesh_of(buffer, heightfield(), 0), mesh_of(buffer, sphere(0.28), 1)]
    nodes = [{"name": "ground", "mesh": 0}]
    for j in range(GRID):
        for i in range(GRID):
            x = -SIDE / 2 + (i + 0.5) * SIDE / GRID
            z = -SIDE / 2 + (j + 0.5) * SIDE / GRID
            nodes.append({"name": f"sphere {i},{j}", "mesh": 1, "translation": [x, height(x, z) + 0.25, z]})
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 3.2, 6.2],
                  "rotation": quaternion_looking_down(math.radians(30))})
    # The sun shines along -z tilted 55 degrees down: from behind the camera, shadows beyond.
    nodes.append({"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}},
                  "rotation": quaternion_looking_down(math.radians(55))})
    gltf = {
        "asset": {"version": "2.0", "generator": "wavepath tools/make_instanced_scene.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 2000.0}]}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [
            {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.35, 0.45, 0.3, 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.9}},
            {"name": "spheres", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.55, 0.4, 1.0],
                                                         "metallicFactor": 0.0, "roughnessFactor": 0.4}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.05}}],
        "accessors": buffer.accessors,
        "bufferViews": buffer.views,
        "buffers": [{"byteLength": len(buffer.data)}],
    }
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    with open(args.output, "wb") as out:
        out.write(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(buffer.data)))
        out.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        out.write(struct.pack("<II", len(buffer.data), 0x004E4942) + bytes(buffer.data))


if __name__ == "__main__":
    main()
