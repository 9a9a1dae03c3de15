#!/usr/bin/env python3
"""Writes a .glb of one emissive grid mesh of about N triangles, for trying scenes near and past
the device's buffer limits (docs/robustness.md: a 20-million-triangle scene).

    tools/make_grid_scene.py --triangles 20000000 grid.glb

Python 3 standard library only; a 20 M-triangle file (about 360 MB) takes a minute or two.
"""
import argparse
import array
import json
import math
import struct


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--triangles", type=int, default=20_000_000)
    args = parser.parse_args()
    cells = max(1, math.isqrt(args.triangles // 2))  # cells x cells quads of 2 triangles
    side = cells + 1

    positions = array.array("f")
    for y in range(side):
        v = 2.0 * y / cells - 1.0
        for x in range(side):
            positions.extend((2.0 * x / cells - 1.0, v, -2.0))
    indices = array.array("I")
    for y in range(cells):
        row = y * side
        for x in range(cells):
            a = row + x
            indices.extend((a, a + 1, a + side + 1, a, a + side + 1, a + side))
    pos = positions.tobytes()
    idx = indices.tobytes()
    blob = pos + idx
    doc = {
        "asset": {"version": "2.0", "generator": "wavepath tools/make_grid_scene.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"emissiveFactor": [1, 1, 1], "doubleSided": True}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions) // 3, "type": "VEC3",
             "min": [-1, -1, -2], "max": [1, 1, -2]},
            {"bufferView": 1, "componentType": 5125, "count": len(indices), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
        "buffers": [{"byteLength": len(blob)}],
    }
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    with open(args.output, "wb") as out:
        out.write(b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(blob)))
        out.write(struct.pack("<I", len(text)) + b"JSON" + text)
        out.write(struct.pack("<I", len(blob)) + b"BIN\0" + blob)
    print(f"{args.output}: {len(indices) // 3} triangles, {len(positions) // 3} vertices")


if __name__ == "__main__":
    main()
