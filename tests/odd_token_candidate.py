#!/usr/bin/env python3
"""odd_token_candidate.py FIELD TOKEN WHEN: the exact step (examples/python/step.py) with circle 0's FIELD (px, py,
vx, vy or r) of each answer written as TOKEN, for tests/conform_end_to_end.sh:

  TOKEN  NaN, Infinity, -Infinity (as Python's json writes floats that are not finite), or a number token beyond
         the double range such as 1e400; or "-0.0", which writes the field as -0.0 where the answer holds 0.0
         (a right answer: -0 and +0 are one value), and leaves the other answers alone.
  WHEN   "every" request, or "even" ids only: under --steps 2, conform numbers the two steps of each case 2c + 1
         and 2c + 2, so the even ids are the second steps, each asked from this program's own right first answer.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "python"))
from step import step  # noqa: E402

FIELD = ["px", "py", "vx", "vy", "r"].index(sys.argv[1])
TOKEN, WHEN = sys.argv[2], sys.argv[3]
PLACEHOLDER = 123456.78901234  # a value no step of conform's worlds answers, replaced by TOKEN in the text

for line in sys.stdin:
    request = json.loads(line)
    answer = step(request["circles"])
    if answer and (WHEN == "every" or request["id"] % 2 == 0):
        if TOKEN != "-0.0":
            answer[0][FIELD] = PLACEHOLDER
        elif answer[0][FIELD] == 0:
            answer[0][FIELD] = -0.0
    print(json.dumps({"id": request["id"], "circles": answer}).replace(repr(PLACEHOLDER), TOKEN), flush=True)
