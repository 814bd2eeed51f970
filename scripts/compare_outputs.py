#!/usr/bin/env python3
"""Before/after safety net for refactors: run a fixed list of lrchain commands, then compare two runs.

  scripts/compare_outputs.py list --lrchain build/cli/lrchain [--only PATTERN] [--quick]
  scripts/compare_outputs.py run --lrchain build/cli/lrchain --out /tmp/before [--only PATTERN] [--quick]
  scripts/compare_outputs.py compare /tmp/before /tmp/after

The cases (in this order):
  example-*   every example config: examples/*.toml and examples/models/*.toml through
              `lrchain simulate --config FILE`, examples/sweeps/*.toml through `lrchain sweep --config FILE`;
  doc-*       every `lrchain ...` command line in a fenced code block of README.md and docs/*.md
              (parsed with shlex; a line that is a synopsis with placeholders, needs a file that does
              not exist, needs an MPI launcher or prints the build's commit is skipped, with its reason);
  reproduce-quick   `lrchain reproduce --quick`.
Every case writes to its own directory DIR/<case>/: the tool's --out (or a sweep's --output) is set to
DIR/<case>/out, stdout is saved as stdout.json (or stdout.txt when it is not JSON), stderr as
stderr.txt, and the argv, exit code and wall time as case.json. Children run from the source tree (the
examples name files relative to it) with an argv list, a timeout each, and XDG_CACHE_HOME=DIR/.cache so
model compiles do not touch the user's cache. Sweeps get --threads 1 and --quiet (their results do not
depend on either); run the script under `nice -n 19` on a shared machine.

--quick shrinks long runs only where the tool has an option for it: `reproduce --full` becomes
`--quick`. The dark-stability atlas sweep (7 minutes on one thread; `lrchain sweep` has no option to
run a subset) is skipped under --quick, with that reason. What --quick changed is recorded in case.json
and manifest.json, so a quick run compared with a full run shows up as a difference.

compare: for every case the exit codes and argv must be equal, every data file byte-identical and
every JSON file equal apart from provenance and timing. See IGNORED_JSON_KEYS and compare_file for
exactly what is ignored. Exit 0 if identical, 1 if not, 2 for bad usage.
"""

import argparse
import fnmatch
import glob
import hashlib
import json
import math
import os
import re
import shlex
import signal
import subprocess
import sys
import time
from pathlib import Path

SOURCE_DEFAULT = Path(__file__).resolve().parents[1]
OUT_TOKEN = "{OUT}"  # stands in the recorded argv for DIR/<case>/out, so two runs in different DIRs agree

# JSON keys left out of the comparison, wherever they occur: build, machine and invocation facts, and
# wall-clock durations. Each entry names what writes it. Physics numbers are never in this list.
IGNORED_JSON_KEYS = {
    "provenance",      # lib/src/provenance.cpp: version, git commit, compiler, date, hardware threads, argv
    "seconds",         # wall time: reproduce steps and total, regime map curves, sweep, lattice-code load
    "wall_seconds",    # simulate / simulate --model: wall time of the whole run
    "solve_seconds",   # sim/src/run_json.cpp, model_bright_outputs.cpp: wall time of the integration
    "map_seconds",     # regime map: wall time of the map
    "derive_seconds",  # derive: wall time of the symbolic derivation
    "check_seconds",   # derive: wall time of the checks
    "probe_seconds",   # bright: wall time of the automatic step probe (the chosen step is compared)
}
# Keys ignored only inside an object under this parent key: the state of the model cache, which
# depends on which cases ran before in the same DIR (e.g. with --only), not on the code.
IGNORED_JSON_KEYS_UNDER = {"lattice_code": {"from_cache", "library"}}
# CSV columns dropped before comparing when the bytes differ: the sweep's CSV view has a wall-time column.
IGNORED_CSV_COLUMNS = {"wall_seconds"}
# Text files in which the run directory and source tree paths are replaced by <RUN> and <SOURCE>.
TEXT_SUFFIXES = {".json", ".txt", ".gp", ".html", ".md", ".tex", ".svg", ".csv", ".toml", ".log"}
# Parts of the reproduce report's HTML that are provenance or timing, replaced by "<volatile>" before
# comparing (cli/src/report/html_report.cpp): the total time, each step's time, the provenance table.
VOLATILE_HTML = [
    re.compile(r"(<p>Produced by <code>[^<]*</code> in )[0-9.]+( s\.)"),
    re.compile(r"(Step time: )[0-9.]+( s)"),
    re.compile(r"([ ,])[0-9.]+( s solve\.)"),  # steps_bright.cpp, steps_lattice.cpp: the solve time of a run
    re.compile(r"(<tr><td>(?:lrchain|git commit|compiler|build type|machine|date \(UTC\))</td><td>)[^<]*(</td></tr>)"),
]
# stderr (stderr.txt): warnings and error messages are compared; progress lines carry times and, for
# steps run in parallel (reproduce --jobs), come in any order: times become "<t> s", the counter
# "[ k/N]" goes, and the lines are compared as a sorted list.
STDERR_TIME = re.compile(r"\b[0-9]+(\.[0-9]+)? s\b")
STDERR_COUNTER = re.compile(r"^\[\s*[0-9]+/[0-9]+\]")
# `lrchain derive` prints text that differs between two runs of the same build with the same argv:
# GiNaC writes the terms and factors of an expression in a varying order, with the signs moved
# ("-1/2 (a^2 - a)" and "1/2 (a - a^2)"), a check's "max difference" differs in its leading digits
# (7.32e-.. and 4.88e-..), and it prints its own timing. Differences in the text outputs of these
# subcommands are printed as UNSTABLE and do not make compare fail; their JSON outputs are compared.
UNSTABLE_TEXT_SUBCOMMANDS = {"derive": "derive's text output varies from run to run of the same build"}
# A sweep's side-files manifest (jobs/src/sweep/side_files.cpp, .OUTPUT.lrchain-files) is JSON holding the
# SHA-256 of its CSV views, which have a wall-time column: the names are compared, the hashes not (the
# CSV files themselves are compared, without that column).
SIDE_FILES_SUFFIX = ".lrchain-files"
# HDF5 files embed the date, commit and (sweeps) per-point wall times, and the standard library cannot
# read them: they are listed as not compared; the same numbers are compared in the CSV/JSON views.
UNCOMPARED_SUFFIXES = {".h5": "HDF5 embeds date, commit and wall times; no HDF5 reader in the Python standard library"}
# Example configs too long to run under --quick, and why (there is no option to shrink them).
# (examples/sweeps/atlas_bright_optical.toml, 342 short lattice runs, took 20 s on one thread: it stays.)
LONG_EXAMPLES = {
    "examples/sweeps/atlas_dark_stability.toml":
        "12 dark continuations (101 sites) with Floquet multipliers at every point: 442 s on one thread",
}
NOT_SHELL_FENCES = {"python", "py", "toml", "cmake", "cpp", "c++", "json", "ini"}  # code, not command lines
PLACEHOLDERS = {"DIR", "FILE", "N", "ID", "NAME", "PATH", "...", "ID,..."}
FILE_SUFFIXES = (".toml", ".h5", ".bin", ".csv", ".json")


class UsageError(Exception):
    """Bad command line or directory: exit 2 with one line on stderr."""


# ---------------------------------------------------------------- the case list


def case_slug(words):
    """A file-name-safe slug of some argv words."""
    return re.sub(r"[^A-Za-z0-9]+", "-", "-".join(words)).strip("-").lower()


def subcommand_words(argv):
    """The leading subcommand words of an lrchain argv (up to the first option)."""
    words = []
    for token in argv:
        if token.startswith("-"):
            break
        words.append(token)
    return words


class HelpCache:
    """Answers whether `lrchain WORDS` takes an option, from its --help (cached per subcommand)."""

    def __init__(self, lrchain):
        self.lrchain = lrchain
        self.texts = {}

    def takes(self, words, option):
        key = tuple(words)
        if key not in self.texts:
            done = subprocess.run([str(self.lrchain), *words, "--help"], capture_output=True, text=True, timeout=60)
            self.texts[key] = done.stdout
        return re.search(r"^\s*(?:-\w,)?" + re.escape(option) + r"\b", self.texts[key], re.M) is not None


def set_option(argv, option, value):
    """argv with OPTION's value replaced by VALUE, or OPTION VALUE appended."""
    argv = list(argv)
    for i, token in enumerate(argv):
        if token == option and i + 1 < len(argv):
            argv[i + 1] = value
            return argv
        if token.startswith(option + "="):
            argv[i] = option + "=" + value
            return argv
    return argv + [option, value]


def direct_outputs(argv, help_cache):
    """argv with every output of the command pointed into the case directory."""
    words = subcommand_words(argv)
    if words[:1] == ["sweep"]:
        argv = set_option(argv, "--output", OUT_TOKEN + "/results.h5")
        if "--threads" not in argv:
            argv += ["--threads", "1"]
        if "--quiet" not in argv:
            argv += ["--quiet"]
        return argv
    if help_cache.takes(words, "--out"):
        return set_option(argv, "--out", OUT_TOKEN)
    return argv


def quick_changes(argv):
    """(argv, changes): the shrunk argv under --quick and a description of each change."""
    if subcommand_words(argv)[:1] == ["reproduce"] and "--full" in argv:
        return [("--quick" if t == "--full" else t) for t in argv], ["reproduce --full -> --quick"]
    return argv, []


def example_cases(source):
    """(cases, skipped) for the example configs."""
    cases, skipped = [], []
    for pattern in ("examples/*.toml", "examples/models/*.toml", "examples/sweeps/*.toml"):
        for path in sorted(glob.glob(str(source / pattern))):
            rel = Path(path).relative_to(source).as_posix()
            sub = "sweep" if "/sweeps/" in rel else "simulate"
            name = "example-" + case_slug([Path(rel).parent.name if rel.count("/") > 1 else "", Path(rel).stem])
            cases.append({"name": name, "origin": rel, "argv": [sub, "--config", rel]})
    return cases, skipped


def doc_command_lines(source):
    """(origin, line) of every line in a fenced code block of README.md and docs/*.md."""
    files = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    for path in files:
        fence = None
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            stripped = line.strip()
            if stripped.startswith("```") or stripped.startswith("~~~"):
                fence = None if fence else (stripped[3:].strip() or "text")
                continue
            if fence and fence not in NOT_SHELL_FENCES:
                yield f"{path.relative_to(source).as_posix()}:{number}", stripped


def doc_skip_reason(tokens, source):
    """Why a doc command line cannot be run as a case, or None."""
    if any(t in PLACEHOLDERS or "[" in t or "]" in t or "|" in t for t in tokens[1:]):
        return "a synopsis with placeholders or optional parts"
    if tokens[1:] == ["--version"]:
        return "prints the build's version and commit: differs between builds by design"
    for t in tokens[1:]:
        value = t.split("=", 1)[1] if t.startswith("--") and "=" in t else t
        if value.startswith("~") or (value.endswith(FILE_SUFFIXES) and not (source / value).exists()):
            return f"needs the file {value}, which does not exist in the source tree"
    return None


def doc_cases(source):
    """(cases, skipped) for the lrchain command lines of the docs."""
    cases, skipped = [], []
    for origin, line in doc_command_lines(source):
        try:
            tokens = shlex.split(line, comments=True)
        except ValueError:
            continue  # prose or program output, not a command line
        positions = [i for i, t in enumerate(tokens) if (t == "lrchain" or t.endswith("/lrchain"))
                     and not (i > 0 and tokens[i - 1].startswith("--"))]  # not an option's value (--lrchain PATH)
        if not positions:
            continue
        if positions[0] != 0:
            skipped.append({"origin": origin, "command": line, "reason": f"not a plain lrchain command line (starts with {tokens[0]})"})
            continue
        reason = doc_skip_reason(tokens, source)
        if reason:
            skipped.append({"origin": origin, "command": line, "reason": reason})
            continue
        argv = tokens[1:]
        digest = hashlib.sha256("\0".join(argv).encode()).hexdigest()[:8]
        cases.append({"name": "doc-" + case_slug(subcommand_words(argv)) + "-" + digest, "origin": origin, "argv": argv})
    return cases, skipped


def all_cases(source, lrchain, quick):
    """(cases, skipped): the fixed list, outputs directed, duplicates folded, --quick applied."""
    help_cache = HelpCache(lrchain)
    examples, skipped_examples = example_cases(source)
    docs, skipped_docs = doc_cases(source)
    reproduce = [{"name": "reproduce-quick", "origin": "the quick report", "argv": ["reproduce", "--quick"]}]
    cases, skipped, seen = [], skipped_examples + skipped_docs, {}
    for case in examples + reproduce + docs:
        argv, changes = direct_outputs(case["argv"], help_cache), []
        if quick:
            argv, changes = quick_changes(argv)
            config = argv[argv.index("--config") + 1] if "--config" in argv[:-1] else None
            if config in LONG_EXAMPLES:
                skipped.append({"origin": case["origin"], "command": "lrchain " + shlex.join(case["argv"]),
                                "reason": "skipped under --quick: " + LONG_EXAMPLES[config]})
                continue
        if tuple(argv) in seen:
            seen[tuple(argv)]["also"].append(case["origin"])
            continue
        entry = {"name": case["name"], "origin": case["origin"], "also": [], "argv": argv, "quick_changes": changes}
        seen[tuple(argv)] = entry
        cases.append(entry)
    return cases, skipped


def select(cases, pattern):
    """The cases whose name matches the fnmatch PATTERN (all without one)."""
    return [c for c in cases if pattern is None or fnmatch.fnmatch(c["name"], pattern)]


# ---------------------------------------------------------------- the Python module's results


def python_calls():
    """(name, call) of the Python module calls whose results are saved: small and fast, one per door."""
    import numpy as np
    import lrchain
    from math import pi

    params = lrchain.Params()
    theta = np.linspace(0.05, pi, 64)
    return [
        ("coefficients_optical", lambda: lrchain.coefficients(params, "optical", theta)),
        ("coefficients_acoustic_rho10", lambda: lrchain.coefficients(lrchain.Params(rho=10), "acoustic", theta)),
        ("coefficients_klein_gordon", lambda: lrchain.coefficients(lrchain.load_model("klein_gordon", w0=1.2), "branch0", theta)),
        ("regime_theta_rho_map", lambda: lrchain.regime.theta_rho_map(params, "optical", rho=(0.01, 2.5, 24), theta=(0.01, 3.1, 24))),
        ("simulate_bright", lambda: lrchain.simulate.bright(params, "optical", pi / 2, sites=201, periods=3)),
        ("dark_continue_branch", lambda: lrchain.dark.continue_branch(params, omega_b=2.42, sites=41, points=4, ds=0.1)),
    ]


def arrays_of(value, name, out, depth=0):
    """Adds every number, string and array reachable from VALUE to OUT under NAME/... (timing and provenance left out)."""
    import numpy as np

    if depth > 4 or callable(value) and not hasattr(value, "__dict__"):
        return
    if isinstance(value, np.ndarray):
        if value.dtype != object:
            out[name] = value
        else:
            for i, v in enumerate(value.ravel()):
                arrays_of(v, f"{name}/{i}", out, depth + 1)
    elif isinstance(value, (bool, int, float, complex, str, np.generic)) or value is None:
        out[name] = np.asarray(str(value) if value is None else value)
    elif isinstance(value, dict):
        for k, v in value.items():
            if k not in IGNORED_JSON_KEYS:
                arrays_of(v, f"{name}/{k}", out, depth + 1)
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            arrays_of(v, f"{name}/{i}", out, depth + 1)
    else:
        for attribute in dir(value):
            if attribute.startswith("_") or attribute in ("params",):
                continue
            member = getattr(value, attribute)
            if not callable(member):
                arrays_of(member, f"{name}/{attribute}", out, depth + 1)


def command_python_results(args):
    """`python-results` (run by `run --python-path`): the Python calls' results into one .npz."""
    import numpy as np

    out = {}
    for name, call in python_calls():
        arrays_of(call(), name, out)
    np.savez(args.out, **out)
    print(json.dumps({"arrays": len(out), "file": args.out}))
    return 0


def npy_element(data):
    """(header dict, header length) of one .npy member."""
    import ast

    major = data[6]
    length = int.from_bytes(data[8:10], "little") if major == 1 else int.from_bytes(data[8:12], "little")
    start = 10 if major == 1 else 12
    return ast.literal_eval(data[start:start + length].decode("latin1")), start + length


def compare_npz(a_path, b_path):
    """The first differing array of two .npz files (bit for bit), or None. Zip timestamps are ignored."""
    import zipfile

    with zipfile.ZipFile(a_path) as a, zipfile.ZipFile(b_path) as b:
        a_names, b_names = set(a.namelist()), set(b.namelist())
        if a_names != b_names:
            return f"arrays only in one: {sorted(a_names ^ b_names)[:5]}"
        for member in sorted(a_names):
            x, y = a.read(member), b.read(member)
            if x == y:
                continue
            header, start = npy_element(x)
            offset = next((i for i, (p, q) in enumerate(zip(x, y)) if p != q), min(len(x), len(y)))
            if offset < start or len(x) != len(y):
                return f"{member[:-4]}: header or size differs ({header})"
            itemsize = int("".join(c for c in header["descr"] if c.isdigit()) or 1)
            return f"{member[:-4]}: element {(offset - start) // itemsize} (flat) differs, dtype {header['descr']}"
    return None


# ---------------------------------------------------------------- running


def run_case(case, lrchain, source, case_dir, env, timeout, recorded=True):
    """Runs one case into CASE_DIR and writes its case.json."""
    case_dir.mkdir(parents=True, exist_ok=not recorded)
    out = case_dir / "out"
    argv = [a.replace(OUT_TOKEN, str(out)) for a in case["argv"]]
    start = time.monotonic()
    with open(case_dir / "stdout.raw", "wb") as stdout, open(case_dir / "stderr.txt", "wb") as stderr:
        child = subprocess.Popen([str(lrchain), *argv], cwd=source, env=env, stdout=stdout, stderr=stderr,
                                 stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            exit_code = child.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(child.pid, signal.SIGTERM)  # the child's own process group: it and its gnuplots
            try:
                child.wait(timeout=20)
            except subprocess.TimeoutExpired:
                os.killpg(child.pid, signal.SIGKILL)
                child.wait()
            exit_code = "timeout"
    seconds = time.monotonic() - start
    raw = (case_dir / "stdout.raw").read_bytes()
    try:
        json.loads(raw)
        (case_dir / "stdout.raw").rename(case_dir / "stdout.json")
    except ValueError:
        (case_dir / "stdout.raw").rename(case_dir / "stdout.txt")
    record = dict(case, exit_code=exit_code, seconds=round(seconds, 3), timeout=timeout)
    if not recorded:
        record["argv"] = record["argv"][1:]  # the script's own path differs between trees
    (case_dir / "case.json").write_text(json.dumps(record, indent=2) + "\n")
    return exit_code, seconds


def executable(path):
    """The --lrchain path, resolved (UsageError if it is not an executable file)."""
    resolved = Path(path).resolve()
    if not resolved.is_file() or not os.access(resolved, os.X_OK):
        raise UsageError(f"--lrchain {path}: not an executable file")
    return resolved


def command_run(args):
    """`run`: every selected case into args.out."""
    lrchain, source = executable(args.lrchain), Path(args.source).resolve()
    out = Path(args.out).resolve()
    cases, skipped = all_cases(source, lrchain, args.quick)
    chosen = select(cases, args.only)
    if not chosen and not (args.python_path and args.only == "python"):
        raise UsageError(f"--only {args.only}: matches no case (see the list subcommand)")
    for case in chosen + ([{"name": "python"}] if args.python_path else []):
        if (out / case["name"]).exists():
            raise UsageError(f"--out {args.out}: {case['name']} exists already; use a new directory")
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, XDG_CACHE_HOME=str(out / ".cache"))
    version = subprocess.run([str(lrchain), "--version"], capture_output=True, text=True).stdout.strip()
    manifest = {"lrchain": str(lrchain), "version": version, "source": str(source), "run_dir": str(out),
                "quick": args.quick, "only": args.only, "cases": [c["name"] for c in chosen], "skipped": skipped}
    if (out / "manifest.json").is_file():  # a second run into the same DIR (other cases): keep the first's list
        earlier = load_json(out / "manifest.json")
        manifest["cases"] = earlier.get("cases", []) + manifest["cases"]
        manifest["runs"] = earlier.get("runs", 1) + 1
    (out / "manifest.json").write_text(json.dumps(manifest, indent=2) + "\n")
    total = time.monotonic()
    for case in chosen:
        exit_code, seconds = run_case(case, lrchain, source, out / case["name"], env, args.timeout)
        print(f"{case['name']}: exit {exit_code}, {seconds:.1f} s", flush=True)
    if args.python_path:
        python_env = dict(env, PYTHONPATH=str(Path(args.python_path).resolve()), PYTHONDONTWRITEBYTECODE="1")
        case = {"name": "python", "origin": "python_calls() in this script", "also": [], "quick_changes": [],
                "argv": [str(Path(__file__).resolve()), "python-results", "--out", OUT_TOKEN + "/results.npz"]}
        (out / "python" / "out").mkdir(parents=True)
        exit_code, seconds = run_case(case, args.python, source, out / "python", python_env, args.timeout, recorded=False)
        print(f"python: exit {exit_code}, {seconds:.1f} s", flush=True)
    print(f"{len(chosen)} cases in {time.monotonic() - total:.1f} s into {out} ({len(skipped)} command lines skipped: "
          f"see manifest.json)")
    return 0


def command_list(args):
    """`list`: the cases and the skipped command lines, without running anything."""
    cases, skipped = all_cases(Path(args.source).resolve(), executable(args.lrchain), args.quick)
    for case in select(cases, args.only):
        extra = f"  [quick: {'; '.join(case['quick_changes'])}]" if case["quick_changes"] else ""
        print(f"{case['name']}  ({case['origin']})  lrchain {shlex.join(case['argv'])}{extra}")
    for s in skipped:
        print(f"skipped  ({s['origin']})  {s['command']}: {s['reason']}")
    return 0


# ---------------------------------------------------------------- comparing


class Normaliser:
    """Replaces a run's directory and source tree in strings by <RUN> and <SOURCE>."""

    def __init__(self, manifest):
        self.pairs = [(manifest.get("run_dir", ""), "<RUN>"), (manifest.get("source", ""), "<SOURCE>")]
        self.pairs = sorted([p for p in self.pairs if p[0]], key=lambda p: -len(p[0]))

    def text(self, s):
        for path, marker in self.pairs:
            s = s.replace(path, marker)
        return s

    def json(self, value, parent=None):
        """VALUE with ignored keys removed and paths replaced."""
        if isinstance(value, dict):
            drop = IGNORED_JSON_KEYS | IGNORED_JSON_KEYS_UNDER.get(parent, set())
            return {k: self.json(v, k) for k, v in value.items() if k not in drop}
        if isinstance(value, list):
            return [self.json(v, parent) for v in value]
        if isinstance(value, str):
            return self.text(value)
        return value


def first_json_difference(a, b, path="$"):
    """(path, a, b) of the first difference between two JSON values (bit-exact numbers), or None."""
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                return (f"{path}.{key}", a.get(key, "<absent>"), b.get(key, "<absent>"))
            found = first_json_difference(a[key], b[key], f"{path}.{key}")
            if found:
                return found
        return None
    if isinstance(a, list) and isinstance(b, list):
        for i, (x, y) in enumerate(zip(a, b)):
            found = first_json_difference(x, y, f"{path}[{i}]")
            if found:
                return found
        return None if len(a) == len(b) else (f"{path}.length", len(a), len(b))
    if type(a) is not type(b):
        return (path, a, b)
    if isinstance(a, float) and (a != b and not (math.isnan(a) and math.isnan(b))):
        return (path, a, b)
    return None if a == b else (path, a, b)


def load_json(path):
    """Parsed JSON of a file; NaN and Infinity as Python accepts them."""
    return json.loads(path.read_text(encoding="utf-8"))


def first_line_difference(a_lines, b_lines):
    """(line number, a line, b line) of the first differing line."""
    for i, (x, y) in enumerate(zip(a_lines, b_lines), 1):
        if x != y:
            return i, x, y
    n = min(len(a_lines), len(b_lines)) + 1
    return n, a_lines[n - 1] if len(a_lines) >= n else "<end>", b_lines[n - 1] if len(b_lines) >= n else "<end>"


def csv_without_columns(text):
    """CSV text with the IGNORED_CSV_COLUMNS removed (plain comma-separated, as lrchain writes it)."""
    lines = text.splitlines()
    header = lines[0].split(",") if lines else []
    keep = [i for i, name in enumerate(header) if name.strip() not in IGNORED_CSV_COLUMNS]
    if len(keep) == len(header):
        return lines
    return [",".join(f for i, f in enumerate(line.split(",")) if i in keep) for line in lines]


def without_volatile_html(text):
    """HTML with the VOLATILE_HTML parts replaced by <volatile>."""
    for pattern in VOLATILE_HTML:
        text = pattern.sub(lambda m: m.group(1) + "<volatile>" + m.group(m.lastindex), text)
    return text


def stderr_lines(text):
    """stderr's lines without times and progress counters, sorted (see STDERR_TIME)."""
    return sorted(STDERR_COUNTER.sub("[k/N]", STDERR_TIME.sub("<t> s", line)) for line in text.splitlines())


def without_side_file_hashes(manifest):
    """A sweep's side-files manifest with the hashes of its files replaced by a marker."""
    if isinstance(manifest, dict) and isinstance(manifest.get("files"), dict):
        manifest = dict(manifest, files={name: "<sha256>" for name in manifest["files"]})
    return manifest


def compare_file(rel, a_path, b_path, norm_a, norm_b):
    """A description of the first difference between two files, or None if they agree."""
    suffix = a_path.suffix.lower()
    if suffix == ".npz":
        return compare_npz(a_path, b_path)
    if suffix == ".json" or a_path.name.endswith(SIDE_FILES_SUFFIX):
        try:
            a, b = norm_a.json(load_json(a_path)), norm_b.json(load_json(b_path))
            if a_path.name.endswith(SIDE_FILES_SUFFIX):
                a, b = without_side_file_hashes(a), without_side_file_hashes(b)
        except ValueError as e:
            a_bytes, b_bytes = a_path.read_bytes(), b_path.read_bytes()
            return None if a_bytes == b_bytes else f"not JSON ({e}) and the bytes differ"
        found = first_json_difference(a, b)
        return None if not found else f"at {found[0]}: {json.dumps(found[1])} != {json.dumps(found[2])}"
    a_bytes, b_bytes = a_path.read_bytes(), b_path.read_bytes()
    if a_bytes == b_bytes:
        return None
    if suffix in TEXT_SUFFIXES:
        try:
            a_text, b_text = norm_a.text(a_bytes.decode()), norm_b.text(b_bytes.decode())
        except UnicodeDecodeError:
            a_text = b_text = None
        if a_text is not None:
            if suffix == ".csv":
                a_lines, b_lines = csv_without_columns(a_text), csv_without_columns(b_text)
            elif rel == "stderr.txt":
                a_lines, b_lines = stderr_lines(a_text), stderr_lines(b_text)
            else:
                if suffix == ".html":
                    a_text, b_text = without_volatile_html(a_text), without_volatile_html(b_text)
                a_lines, b_lines = a_text.splitlines(), b_text.splitlines()
            if a_lines == b_lines and (suffix != ".csv" or a_text.endswith("\n") == b_text.endswith("\n")):
                return None
            line, x, y = first_line_difference(a_lines, b_lines)
            return f"line {line}: {x[:160]!r} != {y[:160]!r}"
    offset = next((i for i, (x, y) in enumerate(zip(a_bytes, b_bytes)) if x != y), min(len(a_bytes), len(b_bytes)))
    return f"bytes differ from offset {offset} (sizes {len(a_bytes)} and {len(b_bytes)})"


def files_under(case_dir):
    """Relative paths of every file in a case directory but case.json."""
    return {p.relative_to(case_dir).as_posix() for p in case_dir.rglob("*")
            if p.is_file() and p != case_dir / "case.json"}


def read_manifest(run_dir):
    """The manifest of a run directory (UsageError if there is none)."""
    path = run_dir / "manifest.json"
    if not path.is_file():
        raise UsageError(f"{run_dir}: no manifest.json (not a directory written by `compare_outputs.py run`)")
    return load_json(path)


def compare_case(name, before, after, norm_a, norm_b, report):
    """Compares one case; calls REPORT(file, text) for each difference; returns (compared, uncompared)."""
    a_dir, b_dir = before / name, after / name
    a_case, b_case = load_json(a_dir / "case.json"), load_json(b_dir / "case.json")
    for key in ("argv", "quick_changes", "exit_code"):
        if a_case.get(key) != b_case.get(key):
            report(f"{name}/case.json", f"{key}: {json.dumps(a_case.get(key))} != {json.dumps(b_case.get(key))}")
    a_files, b_files = files_under(a_dir), files_under(b_dir)
    compared = uncompared = 0
    for rel in sorted(a_files | b_files):
        if rel not in b_files or rel not in a_files:
            report(f"{name}/{rel}", "only in " + ("BEFORE" if rel in a_files else "AFTER"))
            continue
        if Path(rel).suffix.lower() in UNCOMPARED_SUFFIXES:
            uncompared += 1
            continue
        compared += 1
        found = compare_file(rel, a_dir / rel, b_dir / rel, norm_a, norm_b)
        words = subcommand_words(a_case.get("argv", []))
        unstable = UNSTABLE_TEXT_SUBCOMMANDS.get(words[0]) if words and rel in ("stdout.txt", "stderr.txt") else None
        if found:
            report(f"{name}/{rel}", found, unstable)
    return compared, uncompared


def command_compare(args):
    """`compare`: every case of two run directories."""
    before, after = Path(args.before).resolve(), Path(args.after).resolve()
    norm_a, norm_b = Normaliser(read_manifest(before)), Normaliser(read_manifest(after))
    names_a = {p.parent.name for p in before.glob("*/case.json")}
    names_b = {p.parent.name for p in after.glob("*/case.json")}
    differences, unstable = [], []

    def report(where, text, unstable_reason=None):
        (unstable if unstable_reason else differences).append(where)
        print(f"UNSTABLE {where} ({unstable_reason}): {text}" if unstable_reason else f"DIFF {where}: {text}")

    compared = uncompared = 0
    for name in sorted(names_a | names_b):
        if name not in names_a or name not in names_b:
            report(name, "case only in " + ("BEFORE" if name in names_a else "AFTER"))
            continue
        c, u = compare_case(name, before, after, norm_a, norm_b, report)
        compared, uncompared = compared + c, uncompared + u
    cases = len(names_a & names_b)
    print(f"{len(differences)} differences in {cases} cases ({compared} files compared; {len(unstable)} differences in "
          f"outputs known to vary run to run, not counted; {uncompared} HDF5 files not compared: "
          f"{UNCOMPARED_SUFFIXES['.h5']})")
    return 0 if not differences else 1


# ---------------------------------------------------------------- command line


class Parser(argparse.ArgumentParser):
    """argparse with exit code 2 and one line on stderr for bad usage."""

    def error(self, message):
        raise UsageError(message)


def parser():
    p = Parser(description=__doc__.split("\n\n")[0], epilog="example: nice -n 19 scripts/compare_outputs.py run "
               "--lrchain build/cli/lrchain --out /tmp/before --quick; (change the code, rebuild) ...run ... --out "
               "/tmp/after --quick; scripts/compare_outputs.py compare /tmp/before /tmp/after",
               formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True, parser_class=Parser)
    for name, help_text in (("run", "run the cases into --out"), ("list", "list the cases and the skipped command lines")):
        s = sub.add_parser(name, help=help_text)
        s.add_argument("--lrchain", required=True, help="the lrchain executable to run (e.g. build/cli/lrchain)")
        s.add_argument("--only", metavar="PATTERN", help="only the cases whose name matches this shell pattern, e.g. "
                       "'doc-coeffs-*' ('python' with --python-path: only the Python calls)")
        s.add_argument("--quick", action="store_true", help="shrink long runs where lrchain has an option for it (reproduce --full -> --quick); skip the "
                       "sweeps in LONG_EXAMPLES")
        s.add_argument("--source", default=str(SOURCE_DEFAULT), help=f"source tree with examples/ and docs/ (default {SOURCE_DEFAULT})")
        if name == "run":
            s.add_argument("--out", required=True, metavar="DIR", help="directory for the outputs, one subdirectory per case")
            s.add_argument("--timeout", type=float, default=3600, help="seconds per case before it is stopped (default 3600)")
            s.add_argument("--python-path", metavar="DIR", help="also run the Python calls of python_calls() with the lrchain "
                           "module in DIR (e.g. build/python) and save their results as python/out/results.npz")
            s.add_argument("--python", default="/usr/bin/python3" if Path("/usr/bin/python3").exists() else sys.executable,
                           help="interpreter for --python-path, with numpy (default /usr/bin/python3)")
    r = sub.add_parser("python-results", help="(run by run --python-path) save the Python calls' results")
    r.add_argument("--out", required=True, help="the .npz file to write")
    c = sub.add_parser("compare", help="compare two run directories: exit 0 identical, 1 different")
    c.add_argument("before", metavar="BEFORE_DIR")
    c.add_argument("after", metavar="AFTER_DIR")
    return p


def main(argv=None):
    try:
        args = parser().parse_args(argv)
        return {"run": command_run, "list": command_list, "compare": command_compare,
                "python-results": command_python_results}[args.command](args)
    except UsageError as e:
        print(f"compare_outputs.py: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
