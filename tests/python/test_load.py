"""lrchain.load(path): every HDF5 result class read back from its file equals the result that wrote it
(every array bit for bit), and writing the loaded result again gives the same file; the CLI's --out
folder, its summary.json and a sweep's results file load too; anything else raises InputError
naming the file."""

import dataclasses
import math

import numpy as np
import pytest

import lrchain

h5py = pytest.importorskip("h5py")
from test_hdf5 import _assert_same_file  # noqa: E402  (the CLI/Python file comparison)

P = lrchain.Params()


def _runs():
    """One small run per result class that has to_hdf5 (the sizes of test_hdf5*.py)."""
    fput = lambda: lrchain.load_model("fput")  # noqa: E731
    kg = lambda: lrchain.load_model("klein_gordon", b=-0.5)  # noqa: E731  defocusing at pi: omega_b 1.17
    return {
        "bright": lambda: lrchain.simulate.bright(P, sites=41, periods=1, record_strains=True, progress=False),
        "drive": lambda: lrchain.simulate.drive(sites=50, t_end=4, switch_off_time=2, sample_every=1,
                                                spacetime_every=2, record_displacements=True, progress=False),
        "modulated": lambda: lrchain.simulate.modulated(sites=21, theta_waves=13, t_end=4, sample_every=1,
                                                        snapshot_times=[0, 4], progress=False),
        "model_bright": lambda: lrchain.simulate.bright(model=fput(), branch="acoustic", theta=math.pi / 2, sites=41,
                                                        periods=1, progress=False),
        "ring": lambda: lrchain.simulate.ring(fput(), "acoustic", math.pi / 2, periods=20, packet_width=8),
        "dark_floquet": lambda: lrchain.dark.floquet(P, omega_b=2.42, sites=11),
        "dark_branch": lambda: lrchain.dark.continue_branch(P, omega_b=2.42, sites=11, points=2, ds=0.05,
                                                            floquet=True, progress=False),
        "dark_branch_plain": lambda: lrchain.dark.continue_branch(P, omega_b=2.42, sites=11, points=2, ds=0.05,
                                                                  progress=False),
        "dark_evolution": lambda: lrchain.dark.evolve(P, omega_b=2.42, sites=11, t_end=2 * 2 * math.pi / 2.42),
        "model_dark_floquet": lambda: lrchain.dark.floquet(model=kg(), omega_b=1.17, sites=21),
        "model_dark_branch": lambda: lrchain.dark.continue_branch(model=kg(), omega_b=1.17, sites=21, points=2,
                                                                  ds=0.02, floquet=True, progress=False),
        "model_dark_evolution": lambda: lrchain.dark.evolve(model=kg(), omega_b=1.17, sites=21,
                                                            t_end=2 * 2 * math.pi / 1.17),
        # theta of any shape; a scalar theta; a model without mean flow (lambda NaN) at a resonance-free edge
        "coefficients": lambda: lrchain.coefficients(P, "optical", np.linspace(0.1, 3.1, 12).reshape(3, 4)),
        "coefficients_scalar": lambda: lrchain.coefficients(P, "acoustic", 1.0),
        "coefficients_model": lambda: lrchain.coefficients(lrchain.load_model("klein_gordon"), "branch0",
                                                           np.linspace(-3, 3, 5)),
        "intervals": lambda: lrchain.regime.intervals(P, "acoustic"),
        "intervals_model": lambda: lrchain.regime.intervals(fput(), "acoustic"),
        "regime_map": lambda: lrchain.regime.theta_rho_map(P, "optical", rho=(0.1, 5, 20), theta=(0.1, 3, 15)),
        "boundary_curve": lambda: lrchain.regime.boundary_curves(P, "optical", lo=0.1, hi=2)[0],
        "bright_floquet": lambda: lrchain.bright.floquet(lrchain.load_model("fput", a=0), omega_b=2.2, center="bond",
                                                         sites=41),
        "bright_branch": lambda: lrchain.bright.continue_branch(lrchain.load_model("klein_gordon"), omega_b=1.19,
                                                                sites=81, points=3),
        "wave": lambda: lrchain.wave.stability(fput(), theta=2.5, amplitude=0.02, k_points=10),
        "wave_branch": lambda: lrchain.wave.continue_branch(fput(), theta=2.5, amplitudes=[0.05, 0.1]),
        "standing": lambda: lrchain.wave.standing(fput(), theta=2 * math.pi / 5, amplitude=0.02, ring_sites=10),
    }


def _assert_equal(a, b, where):
    """Equal values: arrays bit for bit (NaN where NaN), dataclasses field by field, containers by item."""
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), where
        for f in dataclasses.fields(a):
            if f.name == "source":  # Coefficients: the Params/Model evaluated, or the model read from the file
                _assert_equal(a.model, b.model, f"{where}.model")
            elif f.name != "summary" or type(a).__name__ in ("BrightBreather", "TravellingWave", "WaveBranch",
                                                                      "StandingWave"):
                # a bright breather's and a wave's summary is exact JSON text in its file; the others' summary
                # tree drops nulls, reads booleans as 0/1: compared by file
                _assert_equal(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif isinstance(a, dict):
        assert list(a) == list(b) if where.endswith("measures") else sorted(a) == sorted(b), where
        for k in a:
            _assert_equal(a[k], b[k], f"{where}[{k}]")
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _assert_equal(x, y, f"{where}[{i}]")
    elif isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        x, y = np.asarray(a), np.asarray(b)
        assert x.dtype == y.dtype and x.shape == y.shape, where
        assert np.array_equal(x, y, equal_nan=x.dtype.kind in "fc"), where
    elif isinstance(a, lrchain.Params):
        assert (a.alpha, a.delta0, a.kappa, a.rho) == (b.alpha, b.delta0, b.kappa, b.rho), where
    else:
        assert a == b or (a != a and b != b), f"{where}: {a!r} != {b!r}"


def test_every_result_class_round_trips(tmp_path):
    classes = set()
    for name, run in _runs().items():
        r = run()
        first, second = tmp_path / f"{name}.h5", tmp_path / f"{name}_again.h5"
        r.to_hdf5(first)
        loaded = lrchain.load(first)
        _assert_equal(r, loaded, name)
        loaded.to_hdf5(second)  # the summary tree too: writing the loaded result gives the same file
        assert _assert_same_file(first, second) >= 5, name
        classes.add(type(r).__name__)
    # every class lrchain.load reads is covered (the writers' lrchain_result names)
    assert classes == {"BrightResult", "DriveResult", "ModulatedResult", "ModelBrightResult", "RingResult",
                       "DarkSolution", "Branch", "Evolution", "ModelDarkSolution", "ModelBranch", "ModelEvolution",
                       "Coefficients", "Intervals", "RegimeMap", "BoundaryCurve", "BrightBreather", "BrightBranch",
                       "TravellingWave", "WaveBranch", "StandingWave"}


def test_cli_out_folder_summary_and_sweep(tmp_path, cli, source_dir):
    out = tmp_path / "run"
    printed = cli("simulate", "bright", "--branch", "optical", "--theta", repr(math.pi / 2), "--sites", "41",
                  "--periods", "1", "--out", str(out), "--format", "hdf5")
    run = lrchain.load(out)  # the folder: its result.h5
    assert isinstance(run, lrchain.simulate.BrightResult)
    direct = lrchain.simulate.bright(P, "optical", math.pi / 2, sites=41, periods=1, progress=False)
    np.testing.assert_array_equal(run.E_x, direct.E_x)  # the same job: the same bits
    np.testing.assert_array_equal(run.energy_density.values, direct.energy_density.values)
    assert run.summary["max_E_x"] == direct.summary["max_E_x"]
    summary = lrchain.load(out / "summary.json")  # the command's JSON summary, as a dict
    assert isinstance(summary, dict) and summary["max_E_x"] == printed["max_E_x"] == direct.summary["max_E_x"]
    sweep = tmp_path / "s.toml"
    base = source_dir / "examples" / "sweeps" / "base" / "regime_intervals.toml"
    sweep.write_text(f'job = "regime intervals"\nbase = "{base}"\noutput = "{tmp_path / "sweep" / "out.h5"}"\n'
                     '[[axis]]\nparameter = "model.rho"\nvalues = [0.2, 1.0]\n')
    cli("sweep", "--config", str(sweep), "--threads", "1", "--quiet")
    ds = lrchain.load(tmp_path / "sweep")  # the folder's one sweep file, as open_sweep reads it
    assert ds.attrs["lrchain_result"] == "sweep" and ds["model.rho"].values.tolist() == [0.2, 1.0]


def test_other_files_raise_input_error_naming_them(tmp_path):
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f["x"] = [1.0]
    (tmp_path / "table.csv").write_text("a,b\n1,2\n")
    (tmp_path / "bad.json").write_text("{")
    for name, match in (("other.h5", "not an lrchain result"), ("table.csv", "neither an HDF5 file"),
                        ("bad.json", "not valid JSON"), ("missing.h5", "does not exist")):
        with pytest.raises(lrchain.InputError, match=match) as e:
            lrchain.load(tmp_path / name)
        assert name in str(e.value)
    with pytest.raises(lrchain.InputError, match="no result.h5 and 2 .h5 files"):
        (tmp_path / "second.h5").write_bytes((tmp_path / "other.h5").read_bytes())
        lrchain.load(tmp_path)
