"""`circles run` and `circles check-trace` ended by SIGINT, SIGTERM or SIGHUP (cli/interrupt.hpp): exit 128 + the
signal's number, "circles run: interrupted by SIGINT" on stderr, and nothing left behind: no temporary file of the
trace, the exact trace, the video or a frame, no half-written frame, no ffmpeg still running. A signal ignored when
the program starts (nohup) stays ignored. `circles conform` (conform/interrupt.hpp): the candidate's whole process
group killed, the cases checked and the seed said with the command that checks them again, the reports written
and marked interrupted, the progress line erased on a terminal, exit 128 + the signal.

    interrupt_test.py PATH/TO/circles CASE
"""
import json
import os
import pty
import select
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
    step = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "python", "step.py")
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
    elif case == "conform_stops_its_candidates_and_reports_the_cases_checked":
        for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            name = signal.Signals(number).name
            out = os.path.join(scratch, name)
            os.mkdir(out)
            pids = os.path.join(out, "pids")
            # The candidate starts a process of its own in its group, and writes both ids.
            candidate = "sleep 600 & echo $$ $! > %s; exec python3 %s" % (pids, step)
            report, junit = os.path.join(out, "r.json"), os.path.join(out, "r.xml")
            run = subprocess.Popen([circles, "conform", "--exec", candidate, "--report", report, "--junit", junit],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            wait_for("the candidate started", lambda: os.path.exists(pids) and os.path.getsize(pids) > 0)
            time.sleep(1.0)  # some cases checked
            with open(pids) as f:
                started = f.read().split()
            run.send_signal(number)
            try:
                said, err = run.communicate(timeout=60)
            except subprocess.TimeoutExpired:
                run.kill()
                fail("conform did not end on " + name)
            if run.returncode != 128 + number:
                fail("conform on %s exited %s, expected %d: %s" % (name, run.returncode, 128 + number, err))
            lines = err.splitlines()
            if len(lines) != 2 or not lines[0].startswith("circles conform: interrupted by %s after " % name):
                fail("conform on %s said: %r" % (name, err))
            cases, seed = lines[0].split(" after ")[1].split(" cases (seed ")
            if not cases.isdigit() or int(cases) == 0 or not seed.endswith(")"):
                fail("no count of cases or seed in %r" % lines[0])
            seed = seed[:-1]
            again = "to check the same cases again: circles conform --exec '%s' --seed %s --level exact" % (candidate, seed)
            if lines[1] != again:
                fail("conform on %s said %r, expected %r" % (name, lines[1], again))
            if said:
                fail("conform on %s wrote to stdout: %r" % (name, said))
            for pid in started:
                wait_for("process %s of the candidate ended" % pid, lambda: not os.path.exists("/proc/" + pid) or
                         open("/proc/%s/stat" % pid).read().rsplit(")", 1)[1].split()[0] == "Z", seconds=10)
            with open(report) as f:
                r = json.load(f)
            # The message counts the cases checked; the report, the cases drawn and those skipped among them (a
            # world whose next leaves the double range has no expected answer).
            if r["verdict"] != "interrupted" or r["cases"] - r["skipped"] != int(cases) or str(r["seed"]) != seed:
                fail("the report says %s, %s cases of which %s skipped, seed %s; the message said %s checked" %
                     (r["verdict"], r["cases"], r["skipped"], r["seed"], cases))
            with open(junit) as f:
                if '<error type="interrupted" message="interrupted by %s">' % name not in f.read():
                    fail("the JUnit report has no error of the interruption")
            if partial_files(out):
                fail("files left behind: %s" % partial_files(out))
    elif case == "conform_erases_its_progress_line_on_a_terminal":
        # stderr on a terminal, where conform draws its progress line (after 2 s); the candidate is the exact
        # step in Python, slow enough that the line is up when the signal comes.
        controller, terminal = pty.openpty()
        run = subprocess.Popen([circles, "conform", "--exec", "python3 " + step, "--cases", "100000"],
                               stdout=subprocess.DEVNULL, stderr=terminal, stdin=subprocess.DEVNULL)
        os.close(terminal)
        seen = b""
        end = time.monotonic() + 60
        while b"case" not in seen and time.monotonic() < end:
            ready, _, _ = select.select([controller], [], [], 0.1)
            if ready:
                seen += os.read(controller, 4096)
        if b"case" not in seen:
            fail("no progress line on the terminal: %r" % seen)
        run.send_signal(signal.SIGINT)
        while True:
            try:
                chunk = os.read(controller, 4096)
            except OSError:  # EIO: the terminal's last writer has gone
                break
            if not chunk:
                break
            seen += chunk
        run.wait(timeout=60)
        if run.returncode != 128 + signal.SIGINT:
            fail("conform exited %s: %r" % (run.returncode, seen[-300:]))
        if b"\r\x1b[Kcircles conform: interrupted by SIGINT after " not in seen:
            fail("the progress line was not erased before the verdict: %r" % seen[-300:])
    else:
        fail("no case " + case)
finally:
    shutil.rmtree(scratch, ignore_errors=True)
