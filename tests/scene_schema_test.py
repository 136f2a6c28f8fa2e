#!/usr/bin/env python3
"""The scene schema (docs/scene.schema.json) and the scene loader (formats/scene.cpp) accept the same documents.

    scene_schema_test.py PATH/TO/circles REPOSITORY bundled     every scenes/*.json: valid and loaded
    scene_schema_test.py PATH/TO/circles REPOSITORY agreement   the examples below: both say what each one says

A document is valid when it is strict JSON (no NaN or Infinity, no key twice in one object, which JSON Schema
cannot see) and the schema accepts it; the loader accepts it when `circles run FILE --steps 0` exits 0 (and it
must refuse with exit 2 otherwise). Each example also states which it is meant to be, so that the schema and the
loader cannot drift together either. Uses Debian's python3-jsonschema (scripts/setup).
"""
import json
import pathlib
import subprocess
import sys
import tempfile

import jsonschema

# (document, valid?, why). The numbers use the rule of docs/scenes.md: each means the double nearest to it.
EXAMPLES = [
    ('{"circles": []}', True, "the empty world"),
    ('{"circles": [[0, 0, 0, 0, 0]]}', True, "the protocol's compact form"),
    ('{"name": "two", "steps": 0, "circles": [[1, 2, 3, 4, 5], [-1.5, 2e3, 0.1, -0.0, 1]]}', True, "name, steps"),
    ('{"$schema": "../docs/scene.schema.json", "circles": []}', True, "$schema for editors"),
    ('{"circles": [{"p": [0, 0], "v": [60, 0], "r": 1}]}', True, "a circle object"),
    ('{"circles": [{"name": "a", "r": 1, "v": [0, 0], "p": [0, 0]}, [2, 0, 0, 0, 1]]}', True, "both forms, named"),
    ('{"name": "\\u00e9t\\u00e9 \u2603", "circles": [{"p": [0, 0], "v": [0, 0], "r": 1, "name": ""}]}', True,
     "any string"),
    ('{"steps": 9223372036854775807, "circles": []}', True, "the largest steps, 2^63 - 1"),
    ('{"steps": 1e3, "circles": []}', True, "steps an integer written as a float"),
    ('{"steps": 100.0, "circles": []}', True, "steps an integer written with a fraction"),
    ('{"steps": -0.0, "circles": []}', True, "steps -0, which is 0"),
    ('{"circles": [[9007199254740993, 4783255246441940000, 18446744073709551617, 1e-400, 1.7976931348623157e308]]}',
     True, "integers that are not doubles and a tiny number: each its nearest double"),
    ('{"circles": [[0, 0, 0, 0, -0.0]]}', True, "a radius -0, which is 0"),
    ('{"circles": [[0, 0, 0, 0, -1e-400]]}', True, "a radius whose nearest double is -0"),
    ('{"circles": [[-1.7976931348623157e308, 0, 0, 0, 5e-324]]}', True, "the extremes of the doubles"),
    ('[]', False, "not an object"),
    ('{}', False, "no circles"),
    ('{"name": "x"}', False, "no circles"),
    ('{"circles": {}}', False, "circles not an array"),
    ('{"circles": [5]}', False, "a circle that is a number"),
    ('{"circles": [[0, 0, 0, 0]]}', False, "4 numbers"),
    ('{"circles": [[0, 0, 0, 0, 1, 2]]}', False, "6 numbers"),
    ('{"circles": [[0, 0, 0, 0, -1]]}', False, "a negative radius"),
    ('{"circles": [[0, 0, 0, 0, -5e-324]]}', False, "the least negative radius"),
    ('{"circles": [[0, "0", 0, 0, 1]]}', False, "a string for a number"),
    ('{"circles": [[0, 0, 0, 0, null]]}', False, "null for a number"),
    ('{"circles": [[0, 0, true, 0, 1]]}', False, "true for a number"),
    ('{"circles": [[0, 0, 1e400, 0, 1]]}', False, "beyond the double range"),
    ('{"circles": [[0, 0, 0, -1e309, 1]]}', False, "beyond the double range, negative"),
    ('{"circles": [[0, [0], 0, 0, 1]]}', False, "an array for a number"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0], "raduis": 1}]}', False, "a misspelt key in a circle"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0], "r": 1, "id": 3}]}', False, "an unknown key in a circle"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0]}]}', False, "a circle object without r"),
    ('{"circles": [{"p": [0, 0], "r": 1}]}', False, "a circle object without v"),
    ('{"circles": [{"p": [0], "v": [0, 0], "r": 1}]}', False, "p of 1 number"),
    ('{"circles": [{"p": [0, 0, 0], "v": [0, 0], "r": 1}]}', False, "p of 3 numbers"),
    ('{"circles": [{"p": {"x": 0, "y": 0}, "v": [0, 0], "r": 1}]}', False, "p an object"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0], "r": -1}]}', False, "a negative radius in a circle object"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0], "r": [1]}]}', False, "r an array"),
    ('{"circles": [{"p": [0, 0], "v": [0, 1e999], "r": 1}]}', False, "v beyond the double range"),
    ('{"circles": [{"p": [0, 0], "v": [0, 0], "r": 1, "name": 5}]}', False, "a circle name not a string"),
    ('{"circles": [], "step": 10}', False, "a misspelt key at the top"),
    ('{"id": 1, "circles": []}', False, "a protocol request is not a scene"),
    ('{"name": 5, "circles": []}', False, "a name not a string"),
    ('{"$schema": 1, "circles": []}', False, "$schema not a string"),
    ('{"steps": -1, "circles": []}', False, "negative steps"),
    ('{"steps": 1.5, "circles": []}', False, "fractional steps"),
    ('{"steps": "10", "circles": []}', False, "steps a string"),
    ('{"steps": true, "circles": []}', False, "steps true"),
    ('{"steps": null, "circles": []}', False, "steps null"),
    ('{"steps": 9223372036854775808, "circles": []}', False, "steps 2^63"),
    ('{"steps": 1e19, "circles": []}', False, "steps beyond 2^63 - 1 as a float"),
    ('{"circles": [[0, 0, NaN, 0, 1]]}', False, "NaN, not JSON"),
    ('{"circles": [], "circles": [[0, 0, 0, 0, 1]]}', False, "a key twice, which strict JSON refuses"),
]


def strict_json(text):
    """The document, or ValueError for what JSON does not allow but Python's reader would take."""

    def no_constants(name):
        raise ValueError(f"{name} is not JSON")

    def no_duplicates(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)):
            raise ValueError("a key twice in one object")
        return dict(pairs)

    return json.loads(text, parse_constant=no_constants, object_pairs_hook=no_duplicates)


def schema_accepts(validator, text):
    try:
        document = strict_json(text)
    except ValueError:
        return False
    return validator.is_valid(document)


def loader_accepts(circles, path):
    """True when `circles run` loads the scene (exit 0), False when it refuses it (exit 2, with a message)."""
    done = subprocess.run([circles, "run", str(path), "--steps", "0"], capture_output=True, text=True, timeout=120)
    if done.returncode == 0:
        return True
    if done.returncode == 2 and done.stderr.startswith(f"circles: {path}: "):
        return False
    raise AssertionError(f"circles run {path} exited {done.returncode}: {done.stderr.strip()}")


def main():
    circles, root, mode = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
    schema = json.loads((root / "docs" / "scene.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []
    if mode == "bundled":
        scenes = sorted((root / "scenes").glob("*.json"))
        if not scenes:
            failures.append("no scenes/*.json")
        for path in scenes:
            errors = [e.message for e in validator.iter_errors(strict_json(path.read_text(encoding="utf-8")))]
            if errors:
                failures.append(f"{path.name}: the schema refuses it: {errors[0]}")
            if not loader_accepts(circles, path):
                failures.append(f"{path.name}: the loader refuses it")
        print(f"{len(scenes)} bundled scenes checked")
    elif mode == "agreement":
        with tempfile.TemporaryDirectory() as directory:
            for n, (text, valid, why) in enumerate(EXAMPLES):
                path = pathlib.Path(directory) / f"example{n}.json"
                path.write_text(text, encoding="utf-8")
                schema, loader = schema_accepts(validator, text), loader_accepts(circles, path)
                if schema != valid or loader != valid:
                    failures.append(f"{text} ({why}): meant {'valid' if valid else 'invalid'}, "
                                    f"the schema {'accepts' if schema else 'refuses'} it, "
                                    f"the loader {'accepts' if loader else 'refuses'} it")
        print(f"{len(EXAMPLES)} examples checked")
    else:
        failures.append(f"no mode {mode}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
