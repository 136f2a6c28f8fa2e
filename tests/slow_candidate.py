"""A correct but slow program for `circles conform`: it answers each request through `circles serve` (the double
engine), after sleeping SECONDS_PER_CIRCLE for each circle of the request's world; after HANG_AFTER answers, if
given, it hangs instead. Usage: slow_candidate.py CIRCLES SECONDS_PER_CIRCLE [HANG_AFTER]"""
import subprocess
import sys
import time

circles, per_circle = sys.argv[1], float(sys.argv[2])
hang_after = int(sys.argv[3]) if len(sys.argv) > 3 else None
serve = subprocess.Popen([circles, "serve", "--engine", "double", "--threads", "1"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, text=True)
answered = 0
for line in sys.stdin:
    if hang_after is not None and answered >= hang_after:
        time.sleep(3600)
    world = line[line.index('"circles"'):]
    time.sleep(per_circle * world.count("["))  # one more "[" than circles: the list's own
    serve.stdin.write(line)
    serve.stdin.flush()
    sys.stdout.write(serve.stdout.readline())
    sys.stdout.flush()
    answered += 1
