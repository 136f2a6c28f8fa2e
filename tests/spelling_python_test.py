#!/usr/bin/env python3
"""spelling_python_test.py: a candidate for `circles conform --families wire` (tests/CMakeLists.txt) that reads every
number token of its requests with Python's float() and checks it against the token's exact decimal value rounded
once to the nearest double (fractions.Fraction, whose float() divides exactly rounded), then answers with the exact
step (examples/python/step.py), which conform judges. At the end of its input it checks that the requests held
each form docs/protocol.md names: an upper-case E, an exponent with '+' and leading zeros, an integer token, more
than 17 significant digits, a token that underflows to 0, the least subnormal, both key orders and whitespace. A
token read wrong, or a form never sent, is a message on stderr and exit 1, which conform reports.
"""
import json
import os
import re
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "python"))
from step import step  # noqa: E402

REQUEST_NUMBER = re.compile(r"-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?")
FORMS = {
    "upper-case E": re.compile(r"E"),
    "exponent with + and leading zeros": re.compile(r"e\+0|E\+0"),
    "integer token": re.compile(r"^-?[0-9]+$"),
    "more than 17 significant digits": re.compile(r"[1-9][0-9]{17}"),
    "underflow to 0": re.compile(r"^-?[1-9].*e-(4|324)"),
    "least subnormal": re.compile(r"^-?(5e-324|5E-324|4\.9406564584124654e-324)$"),
}
seen = set()


def check(token):
    if not REQUEST_NUMBER.fullmatch(token):
        sys.exit(f"spelling_python_test.py: {token!r} is not a request number of docs/protocol.md")
    exact = float(Fraction(token))
    for read in (float(token), float(int(token)) if FORMS["integer token"].match(token) else float(token)):
        if read != exact:
            sys.exit(f"spelling_python_test.py: {token!r} reads as {read!r}, not {exact!r}")
    for name, form in FORMS.items():
        if form.search(token) and (name != "underflow to 0" or exact == 0):
            seen.add(name)
    return exact


for line in sys.stdin:
    if line.startswith('{"circles"'):
        seen.add("circles first")
    if " " in line or "\t" in line:
        seen.add("whitespace")
    # An integer token stays an int (the id must), checked as the rest; step() takes float() of it.
    request = json.loads(line, parse_float=check, parse_int=lambda t: (check(t), int(t))[1])
    print(json.dumps({"id": request["id"], "circles": step(request["circles"])}), flush=True)
missing = (set(FORMS) | {"circles first", "whitespace"}) - seen
if missing:
    sys.exit("spelling_python_test.py: no request held " + ", ".join(sorted(missing)))
