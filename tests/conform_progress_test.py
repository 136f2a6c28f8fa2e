"""`circles conform` with stderr a terminal shows a progress line there once the run has taken 2 s, and erases it
before the verdict; stdout never holds it, and with stderr a pipe there is none. The terminal is a pseudo-terminal
(pty).

    conform_progress_test.py PATH/TO/circles SOURCE_DIR
"""
import os
import pty
import re
import subprocess
import sys

circles, source = sys.argv[1], sys.argv[2]
# The naive Python example on three families: it fails tangency at its 9th case and passes the other two. It
# starts 2.5 s late, so the run takes longer than 2 s however fast the machine is, and the progress line is
# drawn at its first batch.
naive = "sleep 2.5; exec python3 " + os.path.join(source, "examples/python/step_naive.py")
command = [circles, "conform", "--seed", "1", "--cases", "26000", "--keep-going", "--families",
           "tangency,tangent-after-step,signed-zeros", "--exec", naive]


def on_a_terminal(stdout_too=True):
    """The exit status and what reached the terminal (stderr, and stdout too or else a pipe's bytes after it)."""
    leader, follower = pty.openpty()
    run = subprocess.Popen(command, stdout=follower if stdout_too else subprocess.PIPE, stderr=follower,
                           stdin=subprocess.DEVNULL)
    os.close(follower)
    out = b""
    while True:
        try:
            chunk = os.read(leader, 65536)
        except OSError:  # EIO: the program closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(leader)
    piped = b"" if stdout_too else run.stdout.read()
    return run.wait(), out.decode().replace("\r\n", "\n"), piped.decode()


status, out, _ = on_a_terminal()
verdict = "circles conform: the program `" + naive + "` does not conform: "
assert status == 1, (status, out)
lines = re.findall(r"\r(\[[#.]{20}\] +\d+%  case \d+ of \d+[^\r]*)", out)
assert lines, "no progress line: " + repr(out[:400])
# 26000 cases are 1000 rounds of 26: 1000 cases of each of the 3 families.
for line in lines:
    assert re.fullmatch(r"\[[#.]{20}\] +\d+%  case \d+ of 3000(  1 family failing)?( +\d+\.\d s left)? *", line), line
assert any("  1 family failing" in line for line in lines), lines
# The line is erased (spaces, then back to the start) before the verdict, which starts a line of its own.
assert re.search(r"\r +\r" + re.escape(verdict), out), repr(out[-600:])

piped = subprocess.run(command, capture_output=True, text=True)
assert piped.returncode == 1, piped
assert "\r" not in piped.stdout and not re.search(r"\[[#.]{20}\]", piped.stdout), repr(piped.stdout[:400])
assert piped.stdout.startswith(verdict), piped.stdout[:200]

# stdout a pipe, stderr the terminal: the line is drawn on stderr, and stdout holds the verdict alone.
status, terminal, piped = on_a_terminal(stdout_too=False)
assert status == 1, (status, terminal)
assert re.search(r"\r\[[#.]{20}\] +\d+%  case \d+ of 3000", terminal), "no progress on stderr: " + repr(terminal[:400])
assert "\r" not in piped and not re.search(r"\[[#.]{20}\]", piped) and piped.startswith(verdict), repr(piped[:400])
