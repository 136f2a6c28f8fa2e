#!/usr/bin/env python3
"""A candidate with the classic mistakes, for `circles conform` to reject: floating-point distance (hypot) and
p + v * (1/60), both rounded twice. Otherwise the same as step.py."""
import json
import math
import sys


def step(world):
    out = []
    for k, c in enumerate(world):
        contacts = [j for j, d in enumerate(world)
                    if j != k and math.hypot(d[0] - c[0], d[1] - c[1]) <= c[4] + d[4]]
        vx, vy = c[2], c[3]
        if contacts:
            least = min(contacts, key=lambda j: (*world[j], j))
            vx, vy = world[least][2], world[least][3]
        out.append([c[0] + vx * (1 / 60), c[1] + vy * (1 / 60), vx, vy, c[4]])
    return out


for line in sys.stdin:
    request = json.loads(line)
    print(json.dumps({"id": request["id"], "circles": step(request["circles"])}), flush=True)
