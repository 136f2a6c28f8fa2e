"""`circles conform` holds at most what an answer to its world could need (conform/candidate.hpp,
ProcessCandidate::longest_answer): a candidate that answers an 8-circle world with a line of 300 MB is refused
as soon as the line passes the bound, and conform's memory stays far below the line's size.

    answer_length_test.py PATH/TO/circles
"""
import os
import resource
import subprocess
import sys
import tempfile

circles = sys.argv[1]
LINE = 300 * 1024 * 1024
# Peak resident memory allowed to conform and its candidate together: a third of the line, room for a
# sanitizer's own memory (about 42 MiB under AddressSanitizer, 14 MiB without). Reading the line whole would take
# more than the line itself (a string that grows by doubling).
LIMIT_KIB = LINE // 1024 // 3

with tempfile.TemporaryDirectory() as scratch:
    candidate = os.path.join(scratch, "long_answer.py")
    with open(candidate, "w") as f:
        f.write("import json, sys\n"
                "request = json.loads(sys.stdin.readline())\n"
                "sys.stdout.write('{\"id\": ' + str(request['id']) + ', \"circles\": [')\n"
                "chunk = ' ' * (1 << 20)\n"
                "try:\n"
                "    for _ in range(int(sys.argv[1])):\n"
                "        sys.stdout.write(chunk)\n"
                "except BrokenPipeError:\n"
                "    pass\n")
    run = subprocess.Popen([circles, "conform", "--exec", "python3 %s %d" % (candidate, LINE >> 20), "--seed", "1"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    said, err = run.communicate(timeout=300)
    # The rusage of conform and of the candidate it reaped: the larger peak of the two.
    peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    if run.returncode != 2 or "the line is longer than" not in err:
        print("FAIL: conform exited %d and said %r" % (run.returncode, (said + err)[-500:]), file=sys.stderr)
        sys.exit(1)
    if peak_kib > LIMIT_KIB:
        print("FAIL: conform's memory peaked at %d KiB, over %d KiB, on a line of %d MiB" %
              (peak_kib, LIMIT_KIB, LINE >> 20), file=sys.stderr)
        sys.exit(1)
    print("conform refused the line at a peak of %d KiB: %s" % (peak_kib, err.strip()))
