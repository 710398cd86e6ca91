#!/usr/bin/env python3
"""Writes the small committed assets the fuzz corpora refer to (tests/fuzz/seed_assets/).

tiny.glb: one quad (two triangles) named with the ICT skin material "M_Face", two morph targets
(jawOpen, smile), a weights animation, a camera and a two-joint skin: every part of the glTF path
in under 3 kB (the ICT face is 4+ MB, far too big for a fuzz seed).
track.csv / track.json: performance tracks for those two targets.
It also writes the glTF and track seeds of corpus/ (tiny.glb, the same as an embedded .gltf,
tracks by time and by frame). Run it again only to change them; the output is deterministic.
"""
import json
import struct
from pathlib import Path

here = Path(__file__).resolve().parent / "seed_assets"


class Bin:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def accessor(self, fmt, values, component_type, type_, count, minmax=None):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data += struct.pack("<" + fmt * len(values), *values)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        acc = {"bufferView": len(self.views) - 1, "componentType": component_type, "count": count, "type": type_}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1


def tiny_glb():
    b = Bin()
    positions = [-0.05, -0.05, 0, 0.05, -0.05, 0, 0.05, 0.05, 0, -0.05, 0.05, 0]
    pos = b.accessor("f", positions, 5126, "VEC3", 4, ([-0.05, -0.05, 0], [0.05, 0.05, 0]))
    idx = b.accessor("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6)
    jaw = b.accessor("f", [0, -0.01, 0.002, 0, -0.01, 0.002, 0, 0, 0, 0, 0, 0], 5126, "VEC3", 4,
                     ([0, -0.01, 0], [0, 0, 0.002]))
    smile = b.accessor("f", [-0.005, 0.003, 0, 0.005, 0.003, 0, 0, 0, 0, 0, 0, 0], 5126, "VEC3", 4,
                       ([-0.005, 0, 0], [0.005, 0.003, 0]))
    joints = b.accessor("B", [0, 1, 0, 0] * 4, 5121, "VEC4", 4)
    weights = b.accessor("f", [0.7, 0.3, 0, 0, 0.7, 0.3, 0, 0, 0.2, 0.8, 0, 0, 0.2, 0.8, 0, 0], 5126, "VEC4", 4)
    identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    ibm = b.accessor("f", identity * 2, 5126, "MAT4", 2)
    times = b.accessor("f", [0, 0.5, 1], 5126, "SCALAR", 3, ([0], [1]))
    morph = b.accessor("f", [0, 0, 1, 0.5, 0, 1], 5126, "SCALAR", 6)
    rotation = b.accessor("f", [0, 0, 0, 1, 0, 0, 0.0998, 0.995, 0, 0, 0, 1], 5126, "VEC4", 3)
    doc = {
        "asset": {"version": "2.0", "generator": "lacrima tests/fuzz/make_seed_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 2, 3]}],
        "nodes": [
            {"name": "Face", "mesh": 0, "skin": 0, "extras": {"landmarks68": []}},
            {"name": "Jaw", "translation": [0, -0.02, 0]},
            {"name": "Root", "children": [1]},
            {"name": "Camera", "camera": 0, "translation": [0, 0, 0.3]},
        ],
        "meshes": [{
            "name": "FaceMesh",
            "primitives": [{"attributes": {"POSITION": pos, "JOINTS_0": joints, "WEIGHTS_0": weights},
                            "indices": idx, "material": 0, "mode": 4,
                            "targets": [{"POSITION": jaw}, {"POSITION": smile}]}],
            "weights": [0, 0],
            "extras": {"targetNames": ["jawOpen", "smile"]},
        }],
        "materials": [{"name": "M_Face"}],
        "skins": [{"joints": [2, 1], "inverseBindMatrices": ibm}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.4, "znear": 0.01, "aspectRatio": 1.5}}],
        "animations": [{
            "name": "cry",
            "samplers": [{"input": times, "output": morph, "interpolation": "LINEAR"},
                         {"input": times, "output": rotation, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}},
                         {"sampler": 1, "target": {"node": 1, "path": "rotation"}}],
        }],
        "buffers": [{"byteLength": len(b.data)}],
        "bufferViews": b.views,
        "accessors": b.accessors,
    }
    while len(b.data) % 4:
        b.data.append(0)
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(b.data)
    out = struct.pack("<III", 0x46546C67, 2, total)
    out += struct.pack("<II", len(text), 0x4E4F534A) + text
    out += struct.pack("<II", len(b.data), 0x004E4942) + bytes(b.data)
    return out


def embedded_gltf(glb):
    """The same asset as a .gltf with its buffer as a base64 data URI (the other loading path)."""
    import base64
    json_length = struct.unpack_from("<I", glb, 12)[0]
    doc = json.loads(glb[20:20 + json_length])
    binary = glb[20 + json_length + 8:]
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(binary).decode()
    return json.dumps(doc, indent=1) + "\n"


def main():
    here.mkdir(parents=True, exist_ok=True)
    glb = tiny_glb()
    (here / "tiny.glb").write_bytes(glb)
    corpus = here.parent / "corpus"
    (corpus / "gltf").mkdir(parents=True, exist_ok=True)
    (corpus / "gltf" / "tiny.glb").write_bytes(glb)
    (corpus / "gltf" / "tiny_embedded.gltf").write_text(embedded_gltf(glb))
    (corpus / "track").mkdir(parents=True, exist_ok=True)
    (corpus / "track" / "frames.csv").write_text("frame,jawOpen,mouthSmile,browInnerUp_L\n0,0,0,0\n3,0.5,0.2,0.1\n6,1,0.4,0\n")
    (corpus / "track" / "times.json").write_text(json.dumps(
        {"time": [0, 0.05, 0.2], "weights": {"jawOpen": [0, 0.5, 1], "browInnerUp_L": [0.2, 0.2, 0]}}) + "\n")
    (here / "track.csv").write_text("time,jawOpen,smile\n0,0,0\n0.1,0.4,0.1\n0.2,0.8,0.3\n0.3,0.5,0.6\n")
    (here / "track.json").write_text(json.dumps(
        {"fps": 30, "weights": {"jawOpen": [0, 0.3, 0.7, 0.4], "smile": [0.1, 0.1, 0.5, 0.9]}}) + "\n")
    for name in ("track.csv", "track.json"):
        (corpus / "track" / name).write_text((here / name).read_text())


if __name__ == "__main__":
    main()
