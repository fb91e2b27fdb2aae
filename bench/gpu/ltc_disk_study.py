#!/usr/bin/env python3
"""disk_ltc_cv beyond its validated domain, as the standard model uses it: lights of up to ~2 sr
drawn as the validation probe draws them (docs/models.md "Validation probe"), with the LTC
table's own entries (shaderlib/ltc/ggx.json, read as ltc::sampleBilinear reads it), half of the
views at n.v < 0.05. docs/devices.md ("run here again") quotes what it gave.

  python3 bench/gpu/ltc_disk_study.py gen SEED RMIN RMAX COUNT > disks.csv
  matbricks eval --brick disk_ltc_cv --input disks.csv --json > disks.json
  python3 bench/gpu/ltc_disk_study.py stats disks.json

The quoted runs: `gen 2 0.05 0.1 20000` and `gen 3 0.1 0.2 20000`.
"""
import json
import math
import os
import random
import sys

COLUMNS = ['n.x', 'n.y', 'n.z', 'v.x', 'v.y', 'v.z', 'l.x', 'l.y', 'l.z', 'alpha', 'norm', 'm00', 'm02', 'm20',
           'm22', 'toCenter.x', 'toCenter.y', 'toCenter.z', 'halfX.x', 'halfX.y', 'halfX.z', 'halfY.x', 'halfY.y',
           'halfY.z']
TOLERANCE_ABS, TOLERANCE_REL = 2e-5, 2e-4  # disk_ltc_cv's (shaderlib/disk_light_ltc_cv/slot.json)


def table():
    root = os.path.join(os.path.dirname(__file__), '..', '..', 'shaderlib', 'ltc', 'ggx.json')
    t = json.load(open(root))
    return t['size'], t['entries']


def sample(size, entries, r, nov):  # ltc::sampleBilinear
    last = size - 1.0
    x = min(max(r, 0.0), 1.0) * last
    y = math.sqrt(min(max(1.0 - nov, 0.0), 1.0)) * last
    i0, j0 = min(int(x), size - 2), min(int(y), size - 2)
    fx, fy = x - i0, y - j0
    v = [0.0] * 6
    for i, j, w in ((i0, j0, (1 - fx) * (1 - fy)), (i0, j0 + 1, (1 - fx) * fy), (i0 + 1, j0, fx * (1 - fy)),
                    (i0 + 1, j0 + 1, fx * fy)):
        for k in range(6):
            v[k] += w * entries[i * size + j][k]
    return v


def normalize(a):
    s = math.sqrt(sum(x * x for x in a))
    return [x / s for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def basis(n):  # Duff et al. 2017, as the probe's orthonormalBasis
    s = 1.0 if n[2] >= 0 else -1.0
    a = -1.0 / (s + n[2])
    c = n[0] * n[1] * a
    return [1 + s * n[0] * n[0] * a, s * c, -s * n[0]], [c, s + n[1] * n[1] * a, -n[1]]


def gen(seed, rmin, rmax, count):
    size, entries = table()
    random.seed(seed)
    print(','.join(COLUMNS))
    for _ in range(count):
        nov = random.uniform(0.001, 0.05) if random.random() < 0.5 else random.uniform(0.05, 1)
        n, v = [0, 0, 1], [math.sqrt(1 - nov * nov), 0, nov]
        r = random.uniform(rmin, rmax)
        t = sample(size, entries, r, nov)
        lu = normalize([random.gauss(0, 1), random.gauss(0, 1),
                        abs(random.gauss(0, 1)) * random.choice([1, 1, 1, -0.2])])
        lt, lb = basis(lu)
        d = random.uniform(0.25, 20)
        a, tilt = random.uniform(0, math.pi), random.uniform(0, math.pi)
        hw, hh = random.uniform(-0.4, 1.5), random.uniform(0, 0.9)  # the probe's ranges
        e1 = [lt[k] * math.cos(a) + lb[k] * math.sin(a) for k in range(3)]
        e2 = cross(lu, e1)
        centre = [lu[k] * d for k in range(3)]
        hx = [e1[k] * hw * d for k in range(3)]
        hy = [(e2[k] * math.sin(tilt) + lu[k] * math.cos(tilt)) * (-hh * d) for k in range(3)]
        row = n + v + lu + [r * r, t[4], t[0], t[1], t[2], t[3]] + centre + hx + hy
        print(','.join('%.9g' % x for x in row))


def stats(path):
    rows = json.load(open(path))['rows']
    outside = [abs(r['gpu']['out'] - r['reference']['out']) / max(abs(r['reference']['out']), 1e-30) for r in rows
               if abs(r['gpu']['out'] - r['reference']['out']) > TOLERANCE_ABS + TOLERANCE_REL *
               abs(r['reference']['out'])]
    print('%s: %d disks, %d outside the brick\'s tolerance%s' %
          (path, len(rows), len(outside), ', up to %.2g relative' % max(outside) if outside else ''))


if __name__ == '__main__':
    if len(sys.argv) == 6 and sys.argv[1] == 'gen':
        gen(int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]))
    elif len(sys.argv) >= 3 and sys.argv[1] == 'stats':
        for p in sys.argv[2:]:
            stats(p)
    else:
        sys.exit(__doc__)
