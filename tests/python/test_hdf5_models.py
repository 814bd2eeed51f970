"""`--format hdf5` of the model-file runs and Python's to_hdf5() of the same results write the same
file through the same C++ writer (jobs/simulate/model_run_hdf5.hpp, jobs/model_dark_hdf5.hpp):
simulate bright --model, simulate ring, simulate --config with model = "FILE", dark
solve|floquet|continue --model. Each file is compared dataset by dataset and attribute by attribute
(the same run: the same bits), and its values are read back against the result's own arrays."""

import json
import math

import numpy as np
import pytest

import lrchain
from lrchain import _hdf5
from test_hdf5 import _assert_same_file as same_file

h5py = pytest.importorskip("h5py")

# Entries that differ between two runs of the same physics (timings, the commit each binary was
# built at, the command line) and the model object's lattice_code (how each front end found the lattice code: the CLI
# reports the seconds it took; the dark command reports no lattice_code): compared apart below.
_RUN_DEPENDENT = ("solve_seconds", "@date", "@command_line", "@cores", "@git_commit", "/summary/model/lattice_code",
                  "/@model")
# What only the CLI's summary has: where the files went, the config's run name.
_CLI_ONLY = ("/summary@out", "/summary@name", "/summary/model/lattice_code@seconds")


def _without_lattice_code(model_text):
    model = json.loads(model_text)
    model.pop("lattice_code", None)
    return model


def _assert_same_file(cli_file, python_file):
    """The two files hold the same datasets and attributes with equal values (the model object apart
    from its lattice_code); returns how many were compared."""
    with h5py.File(cli_file, "r") as a, h5py.File(python_file, "r") as b:
        assert _without_lattice_code(a.attrs["model"]) == _without_lattice_code(b.attrs["model"])
    return same_file(cli_file, python_file, _RUN_DEPENDENT, _CLI_ONLY, ("/summary/model/lattice_code",))


def _cli_hdf5(cli, tmp_path, *args):
    """Runs `lrchain ARGS --out DIR --format hdf5` and returns DIR/result.h5."""
    out = tmp_path / "cli"
    cli(*args, "--out", out, "--format", "hdf5")
    return out / "result.h5"


def _assert_provenance(path, model_name):
    with h5py.File(path, "r") as f:
        assert f.attrs["lrchain_version"] == _hdf5.version  # the version both were built as
        assert isinstance(f.attrs["git_commit"], str)
        model = json.loads(f.attrs["model"])
        assert model["name"] == model_name and model["file_hash"].startswith("0x") and "parameters" in model


@pytest.fixture(scope="module")
def fput():
    return lrchain.load_model("fput")


@pytest.fixture(scope="module")
def kg_defocusing():
    # klein_gordon with b = -1/2: defocusing at theta = pi (docs/dark-models.md: omega_b = 1.17).
    return lrchain.load_model("klein_gordon", b=-0.5)


def test_model_bright(tmp_path, cli, fput):
    cli_file = _cli_hdf5(cli, tmp_path, "simulate", "bright", "--model", "fput", "--branch", "acoustic", "--theta",
                         "pi/2", "--sites", "41", "--periods", "1", "--json")
    written = {p.name for p in cli_file.parent.iterdir()}
    assert written == {"result.h5", "summary.json"}  # no CSV, no figures
    r = lrchain.simulate.bright(model=fput, branch="acoustic", theta=math.pi / 2, sites=41, periods=1)
    r.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(cli_file, tmp_path / "python.h5") > 40
    _assert_provenance(cli_file, "fput")
    with h5py.File(tmp_path / "python.h5", "r") as f:  # read back against the result's arrays
        assert f.attrs["lrchain_result"] == "ModelBrightResult"
        for name in ("t", "energy", "centre"):
            assert np.array_equal(f[name][()], getattr(r, name))
        assert len(r.E) == 1 and np.array_equal(f["E_0"][()], r.E_x) and "E_1" not in f  # fput: one field
        assert "energy_density" not in f
        assert len(f["snapshots"]) == len(r.snapshots) == 1
        for column, values in r.snapshots[0].columns.items():
            assert np.array_equal(f["snapshots/0/columns"][column][()], values)
        assert f["summary"].attrs["max_E_x"] == r.summary["max_E_x"]


def test_model_bright_config(tmp_path, cli, source_dir):
    model_file = source_dir / "models" / "fput.toml"
    config = tmp_path / "fput.toml"
    config.write_text(f'experiment = "bright"\nname = "small"\nmodel = {json.dumps(str(model_file))}\n'
                      '[parameters]\nb = "1/2"\n[bright]\nbranch = "acoustic"\ntheta = "pi/2"\nsites = 41\nperiods = 1\n')
    cli_file = _cli_hdf5(cli, tmp_path, "simulate", "--config", config, "--json")
    r = lrchain.simulate.bright(model=lrchain.load_model(str(model_file), b=0.5), branch="acoustic", theta=math.pi / 2,
                                sites=41, periods=1)
    r.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(cli_file, tmp_path / "python.h5") > 40
    with h5py.File(cli_file, "r") as f:
        assert f["summary"].attrs["name"] == "small"
        assert f["summary/model/parameters"].attrs["b"] == 0.5


def test_ring(tmp_path, cli, fput):
    cli_file = _cli_hdf5(cli, tmp_path, "simulate", "ring", "--model", "fput", "--branch", "acoustic", "--theta",
                         "pi/2", "--periods", "20", "--packet-width", "8", "--json")
    assert {p.name for p in cli_file.parent.iterdir()} == {"result.h5", "summary.json"}
    r = lrchain.simulate.ring(fput, "acoustic", math.pi / 2, periods=20, packet_width=8)
    r.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(cli_file, tmp_path / "python.h5") > 20
    _assert_provenance(cli_file, "fput")
    with h5py.File(tmp_path / "python.h5", "r") as f:
        assert f.attrs["lrchain_result"] == "RingResult"
        for name in ("amplitude", "measured_frequency", "predicted_frequency", "measured_shift", "predicted_shift",
                     "relative_disagreement", "packet_t", "packet_centre"):
            assert np.array_equal(f[name][()], getattr(r, name), equal_nan=True), name
        assert f["summary/prediction"].attrs["h"] == r.summary["prediction"]["h"]


@pytest.mark.parametrize("command, python_run", [
    (["dark", "solve"], lambda kg: lrchain.dark.solve(model=kg, omega_b=1.17, sites=21)),
    (["dark", "floquet"], lambda kg: lrchain.dark.floquet(model=kg, omega_b=1.17, sites=21)),
    (["dark", "continue", "--points", "2", "--ds", "0.02"],
     lambda kg: lrchain.dark.continue_branch(model=kg, omega_b=1.17, sites=21, points=2, ds=0.02)),
])
def test_model_dark(tmp_path, cli, kg_defocusing, command, python_run):
    cli_file = _cli_hdf5(cli, tmp_path, *command, "--model", "klein_gordon", "--set", "b=-1/2", "--omega-b", "1.17",
                         "--sites", "21", "--quiet")
    assert (cli_file.parent / "profile.csv").exists() or (cli_file.parent / "branch.csv").exists()  # CSV as well
    r = python_run(kg_defocusing)
    r.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(cli_file, tmp_path / "python.h5") >= 15
    _assert_provenance(cli_file, "klein_gordon")
    with h5py.File(tmp_path / "python.h5", "r") as f:
        assert f.attrs["lrchain_result"] == type(r).__name__
        assert np.array_equal(f["z"][()], r.z) and np.array_equal(f["n"][()], r.n)
        assert json.loads(f.attrs["variables"]) == list(r.variables) == ["u0"]
        assert "lambda" not in f.attrs and r.lambda_ is None  # klein_gordon has no mean flow
        for name in ("theta", "omega_edge", "curvature", "h_tilde"):
            assert f.attrs[name] == getattr(r, name)
        assert "K_y" not in f["measures"].attrs and "K_y" not in f["measures"]  # one field: no second strain
        if isinstance(r, lrchain.dark.ModelBranch):
            assert np.array_equal(f["omega_b"][()], r.omega_b) and f["z"].shape == (2, 1, 21)
            assert np.array_equal(f["measures/norm_squared"][()], r.norm_squared)
            assert np.array_equal(f["floquet/max_modulus"][()], r.max_modulus)
            assert np.array_equal(f["floquet/multipliers"][()][1], r.floquet[1].multipliers)
        else:
            assert f.attrs["omega_b"] == r.omega_b and np.array_equal(f["seed"][()], r.seed)
            assert np.array_equal(f["newton_residuals"][()], r.newton_residuals)
            assert f["measures"].attrs["E_b"] == r.measures["E_b"]
            if r.floquet is not None:
                assert np.array_equal(f["floquet/multipliers"][()], r.floquet.multipliers)
                assert f["floquet"].attrs["kind"] == r.floquet.kind


@pytest.mark.parametrize("model_args, python_run", [
    ([], lambda kg: lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=2 * 2 * math.pi / 2.42)),
    (["--model", "klein_gordon", "--set", "b=-1/2"],
     lambda kg: lrchain.dark.evolve(model=kg, omega_b=1.17, sites=21, t_end=2 * 2 * math.pi / 1.17)),
])
def test_dark_evolve(tmp_path, cli, kg_defocusing, model_args, python_run):
    omega_b = 1.17 if model_args else 2.42
    cli_file = _cli_hdf5(cli, tmp_path, "dark", "evolve", *model_args, "--omega-b", omega_b, "--sites", "21",
                         "--t-end", repr(2 * 2 * math.pi / omega_b), "--quiet")
    r = python_run(kg_defocusing)
    r.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(cli_file, tmp_path / "python.h5") >= 8
    with h5py.File(tmp_path / "python.h5", "r") as f:
        assert f.attrs["lrchain_result"] == type(r).__name__ and f.attrs["period"] == r.period
        for name in ("t", "E_b", "C_x", "K_x", "position", "depth"):
            assert np.array_equal(f[name][()], getattr(r, name)), name
        if model_args:
            assert np.array_equal(f["z"][()], r.z) and f["z"].shape == (3, 1, 21)
        else:
            assert np.array_equal(f["x"][()], r.x) and np.array_equal(f["y"][()], r.y) and f["x"].shape == (3, 21)
