"""`circles run` and `circles check-trace` ended by SIGINT, SIGTERM or SIGHUP (cli/interrupt.hpp): exit 128 + the
signal's number, "circles run: interrupted by SIGINT" on stderr, and nothing left behind: no temporary file of the
trace, the exact trace, the video or a frame, no half-written frame, no ffmpeg still running. A signal ignored when
the program starts (nohup) stays ignored.

    interrupt_test.py PATH/TO/circles CASE
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

circles, case = sys.argv[1], sys.argv[2]


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def wait_for(what, predicate, seconds=60):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return
        time.sleep(0.02)
    fail("never happened: " + what)


def partial_files(directory):
    found = []
    for root, _, files in os.walk(directory):
        found += [os.path.join(root, f) for f in files if ".partial-" in f or f.startswith(".circles-probe")]
    return found


def ended(run, signal_number, command):
    try:
        _, err = run.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        run.kill()
        fail(command + " did not end on signal " + str(signal_number))
    name = signal.Signals(signal_number).name
    if run.returncode != 128 + signal_number:
        fail("%s on %s exited %s, expected %d: %s" % (command, name, run.returncode, 128 + signal_number, err))
    if not err.endswith(command + ": interrupted by " + name + "\n"):
        fail("%s on %s said: %r" % (command, name, err[-300:]))


def processes_naming(text):
    """The processes whose command line holds `text`."""
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                if text.encode() in f.read():
                    found.append(pid)
        except OSError:
            pass
    return found


def complete_png(path):
    with open(path, "rb") as f:
        data = f.read()
    return data.startswith(b"\x89PNG\r\n\x1a\n") and data.endswith(b"IEND\xaeB`\x82")


scratch = tempfile.mkdtemp()
try:
    if case == "run_leaves_no_temporary_file_and_exits_128_plus_the_signal":
        for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            out = os.path.join(scratch, signal.Signals(number).name)
            os.mkdir(out)
            trace = os.path.join(out, "t.jsonl")
            run = subprocess.Popen([circles, "run", "--random", "20000", "--steps", "100000000", "--threads", "1",
                                    "--engine", "exact", "--trace", trace, "--exact-trace", trace + ".exact"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            # Both traces under way: their temporary files exist and hold a world or more.
            wait_for("the traces being written", lambda: len(partial_files(out)) == 2 and
                     all(os.path.getsize(f) > 0 for f in partial_files(out)))
            run.send_signal(number)
            ended(run, number, "circles run")
            if os.listdir(out):
                fail("files left behind after %s: %s" % (signal.Signals(number).name, os.listdir(out)))
    elif case == "run_stops_ffmpeg_and_keeps_only_complete_frames":
        if not shutil.which("ffmpeg"):
            fail("ffmpeg is not installed (scripts/setup installs it)")
        video = os.path.join(scratch, "v.mp4")
        frames = os.path.join(scratch, "frames")
        run = subprocess.Popen([circles, "run", "--steps", "100000000", "--render", frames, "--video", video],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        wait_for("frames drawn", lambda: os.path.isdir(frames) and len(os.listdir(frames)) >= 3)
        run.send_signal(signal.SIGTERM)
        ended(run, signal.SIGTERM, "circles run")
        if partial_files(scratch) or os.path.exists(video):
            fail("files left behind: %s" % partial_files(scratch))
        if not all(complete_png(os.path.join(frames, f)) for f in os.listdir(frames)):
            fail("a frame left half-written")
        if processes_naming(video):
            fail("ffmpeg still runs: %s" % processes_naming(video))
    elif case == "check_trace_exits_128_plus_the_signal":
        for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            # A trace on stdin that never ends: a pipe held open after its first world.
            run = subprocess.Popen([circles, "check-trace", "-"], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True)
            run.stdin.write('{"step": 0, "circles": [[0, 0, 1, 0, 1]]}\n')
            run.stdin.flush()
            time.sleep(0.3)
            run.send_signal(number)
            ended(run, number, "circles check-trace")
            run.stdin.close()
    elif case == "a_signal_ignored_at_start_stays_ignored":
        out = os.path.join(scratch, "t.jsonl")

        def ignore_hangup():
            signal.signal(signal.SIGHUP, signal.SIG_IGN)

        run = subprocess.Popen([circles, "run", "--random", "20000", "--steps", "100000000", "--threads", "1",
                                "--trace", out], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                               preexec_fn=ignore_hangup)
        wait_for("the trace being written", lambda: len(partial_files(scratch)) == 1)
        run.send_signal(signal.SIGHUP)
        time.sleep(0.5)
        if run.poll() is not None:
            fail("nohup's SIGHUP ended the run (exit %s)" % run.returncode)
        run.send_signal(signal.SIGTERM)
        ended(run, signal.SIGTERM, "circles run")
        if os.listdir(scratch):
            fail("files left behind: %s" % os.listdir(scratch))
    else:
        fail("no case " + case)
finally:
    shutil.rmtree(scratch, ignore_errors=True)
