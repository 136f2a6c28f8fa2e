#!/usr/bin/env python3
"""A correct candidate for `circles conform`: the resolved step in exact rationals.

Speaks the step protocol (docs/protocol.md): one request per line on stdin, {"id": N, "circles": [[px, py, vx,
vy, r], ...]}, one answer per line on stdout. json gives an integer token as an int, which the protocol reads as
its nearest double (9007199254740993 is 2^53): float(x) is that double, and Fraction of a float is its exact value;
float(Fraction) rounds to the nearest double, ties to even (CPython divides the integers exactly rounded), as the
protocol requires.
It tests every pair, O(n²): about 0.25 µs a pair here, so a world of 4097 circles takes some 4 s.
"""
import json
import sys
from fractions import Fraction


def touches(a, b):
    """(3): |p_b - p_a| <= r_a + r_b, squared, exactly, on (px, py, r) given as integers at one scale."""
    dx, dy, s = b[0] - a[0], b[1] - a[1], a[2] + b[2]
    return s * s >= dx * dx + dy * dy


def nearest(p, v):
    """(5): p + v/60, exactly, rounded once to the nearest double."""
    return float(p + v / 60)


def step(world, advance=nearest):
    """(1): every circle from the old world; the least contact is lexicographic on (px, py, vx, vy, r), then index.
    advance(p, v) gives each new position from the exact p and v."""
    w = [[Fraction(float(x)) for x in circle] for circle in world]
    # Every double is an integer over a power of two, so at the largest denominator D of the world's positions and
    # radii they are all integers: (3) on them is (3) on the exact values, scaled by D², and integers are some 30
    # times faster than Fractions, which matters in a world of thousands of circles.
    d = max((x.denominator for c in w for x in (c[0], c[1], c[4])), default=1)
    scaled = [(int(c[0] * d), int(c[1] * d), int(c[4] * d)) for c in w]
    out = []
    for k, c in enumerate(w):
        contacts = [j for j in range(len(w)) if j != k and touches(scaled[k], scaled[j])]
        vx, vy = c[2], c[3]
        if contacts:
            least = min(contacts, key=lambda j: (*w[j], j))
            vx, vy = w[least][2], w[least][3]
        out.append([advance(c[0], vx), advance(c[1], vy), float(vx), float(vy), float(c[4])])
    return out


def serve(step_function):
    """The step protocol: one answer line per request line, flushed."""
    for line in sys.stdin:
        request = json.loads(line)
        print(json.dumps({"id": request["id"], "circles": step_function(request["circles"])}), flush=True)


if __name__ == "__main__":
    serve(step)
