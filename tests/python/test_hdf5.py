"""result.to_hdf5(path): round trips through h5py (Debian python3-h5py) for a bright-breather run and
a dark branch with profiles and Floquet spectra; bad destinations raise InputError, write nothing."""

import json

import numpy as np
import pytest

import lrchain

h5py = pytest.importorskip("h5py")


def test_bright_run_round_trip(tmp_path):
    r = lrchain.simulate.bright(lrchain.Params(), N=40, periods=2, record_strains=True)
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
