#!/usr/bin/env python3
"""A candidate that stores positions in float32, for `circles conform` to reject: step.py's exact step, but each
position is rounded to the nearest float32 (ctypes.c_float, which gives inf beyond float32's range) before and
after the update, and Python's json writes the floats that are not finite as Infinity, -Infinity and NaN."""
import ctypes

from step import serve, step


def f32(x):
    return ctypes.c_float(x).value


def advance_in_float32(p, v):
    return f32(f32(float(p)) + float(v) / 60)


if __name__ == "__main__":
    serve(lambda world: step(world, advance_in_float32))
