"""What scripts/benchmarks and scripts/accuracy share: running a build or benchmark step, describing the machine a
run took place on, filling a Markdown template of scripts/templates/, rewriting the generated section of a
Markdown document, and writing a file so that a failed run leaves it as it was.

The scripts import it from their own directory, whatever the working directory (scripts/benchmarks and
scripts/accuracy put it on sys.path first). Standard library only.
"""
import os
import pathlib
import re
import shlex
import string
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent  # the repository
TEMPLATES = pathlib.Path(__file__).resolve().parent / "templates"


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


def cache_value(build, name):
    """The value of `name` in the CMake cache of the build directory `build`, or None."""
    try:
        text = (pathlib.Path(build) / "CMakeCache.txt").read_text()
    except OSError:
        return None
    m = re.search(rf"^{re.escape(name)}:[A-Z]+=(.*)$", text, re.M)
    return m.group(1) if m else None


def cpu_model(default="?"):
    """The CPU's model as lscpu names it (its first "Model name:" line), or `default`."""
    for line in output_lines(["lscpu"]):
        if line.startswith("Model name:"):
            return line.split(":", 1)[1].strip()
    return default


class MarkdownTemplate(string.Template):
    """The prose of a generated section, scripts/templates/NAME: Markdown with $placeholders (string.Template;
    $$ is a dollar sign), read when the script starts, so that a missing or malformed template stops it before a
    long run rather than after. NAME ends in .md.in, not .md: the tests that read every Markdown file of the
    repository would take a template's links, written for the document it fills, for broken ones.

    Its paragraphs and list items may be wrapped like the hand-written docs: each is written as one line, as the
    generated sections have them. A line continues the one above unless it is blank, starts with "#", "|" or
    "- ", or the line above is a heading or a table row (so table rows are never wrapped). A placeholder that
    stands alone as a paragraph and is given an empty value leaves no blank lines behind."""

    def __init__(self, name):
        self.name = name
        lines = []
        for line in (TEMPLATES / name).read_text(encoding="utf-8").splitlines():
            if line.strip() and not line.startswith(("#", "|", "- ")) and lines and lines[-1] \
                    and not lines[-1].startswith(("#", "|")):
                lines[-1] += " " + line.strip()
            else:
                lines.append(line)
        super().__init__("\n".join(lines) + "\n")
        if not self.is_valid():
            raise ValueError(f"scripts/templates/{name}: a $ that starts no placeholder (write $$ for a dollar sign)")

    def fill(self, **values):
        """The text with every placeholder replaced by its value; raises ValueError unless `values` names exactly
        the template's placeholders, so that the template and the script cannot drift apart unnoticed."""
        missing = [f"${name}" for name in self.get_identifiers() if name not in values]
        unused = [name for name in values if name not in self.get_identifiers()]
        if missing or unused:
            raise ValueError(f"scripts/templates/{self.name}: "
                             + "; ".join((["no value for " + ", ".join(missing)] if missing else [])
                                         + (["no placeholder for " + ", ".join(unused)] if unused else [])))
        return re.sub(r"\n{3,}", "\n\n", self.substitute(values))


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
