#!/usr/bin/env python3
"""Packs a .gltf (JSON only) into a .glb: 12-byte header, JSON chunk padded with spaces to
4 bytes (glTF 2.0 spec, "GLB File Format Specification"). No BIN chunk: the hand-written
scenes have no buffers. The test "the committed .glb is the packing of its .gltf" checks the
output against matbricks' own packGlb, byte for byte.

usage: make_glb.py showroom.gltf showroom.glb
"""
import os
import struct
import sys


def pack(json_bytes: bytes) -> bytes:
    json_bytes += b" " * (-len(json_bytes) % 4)
    total = 12 + 8 + len(json_bytes)
    header = struct.pack("<III", 0x46546C67, 2, total)  # "glTF", version 2, length
    chunk = struct.pack("<II", len(json_bytes), 0x4E4F534A)  # length, "JSON"
    return header + chunk + json_bytes


def main() -> None:
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], "rb") as f:
        data = pack(f.read())
    tmp = sys.argv[2] + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, sys.argv[2])  # no partial output on failure


if __name__ == "__main__":
    main()
