"""A small glTF 2.0 writer with one embedded buffer, shared by the animation generators.

Python 3 standard library only. Accessors are added with typed arrays; the JSON parts
(nodes, meshes, animations, ...) are plain lists the caller fills in.
"""
import base64
import json
import struct

FLOAT, BYTE, UBYTE, SHORT, USHORT, UINT = 5126, 5120, 5121, 5122, 5123, 5125
FORMATS = {FLOAT: "f", BYTE: "b", UBYTE: "B", SHORT: "h", USHORT: "H", UINT: "I"}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


class Gltf:
    def __init__(self):
        self.blob = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "wavepath tools/gltf_builder.py"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                    "accessors": [], "bufferViews": [], "buffers": []}

    def accessor(self, values, type_, component=FLOAT, normalized=False, minmax=False):
        """Adds a flat list of numbers as an accessor of `type_` ("SCALAR", "VEC3", ...)."""
        width = WIDTHS[type_]
        assert len(values) % width == 0, (type_, len(values))
        while len(self.blob) % 4:
            self.blob.append(0)
        data = struct.pack("<%d%s" % (len(values), FORMATS[component]), *values)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)})
        self.blob += data
        accessor = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component,
                    "count": len(values) // width, "type": type_}
        if normalized:
            accessor["normalized"] = True
        if minmax:  # glTF requires bounds on POSITION
            accessor["min"] = [min(values[i::width]) for i in range(width)]
            accessor["max"] = [max(values[i::width]) for i in range(width)]
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def node(self, root=True, **fields):
        self.doc["nodes"].append(fields)
        index = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def mesh(self, primitives, **fields):
        self.doc["meshes"].append({"primitives": primitives, **fields})
        return len(self.doc["meshes"]) - 1

    def material(self, **fields):
        self.doc["materials"].append(fields)
        return len(self.doc["materials"]) - 1

    def animation(self, channels, name=""):
        """Adds one animation from (node, path, interpolation, times, flat values) tuples,
        one sampler per channel."""
        samplers, targets = [], []
        for node, path, interpolation, times, values in channels:
            width = {"translation": "VEC3", "rotation": "VEC4", "scale": "VEC3", "weights": "SCALAR"}[path]
            samplers.append({"input": self.accessor(times, "SCALAR"), "output": self.accessor(values, width),
                             "interpolation": interpolation})
            targets.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})
        self.doc.setdefault("animations", []).append({"name": name, "samplers": samplers, "channels": targets})

    def text(self):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()
        self.doc["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        return json.dumps({k: v for k, v in self.doc.items() if v != []}, indent=1) + "\n"

    def write(self, path):
        with open(path, "w") as f:
            f.write(self.text())
