"""result.to_hdf5(path): round trips through h5py (Debian python3-h5py) for a bright-breather run and
a dark branch with profiles and Floquet spectra; bad destinations raise InputError, write nothing."""

import json

import numpy as np
import pytest

import lrchain

h5py = pytest.importorskip("h5py")


def test_bright_run_round_trip(tmp_path):
    r = lrchain.simulate.bright(lrchain.Params(), sites=81, periods=2, record_strains=True)
    path = tmp_path / "bright.h5"
    r.to_hdf5(path)
    assert [p.name for p in tmp_path.iterdir()] == ["bright.h5"]  # no temporary left behind
    with h5py.File(path, "r") as f:
        assert f.attrs["lrchain_result"] == "BrightResult"
        for name in ("t", "E_x", "E_y", "energy", "centre"):
            assert np.array_equal(f[name][()], getattr(r, name))
        density = f["energy_density"]
        assert density.attrs["quantity"] == r.energy_density.quantity
        assert density["values"].dtype == np.float32
        assert np.array_equal(density["values"][()], r.energy_density.values)
        assert np.array_equal(density["n"][()], r.energy_density.n)
        assert np.array_equal(f["x/values"][()], r.x.values) and np.array_equal(f["y/t"][()], r.y.t)
        assert f["summary"].attrs["max_E_x"] == r.summary["max_E_x"]
        assert len(f["snapshots"]) == len(r.snapshots)
        first = f["snapshots/0"]
        assert first.attrs["t"] == r.snapshots[0].t
        for column, values in r.snapshots[0].columns.items():
            assert np.array_equal(first["columns"][column][()], values)


def test_dark_branch_with_floquet_round_trip(tmp_path):
    b = lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, points=2, ds=0.05, floquet=True)
    path = tmp_path / "branch.h5"
    b.to_hdf5(path)
    with h5py.File(path, "r") as f:
        assert f.attrs["lrchain_result"] == "Branch" and f.attrs["stop_reason"] == b.stop_reason
        assert np.array_equal(f["omega_b"][()], b.omega_b)
        assert np.array_equal(f["x"][()], b.x) and f["y"].shape == (2, 101)
        assert np.array_equal(f["measures/norm_squared"][()], b.norm_squared)
        multipliers = f["floquet/multipliers"][()]  # h5py reads the {r, i} compound as complex
        assert multipliers.dtype == np.complex128 and multipliers.shape == (2, 4 * 101)
        assert np.array_equal(multipliers[1], b.floquet[1].multipliers)
        assert np.array_equal(f["floquet/max_modulus"][()], b.max_modulus)
        assert json.loads(f["floquet"].attrs["kind"]) == b.kind


def test_dark_solution_round_trip(tmp_path):
    s = lrchain.dark.floquet(lrchain.Params(), omega_b=2.42, sites=21)
    s.to_hdf5(tmp_path / "solution.h5")
    with h5py.File(tmp_path / "solution.h5", "r") as f:
        assert f.attrs["omega_b"] == 2.42
        assert np.array_equal(f["x"][()], s.x) and np.array_equal(f["newton_residuals"][()], s.newton_residuals)
        assert np.array_equal(f["floquet/multipliers"][()], s.floquet.multipliers)
        assert f["floquet"].attrs["pairing_defect"] == s.floquet.pairing_defect
        assert f["measures"].attrs["E_b"] == s.measures["E_b"]


def test_bad_destination_raises_and_writes_nothing(tmp_path):
    s = lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=21)
    with pytest.raises(lrchain.InputError, match="does not exist"):
        s.to_hdf5(tmp_path / "missing" / "s.h5")
    with pytest.raises(lrchain.InputError, match="is a directory"):
        s.to_hdf5(tmp_path)
    assert list(tmp_path.iterdir()) == []


def _hdf5_items(path):
    """{'/path': array} for datasets and {'/path@name': value} for attributes of an HDF5 file."""
    items = {}

    def visit(name, obj):
        key = "/" + name
        for attr, value in obj.attrs.items():
            items[f"{key}@{attr}"] = value
        if isinstance(obj, h5py.Dataset):
            items[key] = obj[()]

    with h5py.File(path, "r") as f:
        for attr, value in f.attrs.items():
            items[f"/@{attr}"] = value
        f.visititems(visit)
    return items


# Entries that differ between two runs of the same physics: timings, the date, the command line,
# the commit each binary was built at (the CLI and the module may be rebuilt at different times),
# the checkpoints (the CLI writes them to --out), and the CLI's own report keys (where the files
# went), which a Python run does not have.
_RUN_DEPENDENT = ("solve_seconds", "probe_seconds", "@date", "@command_line", "@cores", "checkpoint", "@git_commit")
_CLI_ONLY = ("/summary@out", "/summary@checkpoint_file", "/summary@checkpoints_written", "/summary@t_start",
             "/summary@figures")


def _assert_same_file(cli_file, python_file, run_dependent=_RUN_DEPENDENT, cli_only=_CLI_ONLY, python_only=()):
    """Equal datasets and attributes but those whose key contains one of `run_dependent`, the
    attributes in `cli_only` (CLI file only) and those starting with one of `python_only`."""
    a, b = _hdf5_items(cli_file), _hdf5_items(python_file)
    datasets_a = {k for k in a if "@" not in k}
    datasets_b = {k for k in b if "@" not in k}
    assert datasets_a == datasets_b
    assert {k for k in set(b) - set(a) if not k.startswith(tuple(python_only) or ("\0",))} == set()
    assert {k for k in set(a) - set(b) if k not in cli_only} == set()
    compared = 0
    for key in b:
        if any(s in key for s in run_dependent):
            continue
        x, y = np.asarray(a[key]), np.asarray(b[key])
        assert x.dtype == y.dtype and x.shape == y.shape, key
        assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), key  # the same run: the same bits
        compared += 1
    return compared


@pytest.mark.parametrize("kind, cli_args, python_run", [
    ("bright", ["--branch", "optical", "--theta", "pi/2", "--sites", "81", "--periods", "2", "--stepper", "rkf78"],
     lambda: lrchain.simulate.bright(lrchain.Params(), "optical", np.pi / 2, sites=81, periods=2, stepper="rkf78")),
    ("drive", ["--sites", "50", "--t-end", "4", "--switch-off-time", "2", "--sample-every", "1", "--spacetime-every", "2",
               "--snapshots", "2", "4", "--front-fit-start", "0", "--front-fit-end", "4"],
     lambda: lrchain.simulate.drive(sites=50, t_end=4, switch_off_time=2, sample_every=1, spacetime_every=2,
                                    snapshot_times=[2, 4], front_fit_start=0, front_fit_end=4)),
    ("modulated", ["--sites", "21", "--theta-waves", "13", "--t-end", "4", "--sample-every", "1", "--snapshots", "0", "4",
                   "--speed-fit-start", "0", "--speed-fit-end", "4"],
     lambda: lrchain.simulate.modulated(sites=21, theta_waves=13, t_end=4, sample_every=1, snapshot_times=[0, 4],
                                        speed_fit_start=0, speed_fit_end=4)),
])
def test_cli_hdf5_equals_python_to_hdf5(tmp_path, cli, kind, cli_args, python_run):
    """`lrchain simulate KIND --format hdf5` and Python's to_hdf5() of the same run write the same
    datasets and attributes with the same values (one writer in the C++ library serves both)."""
    cli("simulate", kind, *cli_args, "--out", tmp_path / "cli", "--format", "hdf5", "--json")
    written = {p.name for p in (tmp_path / "cli").iterdir()}
    assert {"result.h5", "summary.json"} <= written  # the data in result.h5: no CSV, no float32 files
    assert not [name for name in written if name.endswith((".csv", "spacetime.bin", ".gp", ".png"))]
    python_run().to_hdf5(tmp_path / "python.h5")
    compared = _assert_same_file(tmp_path / "cli" / "result.h5", tmp_path / "python.h5")
    assert compared > 20  # the series, fields, snapshots, summary and provenance were compared
    with h5py.File(tmp_path / "cli" / "result.h5", "r") as f:  # provenance attributes a reader relies on
        summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
        assert f.attrs["lrchain_version"] == summary["provenance"]["lrchain_version"]
        assert f.attrs["git_commit"] == (summary["provenance"]["git_commit"] or "unknown")
        # The root attribute "model" is the summary's model object as JSON text.
        assert json.loads(f.attrs["model"]) == summary["model"]
        assert summary["model"]["name"] == "resonant_chain"
        assert f["summary/model/parameters"].attrs["rho"] == summary["model"]["parameters"]["rho"]
        assert "parameters" not in f.attrs and "params" not in f["summary"]
        assert f["energy_density/values"].dtype == np.float32


@pytest.mark.parametrize("command, python_run", [
    (["dark", "solve"], lambda: lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=21)),
    (["dark", "floquet"], lambda: lrchain.dark.floquet(lrchain.Params(), omega_b=2.42, sites=21)),
    (["dark", "continue", "--points", "2", "--ds", "0.05"],
     lambda: lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=21, points=2, ds=0.05)),
])
def test_cli_dark_hdf5_equals_python_to_hdf5(tmp_path, cli, command, python_run):
    """`lrchain dark solve|floquet|continue --format hdf5` and Python's to_hdf5() of the same
    computation write the same datasets and attributes with the same values (one writer in C++)."""
    cli(*command, "--omega-b", "2.42", "--sites", "21", "--quiet", "--out", tmp_path / "cli", "--format", "hdf5")
    python_run().to_hdf5(tmp_path / "python.h5")
    compared = _assert_same_file(tmp_path / "cli" / "result.h5", tmp_path / "python.h5")
    assert compared >= 12
    with h5py.File(tmp_path / "cli" / "result.h5", "r") as f:
        model = json.loads(f.attrs["model"])
        assert model["name"] == "resonant_chain" and model["file_hash"].startswith("0x")
        assert model["parameters"] == {"alpha": 1.5, "delta0": 4 / 9, "kappa": 1.0, "rho": 1 / 3}
        assert "parameters" not in f.attrs
        if "floquet" in f:
            assert f["floquet/multipliers"].dtype == np.complex128
