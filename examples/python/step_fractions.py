#!/usr/bin/env python3
"""The step as a person writes it to learn the spec: every number a Fraction, every pair tested with Fractions.

A correct candidate for `circles conform` (docs/protocol.md), the slowest kind: some 10 µs a pair here, so a default
run's time budget takes it to worlds of a few thousand circles (docs/benchmarks.md). With the argument
`strict`, it decides (3) with < instead of <=, a bug of worlds of two tangent circles.
"""
import json
import sys
from fractions import Fraction

strict = sys.argv[1:] == ["strict"]


def step(world):
    w = [[Fraction(float(x)) for x in c] for c in world]  # an int token means its nearest double
    out = []
    for i, a in enumerate(w):
        least = None
        for j, b in enumerate(w):
            if i == j:
                continue
            d2 = (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2
            s2 = (a[4] + b[4]) ** 2
            if (d2 < s2) if strict else (d2 <= s2):
                if least is None or (b, j) < (w[least], least):
                    least = j
        vx, vy = (w[least][2], w[least][3]) if least is not None else (a[2], a[3])
        out.append([float(a[0] + vx / 60), float(a[1] + vy / 60), float(vx), float(vy), float(a[4])])
    return out


for line in sys.stdin:
    request = json.loads(line)
    print(json.dumps({"id": request["id"], "circles": step(request["circles"])}), flush=True)
