"""scripts/compare_outputs.py, the before/after comparer of issue 26, checked on small synthetic trees.

The trees imitate what `compare_outputs.py run` writes (manifest.json, DIR/<case>/case.json,
stdout.json, out/...), with JSON keys as lrchain writes them (provenance, wall_seconds, lattice_code).
"""

import copy
import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import numpy as np

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "compare_outputs.py"

SUMMARY = {
    "experiment": "ring",
    "out": "{RUN}/ring/out",
    "amplitudes": [{"amplitude": 0.02, "measured_frequency": 1.6179534898196326}],
    "model": {"name": "diatomic_chain",
              "lattice_code": {"compiled_in": False, "from_cache": False, "library": "{RUN}/.cache/x.so", "seconds": 0.5}},
    "packet": {"duration": 1736.6563145999496, "measured_speed": -0.13859471678351556},
    "wall_seconds": 0.8,
    "provenance": {"date": "2026-11-27T23:38:43Z", "git_commit": "fa837c4a7506", "command_line": ["lrchain"]},
}
CSV = "t,E\n0,1.0\n0.5,0.99999999\n"
SWEEP_CSV = "point,theta,max_Ex,wall_seconds\n0,0.15,0.031,1.25\n"
HTML = ("<p>Produced by <code>lrchain reproduce --quick</code> in 88.8 s. Every number</p>\n"
        "<tr><td>date (UTC)</td><td>2026-11-27T23:38:43Z</td></tr>\n<p class=\"muted\">Step time: 0.4 s</p>\n"
        "<td class=\"num\">72</td>\n")


STDERR = "[ 1/2]    8.2 s  dark_acoustic_bond   done in 8.2 s: 0 pass\n[ 2/2]    1.8 s  exp1   done in 1.8 s: 5 pass\n"


def write_tree(root, date="2026-11-27T23:38:43Z", seconds=0.8, summary=None, csv=CSV, html=HTML, exit_code=0,
               stderr=STDERR, argv=("simulate", "--out", "{OUT}"), stdout_text=None):
    """A run directory with one case, 'ring', as `compare_outputs.py run` lays it out."""
    run = root.resolve()
    case = run / "ring"
    (case / "out").mkdir(parents=True)
    (run / "manifest.json").write_text(json.dumps({"run_dir": str(run), "source": "/src", "cases": ["ring"]}))
    (case / "case.json").write_text(json.dumps({"name": "ring", "argv": list(argv),
                                                "quick_changes": [], "exit_code": exit_code, "seconds": seconds}))
    s = copy.deepcopy(summary or SUMMARY)
    s["provenance"]["date"], s["wall_seconds"] = date, seconds
    text = json.dumps(s, indent=2).replace("{RUN}", str(run))
    (case / "stdout.json").write_text(text)
    (case / "out" / "summary.json").write_text(text)
    (case / "out" / "series.csv").write_text(csv)
    (case / "out" / "results.csv").write_text(SWEEP_CSV.replace("1.25", str(seconds)))
    (case / "out" / "index.html").write_text(html.replace("88.8", str(seconds)))
    (case / "out" / ".results.h5.lrchain-files").write_text(json.dumps(
        {"files": {"results.csv": f"{hash(seconds) & 0xffff:064x}"}, "kind": "lrchain sweep side files", "results": "results.h5"}))
    (case / "stderr.txt").write_text(stderr)
    if stdout_text is not None:
        (case / "stdout.txt").write_text(stdout_text)
    return run


def compare(before, after):
    return subprocess.run([sys.executable, str(SCRIPT), "compare", str(before), str(after)],
                          capture_output=True, text=True, check=False)


def differing(tmp_path, **after_changes):
    """stdout of compare on a default tree and one made with AFTER_CHANGES, which must differ (exit 1)."""
    done = compare(write_tree(tmp_path / "before"), write_tree(tmp_path / "after", **after_changes))
    assert done.returncode == 1, done.stdout + done.stderr
    return done.stdout


def test_identical_apart_from_provenance_timing_and_paths(tmp_path):
    # Different run directories, dates, wall times, cache state: all of it provenance, timing or place.
    before = write_tree(tmp_path / "before")
    other = copy.deepcopy(SUMMARY)
    other["model"]["lattice_code"]["from_cache"] = True
    after = write_tree(tmp_path / "after", date="2027-01-01T00:00:00Z", seconds=12.5, summary=other)
    done = compare(before, after)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.startswith("0 differences in 1 cases"), done.stdout


def test_stderr_progress_times_and_order_ignored_messages_compared(tmp_path):
    # reproduce's progress: steps finish in any order with --jobs 2, each with its time (cli/src/reproduce_command.cpp).
    reordered = "[ 1/2]    1.7 s  exp1   done in 1.7 s: 5 pass\n[ 2/2]    9.7 s  dark_acoustic_bond   done in 9.7 s: 0 pass\n"
    assert compare(write_tree(tmp_path / "a"), write_tree(tmp_path / "b", stderr=reordered)).returncode == 0
    out = differing(tmp_path, stderr=reordered.replace("5 pass", "4 pass"))
    assert "DIFF ring/stderr.txt:" in out, out


def test_derive_text_reported_as_unstable_not_failing(tmp_path):
    # Two runs of one build printed these two lines (`lrchain derive --model models/klein_gordon.toml`).
    argv = ("derive", "--model", "models/klein_gordon.toml")
    before = write_tree(tmp_path / "before", argv=argv, stdout_text="det L_1 = D1*C+w0^2-omega^2 = 0\n")
    after = write_tree(tmp_path / "after", argv=argv, stdout_text="det L_1 = w0^2+C*D1-omega^2 = 0\n")
    done = compare(before, after)
    assert done.returncode == 0, done.stdout
    assert "UNSTABLE ring/stdout.txt" in done.stdout and "1 differences in outputs known to vary" in done.stdout


def test_one_csv_byte_changed(tmp_path):
    out = differing(tmp_path, csv=CSV.replace("0.99999999", "0.99999998"))
    assert "DIFF ring/out/series.csv: line 3: '0.5,0.99999999' != '0.5,0.99999998'" in out, out
    assert out.count("DIFF ") == 1, out


def test_json_physics_number_changed_by_one_ulp(tmp_path):
    # 1.6179534898196326 and the next double up (math.nextafter): bit for bit, not within a tolerance.
    changed = copy.deepcopy(SUMMARY)
    changed["amplitudes"][0]["measured_frequency"] = 1.6179534898196328
    out = differing(tmp_path, summary=changed)
    for name in ("stdout.json", "out/summary.json"):
        assert (f"DIFF ring/{name}: at $.amplitudes[0].measured_frequency: 1.6179534898196326 != 1.6179534898196328"
                in out), out
    assert "2 differences" in out


def test_physics_named_like_timing_is_compared(tmp_path):
    # The ring's packet "duration" is physics (sim/src/ring_outputs.cpp), not a wall time.
    changed = copy.deepcopy(SUMMARY)
    changed["packet"]["duration"] = 1736.0
    out = differing(tmp_path, summary=changed)
    assert "at $.packet.duration: 1736.6563145999496 != 1736.0" in out, out


def test_report_html_number_and_exit_code_compared(tmp_path):
    out = differing(tmp_path, html=HTML.replace(">72<", ">71<"), exit_code=3)
    assert "DIFF ring/case.json: exit_code: 0 != 3" in out, out
    assert "DIFF ring/out/index.html: line 4:" in out, out


def test_missing_file_and_case(tmp_path):
    before = write_tree(tmp_path / "before")
    after = write_tree(tmp_path / "after")
    (after / "ring" / "out" / "series.csv").unlink()
    (before / "extra").mkdir()
    (before / "extra" / "case.json").write_text(json.dumps({"name": "extra", "argv": [], "exit_code": 0}))
    done = compare(before, after)
    assert done.returncode == 1
    assert "DIFF ring/out/series.csv: only in BEFORE" in done.stdout, done.stdout
    assert "DIFF extra: case only in BEFORE" in done.stdout, done.stdout


def test_bad_usage_exit_2_one_line(tmp_path):
    before = write_tree(tmp_path / "before")
    done = compare(before, tmp_path / "nothing")
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and "no manifest.json" in done.stderr, done.stderr
    done = subprocess.run([sys.executable, str(SCRIPT), "run", "--out", str(tmp_path / "x")],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "--lrchain" in done.stderr, done.stderr
    assert not (tmp_path / "x").exists()


def load_script():
    spec = importlib.util.spec_from_file_location("compare_outputs", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_doc_command_lines_extracted_and_skipped(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "models").mkdir()
    (tmp_path / "models" / "fput.toml").write_text("")
    (tmp_path / "README.md").write_text(
        "```sh\nlrchain coeffs --theta pi/2 --json   # a comment\n"
        "lrchain derive --model models/fput.toml\n"
        "lrchain derive --model my_chain.toml\n"
        "mpirun -n 4 lrchain sweep --config s.toml\n"
        "lrchain regime map --out DIR [--nx 600]\n```\n"
        "lrchain coeffs --outside-a-block\n"
        "```python\nimport lrchain\n```\n"
        "```\nlrchain: an error message, 'quoted\n```\n")
    cases, skipped = load_script().doc_cases(tmp_path)
    assert [c["argv"] for c in cases] == [["coeffs", "--theta", "pi/2", "--json"], ["derive", "--model", "models/fput.toml"]]
    assert [(s["origin"], s["reason"]) for s in skipped] == [
        ("README.md:4", "needs the file my_chain.toml, which does not exist in the source tree"),
        ("README.md:5", "not a plain lrchain command line (starts with mpirun)"),
        ("README.md:6", "a synopsis with placeholders or optional parts"),
    ]


def write_npz(path, values):
    """An .npz of one float64 array E_x, as `compare_outputs.py python-results` writes them."""
    np.savez(path, E_x=np.asarray(values, dtype=np.float64))


def test_npz_compared_bit_for_bit(tmp_path):
    before, after = write_tree(tmp_path / "before"), write_tree(tmp_path / "after")
    write_npz(before / "ring" / "out" / "results.npz", [0.5, 0.25, 1e-3])
    write_npz(after / "ring" / "out" / "results.npz", [0.5, 0.25, 1e-3])
    assert compare(before, after).returncode == 0
    write_npz(after / "ring" / "out" / "results.npz", [0.5, 0.25, np.nextafter(1e-3, 1)])
    done = compare(before, after)
    assert done.returncode == 1
    assert "DIFF ring/out/results.npz: E_x: element 2 (flat) differs, dtype <f8" in done.stdout, done.stdout
