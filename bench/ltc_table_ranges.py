#!/usr/bin/env python3
"""The ranges of an LTC table's M^-1 entries where its lobe is not negligible: roughness >= 0.04,
n.v >= 0.001 and norm >= 1e-3 (the table's axes: docs/models/lights.md "LTC tables"). The
sheen bricks' domains (shaderlib/*_light_ltc_sheen/slot.json) quote this for charlie.json.

Usage: python3 bench/ltc_table_ranges.py shaderlib/ltc/charlie.json
"""
import json
import sys

table = json.load(open(sys.argv[1]))
n = table["size"]
kept = [
    table["entries"][i * n + j]
    for i in range(n)
    for j in range(n)
    if i / (n - 1) >= 0.04 and max(1 - (j / (n - 1)) ** 2, 1e-4) >= 0.001 and table["entries"][i * n + j][4] >= 1e-3
]
for k, name in enumerate(["m00", "m02", "m20", "m22"]):
    v = sorted(e[k] for e in kept)
    q = lambda p: v[int(p * (len(v) - 1) + 0.5)]
    print(f"{name}: min {v[0]:.3g}, 1 % {q(0.01):.3g}, 99 % {q(0.99):.3g}, max {v[-1]:.3g} ({len(v)} entries)")
