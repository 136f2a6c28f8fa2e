"""A correct but slow program for `circles conform`: it answers each request through `circles serve` (the double
engine), after sleeping SECONDS_PER_CIRCLE for each circle of the request's world; after HANG_AFTER answers, if
given, it hangs instead; with from:N, it hangs on every world of N or more circles (a cliff).
Usage: slow_candidate.py CIRCLES SECONDS_PER_CIRCLE [HANG_AFTER | from:N]"""
import subprocess
import sys
import time

circles, per_circle = sys.argv[1], float(sys.argv[2])
hang = sys.argv[3] if len(sys.argv) > 3 else None
hang_after = int(hang) if hang is not None and not hang.startswith("from:") else None
hang_from = int(hang[len("from:"):]) if hang is not None and hang.startswith("from:") else None
serve = subprocess.Popen([circles, "serve", "--engine", "double", "--threads", "1"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, text=True)
answered = 0
for line in sys.stdin:
    if hang_after is not None and answered >= hang_after:
        time.sleep(3600)
    world = line[line.index('"circles"'):]
    if hang_from is not None and world.count("[") - 1 >= hang_from:
        time.sleep(3600)
    time.sleep(per_circle * world.count("["))  # one more "[" than circles: the list's own
    serve.stdin.write(line)
    serve.stdin.flush()
    sys.stdout.write(serve.stdout.readline())
    sys.stdout.flush()
    answered += 1
