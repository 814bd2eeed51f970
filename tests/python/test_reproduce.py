"""lrchain.reproduce: the argv it gives `lrchain reproduce`, its progress from --progress-json, the
exit codes as exceptions, Ctrl-C passed on to the child, a missing executable, and one real quick step.

Most tests run a fake `lrchain` (a Python script named by LRCHAIN_EXECUTABLE) that records its argv
and plays back what the test asks for, so that they check the mapping without a report run.
"""

import json
import os
import signal
import stat
import sys
import textwrap
import threading
import time
from pathlib import Path

import pytest

import lrchain

reproduce_module = sys.modules["lrchain.reproduce"]

# The fake lrchain: argv to $FAKE_DIR/argv.json; then the behaviour $FAKE_MODE asks for.
FAKE = textwrap.dedent("""\
    #!{python}
    import json, os, signal, sys, time
    folder = os.environ["FAKE_DIR"]
    with open(os.path.join(folder, "argv.json"), "w") as f:
        json.dump(sys.argv[1:], f)
    mode = os.environ.get("FAKE_MODE", "ok")
    def event(**e):
        print(json.dumps(e), file=sys.stderr, flush=True)
    out = os.path.join(folder, "report")
    summary = {{"report": os.path.join(out, "index.html"), "mode": "quick", "pass": 5, "deviates": 0,
               "erratum": 1, "unresolved": 0, "failed_steps": 0, "figures_missing": [], "seconds": 0.1,
               "steps": [{{"id": "a", "seconds": 0.1, "failed": False}}, {{"id": "b", "seconds": 0.1, "failed": False}}]}}
    if mode == "invalid":
        print("lrchain: invalid jobs: must be in [1, 64] (0: one per core)", file=sys.stderr)
        sys.exit(2)
    if mode == "usage":
        print("lrchain: --figure-format: gif is not png, svg or pdf", file=sys.stderr)
        sys.exit(2)
    if mode == "numerical":
        print("lrchain: numerical failure: Newton did not converge", file=sys.stderr)
        sys.exit(3)
    if mode == "wait_for_sigint":
        def stop(number, frame):
            open(os.path.join(folder, "got_sigint"), "w").close()
            print("lrchain: reproduce interrupted by SIGINT", file=sys.stderr, flush=True)
            sys.exit(130)
        signal.signal(signal.SIGINT, stop)
        event(event="start", steps=2, jobs=1, mode="quick", out=out + ".partial")
        open(os.path.join(folder, "started"), "w").close()
        time.sleep(60)
        sys.exit(0)
    event(event="start", steps=2, jobs=1, mode="quick", out=out + ".partial")
    print("a line of text that is not JSON", file=sys.stderr)
    for k, step in enumerate(["a", "b"], 1):
        event(event="step_started", step=step, title=step, seconds=0.0)
        event(event="step_finished", step=step, done=k, steps=2, seconds=0.1, step_seconds=0.1,
              failed=(mode == "failed" and step == "b"), error=None, **{{"pass": 1}})
    os.makedirs(out, exist_ok=True)
    for name in ("index.html", "a.json"):
        open(os.path.join(out, name), "w").close()
    if mode == "failed":
        summary["failed_steps"] = 1
    print(json.dumps(summary, indent=2))
    if mode == "failed":
        print("lrchain: error: 1 step(s) failed; see the report", file=sys.stderr)
        sys.exit(1)
    """)


@pytest.fixture
def fake(tmp_path, monkeypatch):
    """The fake lrchain as $LRCHAIN_EXECUTABLE; returns a function that reads its recorded argv."""
    exe = tmp_path / "lrchain"
    exe.write_text(FAKE.format(python=sys.executable))
    exe.chmod(exe.stat().st_mode | stat.S_IXUSR)
    monkeypatch.setenv("LRCHAIN_EXECUTABLE", str(exe))
    monkeypatch.setenv("FAKE_DIR", str(tmp_path))
    return lambda: json.loads((tmp_path / "argv.json").read_text())


def test_keywords_map_to_the_commands_options_one_word_each(fake, tmp_path):
    # a value starting with '-' stays a value: --out=VALUE is one argv word
    lrchain.reproduce("-odd name", quick=False, jobs=2, only=["exp1", "dark_solutions"], examples=tmp_path / "ex",
                      errata="errata.md", figure_format="svg", progress=False)
    assert fake() == ["reproduce", "--full", "--out=-odd name", "--jobs=2", "--only=exp1,dark_solutions",
                      f"--examples={tmp_path / 'ex'}", "--errata=errata.md", "--figure-format=svg", "--progress-json"]
    lrchain.reproduce("report", progress=False)  # None: the command's own defaults, not passed
    assert fake() == ["reproduce", "--quick", "--out=report", "--progress-json"]
    lrchain.reproduce("report", only="exp1", progress=False)
    assert "--only=exp1" in fake()


def test_bad_keywords_are_refused_before_anything_runs(fake, tmp_path):
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.reproduce("report", jobs=1.5, progress=False)
    assert err.value.parameter == "jobs"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.reproduce("report", only=["exp1", "a,b"], progress=False)
    assert err.value.parameter == "only"
    assert not (tmp_path / "argv.json").exists()


def test_the_result_holds_the_summary_and_the_files_written(fake, tmp_path):
    r = lrchain.reproduce("report", progress=False)
    assert r.out == tmp_path / "report" and r.report == tmp_path / "report" / "index.html"
    assert r.files == [tmp_path / "report" / "a.json", tmp_path / "report" / "index.html"]
    assert (r.summary["pass"], r.failed_steps, [s["id"] for s in r.steps]) == (5, 0, ["a", "b"])


def test_exit_codes_map_to_the_exceptions_of_lrchain_errors(fake, monkeypatch):
    monkeypatch.setenv("FAKE_MODE", "invalid")
    with pytest.raises(lrchain.InvalidParameterError, match=r"^invalid jobs: must be in \[1, 64\]") as err:
        lrchain.reproduce("report", progress=False)
    assert err.value.parameter == "jobs"
    monkeypatch.setenv("FAKE_MODE", "usage")
    with pytest.raises(lrchain.InputError, match="--figure-format: gif") as err:
        lrchain.reproduce("report", progress=False)
    assert not isinstance(err.value, lrchain.InvalidParameterError)
    monkeypatch.setenv("FAKE_MODE", "numerical")
    with pytest.raises(lrchain.NumericalFailure, match="Newton did not converge"):
        lrchain.reproduce("report", progress=False)
    monkeypatch.setenv("FAKE_MODE", "failed")
    with pytest.raises(lrchain.StepsFailed, match="1 step") as err:
        lrchain.reproduce("report", progress=False)
    assert err.value.result.failed_steps == 1 and err.value.result.report.name == "index.html"


def test_progress_lines_drive_a_bar_of_the_steps(fake, monkeypatch):
    seen = []

    class Recorder(reproduce_module.Counter):
        def start(self, total):
            seen.append(("start", total))

        def advance(self, text=None):
            seen.append(("advance", text))

    monkeypatch.setattr(reproduce_module, "Counter", Recorder)
    monkeypatch.setenv("FAKE_MODE", "failed")
    with pytest.raises(lrchain.StepsFailed) as err:
        lrchain.reproduce("report", progress=False)
    assert seen == [("start", 2), ("advance", "a done"), ("advance", "b FAILED")]
    # the last line of text (not the JSON lines, not earlier text) is the message
    assert str(err.value) == "lrchain: error: 1 step(s) failed; see the report"


def test_the_tqdm_bar_counts_the_steps(fake, capsys):
    pytest.importorskip("tqdm")
    lrchain.reproduce("report", progress=True)
    err = capsys.readouterr().err
    assert "reproduce: 100%" in err and "2/2" in err, err


def test_ctrl_c_is_passed_on_to_the_child_and_raises_after_it_ended(fake, tmp_path, monkeypatch):
    monkeypatch.setenv("FAKE_MODE", "wait_for_sigint")
    main = threading.main_thread().ident

    def interrupt_when_started():
        for _ in range(600):
            if (tmp_path / "started").exists():
                signal.pthread_kill(main, signal.SIGINT)  # as Ctrl-C in a notebook: this process only
                return
            time.sleep(0.05)

    threading.Thread(target=interrupt_when_started, daemon=True).start()
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt, match="interrupted by SIGINT"):
        lrchain.reproduce("report", progress=False)
    assert (tmp_path / "got_sigint").exists()  # the child received SIGINT and ended before the raise
    assert time.monotonic() - t0 < 30  # not the fake's 60 s sleep


def test_a_missing_executable_says_what_to_build(monkeypatch, tmp_path):
    monkeypatch.delenv("LRCHAIN_EXECUTABLE", raising=False)
    monkeypatch.setattr(reproduce_module, "_PACKAGE_EXECUTABLE", tmp_path / "bin" / "lrchain")
    with pytest.raises(FileNotFoundError, match="lrchain_python_executable"):
        lrchain.reproduce("report", progress=False)
    monkeypatch.setenv("LRCHAIN_EXECUTABLE", str(tmp_path / "nothing"))
    with pytest.raises(FileNotFoundError, match="LRCHAIN_EXECUTABLE="):
        lrchain.reproduce_executable()


def test_the_package_finds_the_build_trees_executable(monkeypatch):
    monkeypatch.delenv("LRCHAIN_EXECUTABLE", raising=False)
    exe = lrchain.reproduce_executable()
    assert exe == Path(lrchain.__file__).resolve().parent / "bin" / "lrchain"
    assert os.access(exe, os.X_OK)


def test_a_real_quick_step_writes_the_same_report_as_the_command(tmp_path, monkeypatch, cli):
    monkeypatch.delenv("LRCHAIN_EXECUTABLE", raising=False)
    monkeypatch.chdir(tmp_path)
    step = "coefficients"
    assert step in lrchain.reproduce_steps()
    seen = []

    class Recorder(reproduce_module.Counter):  # the real command's --progress-json lines
        def start(self, total):
            seen.append(("start", total))

        def advance(self, text=None):
            seen.append(("advance", text))

    monkeypatch.setattr(reproduce_module, "Counter", Recorder)
    r = lrchain.reproduce(tmp_path / "py", only=step, jobs=1, progress=False)
    assert seen == [("start", 1), ("advance", "coefficients done")]
    direct = cli("reproduce", "--quick", "--only", step, "--jobs", "1", "--out", tmp_path / "cli")
    assert r.failed_steps == 0 and r.report.is_file()
    assert r.summary["pass"] == direct["pass"] > 0  # the same comparisons as the command's own run
    assert sorted(p.relative_to(r.out) for p in r.files) == \
        sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*") if p.is_file())


def test_the_real_commands_refusal_names_the_keyword_and_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.delenv("LRCHAIN_EXECUTABLE", raising=False)
    with pytest.raises(lrchain.InvalidParameterError, match=r"^invalid jobs: ") as err:
        lrchain.reproduce(tmp_path / "r", jobs=99, progress=False)
    assert err.value.parameter == "jobs"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.reproduce(tmp_path / "r", only="no_such_step", progress=False)
    assert err.value.parameter == "only"
    assert list(tmp_path.iterdir()) == []
