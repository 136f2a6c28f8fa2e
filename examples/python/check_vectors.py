#!/usr/bin/env python3
"""Checks the golden vectors of `circles vectors` (docs/vectors.md) with exact rationals: the usage is
check_vectors.py DIR/vectors.jsonl. For each case: the resolved step in fractions.Fraction, its exact next
world against "next_exact", rounded (float(Fraction) is the nearest double, ties to even) against "next" and
"next_hex", and the state hash (FNV-1a of the little-endian doubles, -0 as +0) against both hashes. Exit 0 when
every case agrees, 1 at the first that does not.
"""
import json
import struct
import sys
from fractions import Fraction


def state_hash(world):
    h = 0xCBF29CE484222325
    for circle in world:
        for byte in b"".join(struct.pack("<d", x + 0.0) for x in circle):  # x + 0.0: -0 becomes +0
            h = ((h ^ byte) * 0x100000001B3) % 2**64
    return format(h, "016x")


def step(world):
    """(1): circle k takes the velocity of the least circle it touches (3), lexicographic then by index."""
    w = [[Fraction(x) for x in c] for c in world]
    touches = lambda a, b: (a[4] + b[4]) ** 2 >= (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2
    out = []
    for k, c in enumerate(w):
        contacts = [j for j in range(len(w)) if j != k and touches(c, w[j])]
        v = c[2:4] if not contacts else w[min(contacts, key=lambda j: (*w[j], j))][2:4]
        out.append([c[0] + v[0] / 60, c[1] + v[1] / 60, v[0], v[1], c[4]])
    return out


def check(case):
    """The first mismatch of one case, or None."""
    hex_of = lambda rows: [[float.fromhex(x) for x in row] for row in rows]
    bits = lambda rows: [[struct.pack("<d", x) for x in row] for row in rows]  # keeps the sign of zero
    if bits(hex_of(case["input_hex"])) != bits(case["input"]):
        return "input_hex is not input"
    if state_hash(case["input"]) != case["input_hash"]:
        return "input_hash"
    exact = step(case["input"])
    if exact != [[Fraction(x) for x in row] for row in case["next_exact"]]:
        return "next_exact"
    rounded = [[float(x) for x in row] for row in exact]  # every zero is +0: a Fraction has no sign
    if bits(rounded) != bits(case["next"]) or bits(rounded) != bits(hex_of(case["next_hex"])):
        return "next or next_hex"
    return None if state_hash(rounded) == case["next_hash"] else "next_hash"


cases = 0
with open(sys.argv[1]) as vectors:
    for cases, line in enumerate(vectors, 1):
        case = json.loads(line)
        if wrong := check(case):
            sys.exit(f"{sys.argv[1]}:{cases}: case {case['case']} ({case['source']}): {wrong} differs")
print(f"{sys.argv[1]}: all {cases} cases agree: exact step, rounding and state hashes")
