#!/usr/bin/env python3
"""wrong_reader_candidate.py KIND: the exact step (examples/python/step.py) behind a number reader that reads some
spellings docs/protocol.md allows wrong, as readers written in other languages do. A default `circles conform`
must reject each through the wire family's requests (tests/conform_end_to_end.sh):

  refuse-underflow    a token whose nearest double is 0 but whose digits are not all 0 (1e-400) is refused, as
                      std::from_chars refuses it (result_out_of_range) when the reader does not map it to 0
  underflow-to-least  such a token is read as the least subnormal, 5e-324, instead of 0
  truncate-17         the digits are cut to 17 significant ones before rounding, as a reader that keeps 17
                      digits does: a long digit string just past a midpoint rounds to the wrong neighbour
  lower-e-only        an exponent written with an upper-case E is refused
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "python"))
from step import step  # noqa: E402

KIND = sys.argv[1]
NUMBER = re.compile(r"(-?)([0-9]+)(?:\.([0-9]+))?(?:[eE]([+-]?[0-9]+))?")


def underflows(token):
    """Whether the token has a nonzero digit but reads as 0."""
    mantissa = re.split("[eE]", token)[0]
    return float(token) == 0 and any(c in "123456789" for c in mantissa)


def truncated(token):
    """The token with its significant digits cut to 17 (towards zero)."""
    sign, whole, fraction, exponent = NUMBER.fullmatch(token).groups()
    fraction = fraction or ""
    digits = (whole + fraction).lstrip("0")  # the value is digits · 10^(exponent − len(fraction))
    if len(digits) <= 17:
        return token
    return f"{sign}{digits[:17]}e{int(exponent or 0) - len(fraction) + len(digits) - 17}"


def read_number(token):
    if KIND == "refuse-underflow" and underflows(token):
        raise ValueError(f"{token}: result out of range")
    if KIND == "underflow-to-least" and underflows(token):
        return -5e-324 if token.startswith("-") else 5e-324
    if KIND == "truncate-17":
        return float(truncated(token))
    if KIND == "lower-e-only" and "E" in token:
        raise ValueError(f"{token}: not a number")
    return float(token)


if KIND not in ("refuse-underflow", "underflow-to-least", "truncate-17", "lower-e-only"):
    sys.exit(f"wrong_reader_candidate.py: unknown kind {KIND!r}")
for line in sys.stdin:
    request = json.loads(line, parse_float=read_number)
    print(json.dumps({"id": request["id"], "circles": step(request["circles"])}), flush=True)
