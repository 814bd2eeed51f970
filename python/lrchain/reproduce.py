"""``lrchain.reproduce(out)``: ``lrchain reproduce`` (the paper's report) from Python.

The report's orchestration (steps run as child ``lrchain`` processes, the HTML rendered with
cmark-gfm) lives in the CLI; this module runs the ``lrchain`` executable with an argv, reads its
``--progress-json`` lines for the progress bar and its JSON summary for the result, and maps its exit
code to the exceptions of :mod:`lrchain.errors`. The executable is the package's ``bin/lrchain`` (a
link to the build tree's CLI, or the copy ``pip install`` puts in the package); the environment
variable ``LRCHAIN_EXECUTABLE`` names another.
"""

import json
import os
import re
import signal
import subprocess
import threading
from dataclasses import dataclass, field
from pathlib import Path

from .errors import InputError, InvalidParameterError, NumericalFailure, StepsFailed
from .progress import Counter

_PACKAGE_EXECUTABLE = Path(__file__).resolve().parent / "bin" / "lrchain"


def reproduce_executable():
    """The ``lrchain`` executable that :func:`reproduce` runs: ``$LRCHAIN_EXECUTABLE`` if set, else the
    package's ``bin/lrchain``. Raises ``FileNotFoundError`` saying what to build when it is missing.

    Example::

        >>> import lrchain
        >>> lrchain.reproduce_executable().name
        'lrchain'
    """
    named = os.environ.get("LRCHAIN_EXECUTABLE")
    path = Path(named) if named else _PACKAGE_EXECUTABLE
    if path.is_file() and os.access(path, os.X_OK):
        return path
    if named:
        raise FileNotFoundError(f"LRCHAIN_EXECUTABLE={named}: no executable file there")
    raise FileNotFoundError(
        f"lrchain.reproduce runs the lrchain executable, and {path} does not exist: in a build tree build "
        "it with `cmake --build <build> --target lrchain_python_executable` (the CLI lrchain_cli and "
        "its link python/lrchain/bin/lrchain); an installed module has it after `pip install .` or "
        "`cmake --install` (set LRCHAIN_EXECUTABLE to use another lrchain)")


def _text_option(name, value):
    """``--name=VALUE`` for a path or text: one argv word, so that a value starting with '-' stays a
    value."""
    return f"--{name.replace('_', '-')}={os.fspath(value)}"


def _argv(out, quick, jobs, only, examples, errata, figure_format):
    """The argv of ``lrchain reproduce`` for the keywords of :func:`reproduce` (None: the command's
    default)."""
    argv = [str(reproduce_executable()), "reproduce", "--quick" if quick else "--full", _text_option("out", out)]
    if jobs is not None:
        if isinstance(jobs, bool) or not isinstance(jobs, int):
            raise InvalidParameterError(f"invalid jobs: must be an integer in [0, 64], not {jobs!r}", "jobs")
        argv.append(f"--jobs={jobs}")
    if only is not None:
        ids = [only] if isinstance(only, str) else list(only)
        if not ids or any(not isinstance(i, str) or not i or "," in i for i in ids):
            raise InvalidParameterError("invalid only: must be a step id or a list of step ids from "
                                        "lrchain.reproduce_steps()", "only")
        argv.append("--only=" + ",".join(ids))
    for name, value in (("examples", examples), ("errata", errata), ("figure_format", figure_format)):
        if value is not None:
            argv.append(_text_option(name, value))
    return argv


_INVALID = re.compile(r"^lrchain: invalid ([a-z_][a-z0-9_]*): ")


def _raise_for(code, lines, result):
    """The exception of lrchain's exit code ``code`` (lrchain/exit_codes.hpp), with the child's last
    line of text on stderr as its message."""
    message = lines[-1] if lines else f"lrchain reproduce ended with exit code {code}"
    if code == 2:
        named = _INVALID.match(message)
        text = message[len("lrchain: "):] if message.startswith("lrchain: ") else message
        if named:
            raise InvalidParameterError(text, named.group(1))
        raise InputError(text)
    if code == 3:
        raise NumericalFailure(message)
    if code >= 128 or code == -signal.SIGINT:
        raise KeyboardInterrupt(message)
    if code == 1 and result is not None:
        raise StepsFailed(message, result)
    if code < 0:
        raise RuntimeError(f"lrchain reproduce was killed by signal {-code}")
    raise RuntimeError(message)


@dataclass
class ReproduceResult:
    """What :func:`reproduce` wrote: the report folder ``out``, its ``index.html`` (``report``), every
    file in it (``files``, sorted), and the JSON summary ``lrchain reproduce`` prints (``summary``:
    mode, pass / deviates / erratum / unresolved counts, failed_steps, figures_missing, seconds, one
    entry per step, provenance)."""

    out: Path
    report: Path
    summary: dict
    files: list = field(default_factory=list)

    @property
    def steps(self):
        """The summary's steps: dicts with id, seconds, failed and the step's counts."""
        return self.summary["steps"]

    @property
    def failed_steps(self):
        return self.summary["failed_steps"]


def _read_result(stdout_text):
    """The result from the JSON summary on stdout, or None when there is none."""
    try:
        summary = json.loads(stdout_text)
    except ValueError:
        return None
    report = Path(summary["report"])
    out = report.parent
    files = sorted(p for p in out.rglob("*") if p.is_file())
    return ReproduceResult(out=out, report=report, summary=summary, files=files)


def _follow(child, bar):
    """Reads the child's stderr to its end: --progress-json lines drive ``bar``, other lines (an error
    message) are returned."""
    text = []
    for line in child.stderr:
        line = line.rstrip("\n")
        event = None
        if line.startswith("{"):
            try:
                event = json.loads(line)
            except ValueError:
                event = None
        if not isinstance(event, dict) or "event" not in event:
            if line:
                text.append(line)
            continue
        if event["event"] == "start":
            bar.start(event["steps"])
        elif event["event"] == "step_finished":
            bar.advance(f"{event['step']} {'FAILED' if event['failed'] else 'done'}")
    return text


def _run(argv, what, progress):
    """Runs ``argv`` (an lrchain reproduce command with --progress-json) with a bar; Ctrl-C passes SIGINT
    on to it and raises KeyboardInterrupt once it has ended. Returns (exit code, stderr text lines,
    stdout)."""
    child = subprocess.Popen([*argv, "--progress-json"], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    stdout = []
    reader = threading.Thread(target=lambda: stdout.append(child.stdout.read()), daemon=True)
    reader.start()
    interrupted = False
    with Counter(what, progress) as bar:
        lines = []
        while True:
            try:
                lines += _follow(child, bar)
                child.wait()
                break
            except KeyboardInterrupt:  # the child stops its runs, removes DIR.partial and exits 130
                interrupted = True
                if child.poll() is None:
                    child.send_signal(signal.SIGINT)
    reader.join()
    if interrupted:
        raise KeyboardInterrupt((lines or ["lrchain reproduce interrupted by SIGINT"])[-1])
    return child.returncode, lines, "".join(stdout)


def reproduce(out, *, quick=True, jobs=None, only=None, examples=None, errata=None, figure_format=None,
              progress=None):
    """Runs every computation of the paper and writes its report ``out/index.html``, as
    ``lrchain reproduce`` does (the command runs: its outputs are the command's): each number the paper
    quotes next to ours (pass / deviates / erratum / unresolved) and each figure beside the paper's.
    The report is written to ``out.partial`` and renamed to ``out`` when complete; ``out`` must be new,
    empty or an earlier report (which is replaced).

    ``quick=True`` (``--quick``, under a minute on 2 cores) or False (``--full``: the paper's lattice
    sizes, tens of minutes); ``jobs``: steps run at the same time, in [0, 64] (None or 0: one per core);
    ``only``: a step id or a list of ids from :func:`lrchain.reproduce_steps` (None: every step);
    ``examples``, ``errata``: the experiment configs' folder and the errata page (None: the shipped
    ones); ``figure_format``: ``"png"`` (default), ``"svg"`` or ``"pdf"``. ``progress``: a bar over the
    steps with rate and ETA (:mod:`lrchain.progress`).

    Returns a :class:`ReproduceResult` (``out``, ``report``, ``files``, ``summary``: the command's JSON).
    Raises :class:`lrchain.InvalidParameterError` naming the keyword for a bad value (nothing written),
    :class:`lrchain.StepsFailed` (with ``.result``: the report is written) when a step failed, and
    ``KeyboardInterrupt`` on Ctrl-C (the runs are stopped and ``out.partial`` removed). The executable
    is :func:`lrchain.reproduce_executable`.

    Example::

        >>> import lrchain
        >>> r = lrchain.reproduce("report", only="coefficients", jobs=1, progress=False)  # one quick step
        >>> r.report.name, r.failed_steps, r.summary["pass"] > 0
        ('index.html', 0, True)
    """
    argv = _argv(out, quick, jobs, only, examples, errata, figure_format)
    code, lines, stdout = _run(argv, "reproduce", progress)
    result = _read_result(stdout) if stdout.strip() else None
    if code != 0:
        _raise_for(code, lines, result)
    if result is None:
        raise RuntimeError("lrchain reproduce printed no JSON summary")
    return result


def reproduce_steps():
    """The steps of :func:`reproduce` (``lrchain reproduce --list``): a dict of step id -> title, in
    the report's order; the ids are what ``only=`` takes.

    Example::

        >>> import lrchain
        >>> steps = lrchain.reproduce_steps()
        >>> "exp1" in steps, all(isinstance(title, str) and title for title in steps.values())
        (True, True)
    """
    done = subprocess.run([str(reproduce_executable()), "reproduce", "--list"], stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        _raise_for(done.returncode, done.stderr.splitlines(), None)
    steps = {}
    for line in done.stdout.splitlines():
        step, _, title = line.partition(" ")
        steps[step] = title.strip()
    return steps


__all__ = ["reproduce", "reproduce_steps", "reproduce_executable", "ReproduceResult"]
