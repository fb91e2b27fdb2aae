#!/usr/bin/env python3
"""Writes the two .glb files of the glTF conformance corpus (issue 18), JSON chunk padded with
spaces and BIN chunk with zeros (glTF 2.0 spec, "GLB File Format Specification"):

  textured_no_lights.glb  base colour, metallic-roughness and normal textures embedded as
                          bufferViews of the BIN chunk, no KHR_lights_punctual light: the
                          scene is planned with ibl_lut, and every texture reaches the output
  short_bin.glb           buffer 0 declares 64 bytes, the BIN chunk holds 16: W-GLB-BIN-SHORT

The image bytes are placeholders (matbricks never reads images). usage: make_glb.py DIR
"""
import json
import os
import struct
import sys

MESH = {
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
}


def pack(doc: dict, bin_bytes: bytes) -> bytes:
    js = json.dumps(doc, indent=1).encode()
    js += b" " * (-len(js) % 4)
    bin_bytes += b"\0" * (-len(bin_bytes) % 4)
    total = 12 + 8 + len(js) + (8 + len(bin_bytes) if bin_bytes else 0)
    out = struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(js), 0x4E4F534A) + js
    if bin_bytes:
        out += struct.pack("<II", len(bin_bytes), 0x004E4942) + bin_bytes
    return out


def textured() -> bytes:
    doc = {"asset": {"version": "2.0", "generator": "make_glb.py: textures in the BIN chunk, no lights"}, **MESH}
    doc["buffers"] = [{"byteLength": 48}]
    doc["bufferViews"] = [{"buffer": 0, "byteOffset": 16 * i, "byteLength": 16} for i in range(3)]
    doc["images"] = [{"bufferView": i, "mimeType": "image/png"} for i in range(3)]
    doc["textures"] = [{"source": i} for i in range(3)]
    doc["materials"] = [{
        "name": "Painted Wood",
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.85, 0.8, 1], "metallicFactor": 1, "roughnessFactor": 1,
                                 "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}},
        "normalTexture": {"index": 2, "scale": 0.8}}]
    return pack(doc, bytes(48))


def short_bin() -> bytes:
    doc = {"asset": {"version": "2.0", "generator": "make_glb.py: BIN chunk shorter than its buffer"}, **MESH}
    doc["buffers"] = [{"byteLength": 64}]
    doc["bufferViews"] = [{"buffer": 0, "byteLength": 64}]
    doc["materials"] = [{"name": "Truncated Steel",
                         "pbrMetallicRoughness": {"baseColorFactor": [0.56, 0.57, 0.58, 1], "roughnessFactor": 0.3}}]
    return pack(doc, bytes(16))


def write(path: str, data: bytes) -> None:
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)  # no partial output on failure


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    write(os.path.join(sys.argv[1], "textured_no_lights.glb"), textured())
    write(os.path.join(sys.argv[1], "short_bin.glb"), short_bin())


if __name__ == "__main__":
    main()
