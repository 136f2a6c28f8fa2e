"""What scripts/benchmarks and scripts/accuracy share: running a build or benchmark step, describing the machine a
run took place on, rewriting the generated section of a Markdown document, and writing a file so that a failed
run leaves it as it was.

The scripts import it from their own directory, whatever the working directory (scripts/benchmarks and
scripts/accuracy put it on sys.path first). Standard library only.
"""
import os
import pathlib
import shlex
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent  # the repository


class Failure(Exception):
    """A step of the run failed; the message says which."""


def run(cmd, **kw):
    """Runs `cmd` (its words may be paths or numbers), echoing it first as `+ cmd`; raises Failure naming it and
    its exit status if it fails. `kw` goes to subprocess.run."""
    print("+ " + shlex.join(str(c) for c in cmd), flush=True)
    result = subprocess.run([str(c) for c in cmd], **kw)
    if result.returncode != 0:
        raise Failure(f"{shlex.join(str(c) for c in cmd)} exited with status {result.returncode}")
    return result


def output_lines(cmd):
    """The lines `cmd` prints, or [] where it cannot run or fails: for describing the machine, where a missing
    tool leaves a figure unknown rather than failing the run."""
    try:
        return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip().splitlines()
    except (OSError, subprocess.CalledProcessError):
        return []


def first_line(cmd, default="?"):
    """The first line `cmd` prints (a compiler's --version, a package's version), or `default`."""
    lines = output_lines(cmd)
    return lines[0] if lines else default


def cpu_model(default="?"):
    """The CPU's model as lscpu names it (its first "Model name:" line), or `default`."""
    for line in output_lines(["lscpu"]):
        if line.startswith("Model name:"):
            return line.split(":", 1)[1].strip()
    return default


def marked_section(begin, body, end):
    """The text of a generated section: the line `begin`, `body` without its surrounding blank lines, and the
    line `end`, a blank line between each."""
    return f"{begin}\n\n{body.strip()}\n\n{end}\n"


def replace_section(document, section, before=None):
    """`document` with its generated section replaced by `section`, whose first line is the section's begin marker
    and whose last line its end marker (as marked_section makes it). The section is what lies between the two
    markers, both included; the rest of the document is kept as it is. A document without the markers gets the
    section inserted before the first occurrence of the text `before` (a heading), or appended at the end when
    `before` is None or not in the document, one blank line apart."""
    section = section.rstrip("\n")
    begin, end = section.split("\n", 1)[0], section.rsplit("\n", 1)[-1]
    if begin in document and end in document:
        head, rest = document.split(begin, 1)
        _, tail = rest.split(end, 1)
        return head + section + tail
    if before is not None and before in document:
        head, tail = document.split(before, 1)
        return head + section + "\n\n" + before + tail
    return document.rstrip("\n") + "\n\n" + section + "\n"


def write_atomically(path, data):
    """Writes `data` (str or bytes) to `path` through a temporary file beside it, renamed over `path`: a reader
    sees the old file or the new one, and a failed write leaves the old one and no temporary file. The file keeps
    its permissions; a new one gets rw-r--r--."""
    path = pathlib.Path(path)
    mode = path.stat().st_mode & 0o777 if path.exists() else 0o644
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb" if isinstance(data, bytes) else "w") as f:
            f.write(data)
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
