#!/usr/bin/python3
"""Checks the machine-checked error bounds: proofs/bounds.tsv against impl/, the Gappa proofs in proofs/gappa/ and
the SMT proofs (z3, floating-point theory) in proofs/smt/.

    proofs/check.py static           the registry, the constants and the hashes (no gappa; a second)
    proofs/check.py prove [--jobs N] [--gappa PATH] [--z3 PATH]
                                     every proof, then every proof with its constant lowered (docs/proofs.md)
    proofs/check.py hash FILE FUNC   the hash of a function's body, for a proof's header
    proofs/check.py case PROOF [N]   the prover's input for case N (from 1) of PROOF (PATH or PATH:VARIANT),
                                     to run one case alone: proofs/check.py case P | gappa

static fails when
  - a double constant named k* in impl/ has no row in the registry, or a row names no such constant;
  - a row is neither proofs (paths under proofs/gappa/ or proofs/smt/) nor `none: KIND, REASON` with a known
    KIND;
  - a proof is in no row, or a row's proof is missing, or lacks a header line (models, claim, regime, hash);
  - a lemma (a proof with a `# lemma:` line: a step other proofs rest on, no constant's) is in a row, or no
    proof names it in `# uses:`, or it has no `# refute: OLD => NEW` (a weakening of its claim that must not
    prove); or a proof `# uses:` what is no lemma;
  - a constant a proof defines (`kName = literal;`) differs in exact value from the C++ constant of that name;
  - a proof's `# hash: FILE FUNCTION HEX` is not the hash of FUNCTION's body in FILE now (the code changed
    under the proof: reread the proof against the code, then put the new hash);
  - a mutant of scripts/mutants lowers a proved bound and the registry and the mutant disagree on its slack;
  - docs/hardening.md's mutants table says of a bound other than the registry (its machine-checked column).
prove fails when a proof does not prove, when a lemma with its `# refute:` edit still proves, or when a proved
bound, set to the value its row gives after `fails` or to its mutant's value (unless the row records that value
as `slack`), still proves: a proof that holds whatever the constant is proves nothing about it. A `slack` value
must still prove.

Exit status: 0 all holds, 1 something failed (each failure on its own line on stderr), 2 bad usage.
"""
import argparse
import ast
import concurrent.futures
import hashlib
import importlib.machinery
import importlib.util
import itertools
import pathlib
import re
import subprocess
import sys
import time
from fractions import Fraction

ROOT = pathlib.Path(__file__).resolve().parent.parent
REGISTRY = ROOT / "proofs/bounds.tsv"
PROOF_DIRS = ("proofs/gappa/", "proofs/smt/")
KINDS = ("overflow", "discrete", "planning", "definition", "open")
HEADER = ("models", "claim", "regime", "hash")
PROVE_SECONDS = 300  # one case at the code's constants; the slowest takes about 10 s
REFUTE_SECONDS = 30  # one case at a lowered constant: gappa searches long before it gives up, and a proof
                     # that has not closed in three times its own time at the code's constants has not closed

CPP_CONSTANT = re.compile(r"constexpr\s+double\s+(k\w+)\s*=\s*([^;]+);")
GAPPA_CONSTANT = re.compile(r"^(k\w+)\s*=\s*([^;]+);", re.M)
SMT_CONSTANT = re.compile(r"^\(define-fun (k\w+) \(\) Real (.+)\)$", re.M)


class Failures(list):
    def add(self, text):
        self.append(text)


# ── exact values ─────────────────────────────────────────────────────────────────────────────────────────

def literal_value(token, exact):
    """A number token of C++ (exact=False: as the compiler rounds it to a double) or of Gappa (exact=True)."""
    if re.fullmatch(r"0[xX][0-9a-fA-F.]+[pP][-+]?\d+", token):
        return Fraction(float.fromhex(token)) if exact else float.fromhex(token)
    if m := re.fullmatch(r"(\d+)b([-+]?\d+)", token):
        return Fraction(int(m[1])) * Fraction(2) ** int(m[2])
    return Fraction(token) if exact else float(token)


def evaluate(text, exact):
    """The value of a constant's initializer: numbers, + - * / and parentheses, and DBL_MAX as C++ spells it.
    C++ (exact=False) evaluates in doubles, each operation rounded as a constant expression is; Gappa
    (exact=True) in rationals. None when the text is anything else."""
    text = text.replace("std::numeric_limits<double>::max()", repr(sys.float_info.max))
    names = {}

    def number(m):
        names[f"n{len(names)}"] = literal_value(m[0], exact)
        return f"n{len(names) - 1}"

    pattern = r"0[xX][0-9a-fA-F.]+[pP][-+]?\d+|\d+b[-+]?\d+|\d+\.\d*(?:[eE][-+]?\d+)?|\d+(?:[eE][-+]?\d+)?"
    expression = re.sub(pattern, number, text)
    try:
        tree = ast.parse(expression.strip(), mode="eval")
    except SyntaxError:
        return None
    allowed = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Name, ast.Load, ast.Add, ast.Sub, ast.Mult, ast.Div,
               ast.USub, ast.UAdd)
    if not all(isinstance(node, allowed) for node in ast.walk(tree)):
        return None
    return eval(compile(tree, "<constant>", "eval"), {"__builtins__": {}}, names)


def cpp_constants():
    """Every `constexpr double k… = …;` of impl/: name → (file, initializer text)."""
    found = {}
    for path in sorted((ROOT / "impl").rglob("*.[ch]pp")):
        for m in CPP_CONSTANT.finditer(path.read_text(encoding="utf-8")):
            found.setdefault(m[1], (path.relative_to(ROOT).as_posix(), " ".join(m[2].split())))
    return found


# ── function bodies ──────────────────────────────────────────────────────────────────────────────────────

def function_body(path, name):
    """The text from the opening brace of function `name`'s definition in path to its closing brace."""
    text = (ROOT / path).read_text(encoding="utf-8")
    for m in re.finditer(r"\b" + re.escape(name) + r"\s*\(", text):
        depth, i = 0, m.end() - 1
        while i < len(text):  # the parameter list
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
            if depth == 0:
                break
        rest = re.match(r"[\s\w:&*<>,]*\{", text[i:])  # noexcept, const, trailing return types
        if not rest or ";" in rest[0]:
            continue
        start = i + rest.end() - 1
        depth = 0
        for j in range(start, len(text)):
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            if depth == 0:
                return text[start:j + 1]
    return None


def body_hash(path, name):
    body = function_body(path, name)
    return None if body is None else hashlib.sha256(body.encode()).hexdigest()[:16]


# ── proofs ───────────────────────────────────────────────────────────────────────────────────────────────

def variant_text(text, variant):
    """A file's text as one of its variants (`# variants: a b`): a line `#[a] X` is X in variant a and absent in
    the others; every other line is shared."""
    lines = []
    for line in text.splitlines(keepends=True):
        if m := re.match(r"[#;]\[(\w+)\] ?", line):
            if m[1] == variant:
                lines.append(line[m.end():])
        else:
            lines.append(line)
    return "".join(lines)


def file_variants(path):
    """The variants a proof file declares (`# variants: a b`), or [None] for a file that is one proof."""
    m = re.search(r"^[#;]\s*variants:(.*)$", path.read_text(encoding="utf-8"), re.M)
    return m[1].split() if m else [None]


class Proof:
    def __init__(self, path, variant=None):
        self.path = path
        self.variant = variant
        self.text = path.read_text(encoding="utf-8")
        if variant is not None:
            self.text = variant_text(self.text, variant)
        self.header = {}
        for line in self.text.splitlines():
            if m := re.match(r"[#;]\s*(\w+):\s*(.*)", line):
                self.header.setdefault(m[1], []).append(m[2].strip())
        self.smt = path.suffix == ".smt2"
        pattern = SMT_CONSTANT if self.smt else GAPPA_CONSTANT
        self.constants = {m[1]: m[2].strip() for m in pattern.finditer(self.text)}

    @classmethod
    def named(cls, name):
        """The proof a registry entry names: PATH, or PATH:VARIANT for one variant of a file."""
        path, _, variant = name.partition(":")
        return cls(ROOT / path, variant or None)

    @property
    def name(self):
        path = self.path.relative_to(ROOT).as_posix()
        return path if self.variant is None else f"{path}:{self.variant}"

    def cases(self, text=None):
        """The gappa inputs of this proof: one, or one per sign case. `# signs: e; r c` splits on the sign of e
        and of r: each hypothesis `e in [-X, X]` becomes `[0, X]` or `[-X, 0]`, and |e| becomes e or (-e); the
        names after the first of a group (c) share its sign."""
        text = self.text if text is None else text
        groups = [g.split() for spec in self.header.get("signs", []) for g in spec.split(";") if g.split()]
        out = []
        for signs in itertools.product((1, -1), repeat=len(groups)):
            case = text
            for group, sign in zip(groups, signs):
                case = re.sub(r"\b" + re.escape(group[0]) + r" in \[([^,\]]+),([^\]]+)\]",
                              lambda m: f"{group[0]} in [0,{m[2]}]" if sign > 0 else f"{group[0]} in [{m[1]}, 0]",
                              case)
                for name in group:
                    case = case.replace(f"|{name}|", name if sign > 0 else f"(-{name})")
            out.append(case)
        return out

    @property
    def lemma(self):
        """A lemma proves a step of other proofs (they name it in `# uses:`), not a constant of impl/."""
        return "lemma" in self.header

    def refutations(self):
        """A lemma's `# refute: OLD => NEW` lines: with every OLD of its text made NEW it must not prove."""
        return [tuple(part.strip() for part in entry.partition("=>")[::2])
                for entry in self.header.get("refute", [])]

    def value(self, name):
        """The exact value of constant name as this proof defines it."""
        text = self.constants[name]
        if self.smt:
            m = re.fullmatch(r"\(/ ([\d.]+) ([\d.]+)\)|([\d.]+)", text)
            return None if not m else Fraction(m[3]) if m[3] else Fraction(m[1]) / Fraction(m[2])
        return evaluate(text, exact=True)

    def with_constant(self, name, value):
        """The proof's text with constant name set to value, a C++ literal (scripts/mutants, proofs/bounds.tsv)."""
        if self.smt:
            q = Fraction(evaluate(value, exact=False))
            return re.sub(r"^(\(define-fun " + re.escape(name) + r" \(\) Real ).+\)$",
                          lambda m: f"{m[1]}(/ {q.numerator}.0 {q.denominator}.0))", self.text, flags=re.M)
        return re.sub(r"^(" + re.escape(name) + r"\s*=\s*)[^;]+;", lambda m: m[1] + value + ";", self.text,
                      flags=re.M)

    def run(self, text, seconds):
        return (z3 if self.smt else gappa)(text, seconds)


GAPPA = ["gappa"]
Z3 = ["z3"]


def all_proofs():
    return [Proof(path, variant) for folder in PROOF_DIRS for path in sorted((ROOT / folder).glob("*.[gs]*"))
            if path.suffix in (".g", ".smt2") for variant in file_variants(path)]


def gappa(text, seconds):
    """True when gappa proves text within seconds, False when it does not."""
    try:
        result = subprocess.run(GAPPA, input=text, capture_output=True, text=True, timeout=seconds)
    except subprocess.TimeoutExpired:
        return False
    return result.returncode == 0


def z3(text, seconds):
    """True when z3 finds the negated claim unsatisfiable within seconds (the claim holds), False when it finds a
    counterexample, gives up or runs out of time."""
    try:
        result = subprocess.run(Z3 + ["-in", f"-T:{seconds}"], input=text, capture_output=True, text=True,
                                timeout=seconds + 10)
    except subprocess.TimeoutExpired:
        return False
    return result.stdout.split()[:1] == ["unsat"]


# ── the registry ─────────────────────────────────────────────────────────────────────────────────────────

class Row:
    def __init__(self, line_number, fields):
        self.line = line_number
        self.name = fields[0]
        self.evidence = fields[1] if len(fields) > 1 else ""
        self.options = {}
        for field in fields[2:]:
            key, _, value = field.partition(" ")
            self.options[key] = value.strip()

    @property
    def proofs(self):
        return [] if self.evidence.startswith("none:") else self.evidence.split()


def read_registry(failures):
    rows = {}
    for number, line in enumerate(REGISTRY.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        row = Row(number, line.split("\t"))
        if row.name in rows:
            failures.add(f"proofs/bounds.tsv:{number}: {row.name} has a row already")
        rows[row.name] = row
    return rows


def load_mutants():
    loader = importlib.machinery.SourceFileLoader("mutants", str(ROOT / "scripts/mutants"))
    spec = importlib.util.spec_from_loader("mutants", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module.MUTANTS


def mutant_value(m):
    """The lowered value a mutant gives a constant, or None when it is not a constant's edit."""
    if not m.old.endswith(";") or m.old.count("=") != 1 or f" {m.name} =" not in m.old:
        return None
    return m.new.split("=")[-1].strip(" ;")


def static(failures):
    rows = read_registry(failures)
    constants = cpp_constants()
    for name in sorted(set(constants) - set(rows)):
        failures.add(f"{constants[name][0]}: {name} is in no row of proofs/bounds.tsv: prove it or explain it")
    for name in sorted(set(rows) - set(constants)):
        failures.add(f"proofs/bounds.tsv:{rows[name].line}: {name} is no double constant of impl/")
    proved = set()
    for row in rows.values():
        where = f"proofs/bounds.tsv:{row.line}: {row.name}"
        if row.evidence.startswith("none:"):
            kind, _, reason = row.evidence[5:].partition(",")
            if kind.strip() not in KINDS or not reason.strip():
                failures.add(f"{where}: `none:` needs a kind ({', '.join(KINDS)}), a comma and a reason")
            continue
        if not row.proofs:
            failures.add(f"{where}: neither proofs nor `none: KIND, REASON`")
        for path in row.proofs:
            proved.add(path)
            file, _, variant = path.partition(":")
            if not file.startswith(PROOF_DIRS) or not (ROOT / file).is_file():
                failures.add(f"{where}: {file} is no file under {' or '.join(PROOF_DIRS)}")
            elif (variant or None) not in file_variants(ROOT / file):
                failures.add(f"{where}: {file} has no variant {variant!r} (its `# variants:` line)")
            elif row.name not in Proof.named(path).constants:
                failures.add(f"{where}: {path} does not define {row.name}")
    proofs = all_proofs()
    lemmas = {proof.name: proof for proof in proofs if proof.lemma}
    used = {name for proof in proofs for name in proof.header.get("uses", [])}
    for proof in proofs:
        if proof.lemma:
            if proof.name not in used:
                failures.add(f"{proof.name}: a lemma no proof `# uses:`")
            if proof.name in proved:
                failures.add(f"{proof.name}: a lemma is no constant's proof: name it in a proof's `# uses:`")
            if not proof.refutations():
                failures.add(f"{proof.name}: a lemma needs a `# refute: OLD => NEW` that must not prove")
            for old, new in proof.refutations():
                if not old or old not in proof.text:
                    failures.add(f"{proof.name}: `# refute:` {old!r} is not in its text")
        elif proof.name not in proved:
            failures.add(f"{proof.name}: in no row of proofs/bounds.tsv")
        for name in proof.header.get("uses", []):
            if name not in lemmas:
                failures.add(f"{proof.name}: `# uses: {name}` is no lemma (a proof with a `# lemma:` line)")
        for key in HEADER:
            if key not in proof.header:
                failures.add(f"{proof.name}: its header has no `# {key}:` line")
        for entry in proof.header.get("hash", []):
            parts = entry.split()
            if len(parts) != 3:
                failures.add(f"{proof.name}: `# hash: {entry}` is not FILE FUNCTION HEX")
                continue
            now = body_hash(parts[0], parts[1]) if (ROOT / parts[0]).is_file() else None
            if now is None:
                failures.add(f"{proof.name}: no definition of {parts[1]} in {parts[0]}")
            elif now != parts[2]:
                failures.add(f"{proof.name}: {parts[1]} in {parts[0]} changed (hash {now}, the proof says "
                             f"{parts[2]}): check the proof still models it, then update its `# hash:`")
        for name, text in proof.constants.items():
            if name not in constants:
                failures.add(f"{proof.name}: {name} is no double constant of impl/")
                continue
            mine, theirs = proof.value(name), evaluate(constants[name][1], exact=False)
            if mine is None or theirs is None:
                failures.add(f"{proof.name}: {name}: cannot evaluate `{text}` or `{constants[name][1]}`")
            elif mine != Fraction(theirs):
                failures.add(f"{proof.name}: {name} = {text} here but {constants[name][1]} in {constants[name][0]}")
    for m in load_mutants():
        row, value = rows.get(m.name), mutant_value(m)
        if row is None or value is None or not row.proofs:
            continue
        slack = row.options.get("slack")
        if (m.known is not None and m.known.startswith("slack")) != (slack == value):
            failures.add(f"proofs/bounds.tsv:{row.line}: {m.name}: scripts/mutants "
                         f"{'calls' if m.known else 'does not call'} {value} slack, the registry "
                         f"{'does' if slack == value else 'does not'}")
    check_hardening_table(rows, failures)
    return rows


def machine_checked(row):
    """The cell of docs/hardening.md's mutants table for a bound: its proofs, or the kind of claim it is."""
    if row is None:
        return "not machine-checked: not a constant (a step of the proof)"
    if not row.proofs:
        return f"not machine-checked ({row.evidence[5:].partition(',')[0].strip()})"
    return ", ".join(f"`{path.split('/')[-1]}`" for path in row.proofs)


def check_hardening_table(rows, failures):
    """docs/hardening.md's mutants table says of each bound what the registry says."""
    text = (ROOT / "docs/hardening.md").read_text(encoding="utf-8")
    start = text.index("| mutant (file) | edit | verdict: the first test that failed | machine-checked")
    for line in text[start:text.index("\n\n", start)].splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        name = cells[0].split(" (")[0]
        if cells[-1] != machine_checked(rows.get(name)):
            failures.add(f"docs/hardening.md: the mutants table says {cells[-1]!r} of {name}, "
                         f"proofs/bounds.tsv {machine_checked(rows.get(name))!r}")


def jobs_of(rows, failures):
    """(label, proof texts, expected verdict) for every gappa run: each proof, then each lowered constant."""
    jobs = []
    for proof in all_proofs():
        jobs.append((proof.name, [(proof, case) for case in proof.cases()], True))
        for old, new in proof.refutations():
            jobs.append((f"{proof.name} with {old} => {new}",
                         [(proof, case) for case in proof.cases(proof.text.replace(old, new))], False))
    mutants = {m.name: mutant_value(m) for m in load_mutants()}
    for row in rows.values():
        if not row.proofs:
            continue
        proofs = [Proof.named(p) for p in row.proofs]
        lowered = [v for v in (row.options.get("fails"), mutants.get(row.name))
                   if v and v != "never" and v != row.options.get("slack")]
        if not lowered and row.options.get("fails") != "never":
            failures.add(f"proofs/bounds.tsv:{row.line}: {row.name}: no value it must fail at (`fails V`, or "
                         f"a mutant), nor `fails never` with the reason in the docs")
        for value in dict.fromkeys(lowered):
            texts = [(p, case) for p in proofs for case in p.cases(p.with_constant(row.name, value))]
            jobs.append((f"{row.name} = {value}", texts, False))
        if row.options.get("slack"):
            value = row.options["slack"]
            texts = [(p, case) for p in proofs for case in p.cases(p.with_constant(row.name, value))]
            jobs.append((f"{row.name} = {value} (slack)", texts, True))
    return jobs


def prove(rows, jobs_count, failures):
    jobs = jobs_of(rows, failures)
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs_count) as pool:
        runs = [(label, expected, [pool.submit(proof.run, text, PROVE_SECONDS if expected else REFUTE_SECONDS)
                                   for proof, text in texts])
                for label, texts, expected in jobs]
        for label, expected, futures in runs:
            verdicts = [f.result() for f in futures]
            if expected and not all(verdicts):
                failures.add(f"{label}: not proved (case {verdicts.index(False) + 1} of {len(verdicts)})")
            elif not expected and all(verdicts):
                failures.add(f"{label}: still proves: the proof does not need the constant it names")
            else:
                print(f"{label}: {'proved' if expected else 'refuted, as it must be'} ({len(verdicts)} case(s))")
    print(f"{len(jobs)} proof jobs in {time.monotonic() - start:.0f} s")


def main(argv):
    parser = argparse.ArgumentParser(prog="proofs/check.py", description=__doc__.split("\n")[0])
    parser.add_argument("mode", choices=("static", "prove", "hash", "case"))
    parser.add_argument("args", nargs="*")
    parser.add_argument("--jobs", type=int, default=2, help="gappa runs at once (default 2)")
    parser.add_argument("--gappa", default="gappa", help="the gappa program (default: gappa on the PATH)")
    parser.add_argument("--z3", default="z3", help="the z3 program (default: z3 on the PATH)")
    args = parser.parse_args(argv)
    GAPPA[0], Z3[0] = args.gappa, args.z3
    if args.mode == "hash":
        if len(args.args) != 2:
            parser.error("hash takes FILE FUNCTION")
        print(body_hash(*args.args) or f"no definition of {args.args[1]} in {args.args[0]}")
        return 0
    if args.mode == "case":
        if len(args.args) not in (1, 2):
            parser.error("case takes PROOF [N]")
        file, _, variant = args.args[0].partition(":")
        if not (ROOT / file).is_file() or (variant or None) not in file_variants(ROOT / file):
            parser.error(f"{args.args[0]}: no such proof (a variant is PATH:NAME, its file's `# variants:` line)")
        cases = Proof.named(args.args[0]).cases()
        number = int(args.args[1]) if len(args.args) == 2 else 1
        if not 1 <= number <= len(cases):
            parser.error(f"{args.args[0]} has {len(cases)} case(s)")
        print(cases[number - 1], end="")
        return 0
    failures = Failures()
    rows = static(failures)
    if args.mode == "prove" and not failures:
        prove(rows, args.jobs, failures)
    for failure in failures:
        print(f"proofs/check.py: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
