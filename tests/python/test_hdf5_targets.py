"""result.to_hdf5(path) for every result type: the model-file results write (ModelDarkSolution had no
to_hdf5 although docs/dark-breathers.md promises Python's to_hdf5 for every dark computation) and read
back with h5py; and no result renames over a target that exists and is not a regular file (a FIFO, a
directory): InputError naming it, the target left as it was, no temporary file left behind. Before,
the temporary file was renamed over a FIFO (as root, over /dev/null)."""

import json
import math
import os
import stat

import numpy as np
import pytest

import lrchain

h5py = pytest.importorskip("h5py")


@pytest.fixture(scope="module")
def kg_defocusing():
    # klein_gordon with b = -1/2: defocusing at theta = pi (docs/dark-models.md: omega_b = 1.17).
    return lrchain.load_model("klein_gordon", b=-0.5)


@pytest.fixture(scope="module")
def model_solution(kg_defocusing):
    return lrchain.dark.floquet(model=kg_defocusing, omega_b=1.17, sites=21)


def test_model_dark_solution_round_trip(tmp_path, model_solution):
    s = model_solution
    path = tmp_path / "solution.h5"
    s.to_hdf5(path)
    assert [p.name for p in tmp_path.iterdir()] == ["solution.h5"]
    with h5py.File(path, "r") as f:
        assert f.attrs["lrchain_result"] == "ModelDarkSolution"
        for name in ("omega_b", "omega_edge", "theta", "curvature", "h_tilde"):
            assert f.attrs[name] == getattr(s, name)
        assert "lambda" not in f.attrs and s.lambda_ is None  # klein_gordon has no mean flow
        assert f.attrs["branch"] == s.branch and f.attrs["lattice_form"] == s.lattice_form
        assert json.loads(f.attrs["variables"]) == list(s.variables) == ["u0"]
        assert json.loads(f.attrs["model"]) == s.model  # JSON text, as the dark files' root attribute
        assert json.loads(f.attrs["model"])["parameters"]["b"] == -0.5
        assert np.array_equal(f["z"][()], s.z) and f["z"].shape == (1, 21)
        assert np.array_equal(f["seed"][()], s.seed) and np.array_equal(f["n"][()], s.n)
        assert np.array_equal(f["newton_residuals"][()], s.newton_residuals)
        for key, value in s.measures.items():
            if value is None:  # K_y, C_y of a one-field model
                assert key not in f["measures"].attrs
            else:
                assert f["measures"].attrs[key] == value
        multipliers = f["floquet/multipliers"][()]
        assert multipliers.dtype == np.complex128 and np.array_equal(multipliers, s.floquet.multipliers)
        assert f["floquet"].attrs["max_modulus"] == s.floquet.max_modulus
        assert f["floquet"].attrs["kind"] == s.floquet.kind


def test_model_branch_and_evolution_round_trip(tmp_path, kg_defocusing):
    b = lrchain.dark.continue_branch(model=kg_defocusing, omega_b=1.17, sites=21, points=2, ds=0.02, floquet=False)
    b.to_hdf5(tmp_path / "branch.h5")
    with h5py.File(tmp_path / "branch.h5", "r") as f:
        assert f.attrs["lrchain_result"] == "ModelBranch" and f.attrs["stop_reason"] == b.stop_reason
        assert np.array_equal(f["omega_b"][()], b.omega_b) and np.array_equal(f["z"][()], b.z)
        assert f["measures/norm_squared"][1] == b.measures[1]["norm_squared"]  # one dataset per measure
    e = lrchain.dark.evolve(model=kg_defocusing, omega_b=1.17, sites=21, t_end=3 * 2 * math.pi / 1.17)
    e.to_hdf5(tmp_path / "evolution.h5")
    with h5py.File(tmp_path / "evolution.h5", "r") as f:
        assert f.attrs["lrchain_result"] == "ModelEvolution" and f.attrs["period"] == e.period
        assert np.array_equal(f["E_b"][()], e.E_b) and np.array_equal(f["z"][()], e.z)


def test_ring_result_round_trip(tmp_path):
    r = lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", math.pi / 2, periods=20, packet_width=8)
    r.to_hdf5(tmp_path / "ring.h5")
    with h5py.File(tmp_path / "ring.h5", "r") as f:
        assert f.attrs["lrchain_result"] == "RingResult"
        assert np.array_equal(f["measured_frequency"][()], r.measured_frequency)
        assert np.array_equal(f["packet_centre"][()], r.packet_centre)


# One cheap result of every type that has to_hdf5.
RESULTS = {
    "DarkSolution": lambda kg: lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=21),
    "Branch": lambda kg: lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=21, points=1,
                                                      floquet=False),
    "Evolution": lambda kg: lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=2 * 2 * math.pi / 2.42),
    "BrightResult": lambda kg: lrchain.simulate.bright(lrchain.Params(), sites=41, periods=1),
    "DriveResult": lambda kg: lrchain.simulate.drive(sites=20, t_end=20, switch_off_time=10, sample_every=1,
                                                     spacetime_every=2, snapshot_times=[20], front_fit_start=1,
                                                     front_fit_end=20),
    "ModulatedResult": lambda kg: lrchain.simulate.modulated(sites=40, theta_waves=25, t_end=20, sample_every=10,
                                                             snapshot_times=[0], speed_fit_start=0,
                                                             speed_fit_end=20),
    "ModelDarkSolution": lambda kg: lrchain.dark.solve(model=kg, omega_b=1.17, sites=21),
    "ModelBrightResult": lambda kg: lrchain.simulate.bright(model=lrchain.load_model("fput"), branch="acoustic",
                                                            theta=math.pi / 2, sites=41, periods=1),
}


@pytest.mark.parametrize("kind", list(RESULTS))
def test_to_hdf5_refuses_fifo_and_directory(tmp_path, kind, kg_defocusing):
    result = RESULTS[kind](kg_defocusing)
    assert type(result).__name__ == kind
    fifo = tmp_path / "pipe.h5"
    os.mkfifo(fifo)
    with pytest.raises(lrchain.InputError, match="pipe.h5.*FIFO"):
        result.to_hdf5(fifo)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)  # still the FIFO: nothing renamed over it
    directory = tmp_path / "dir.h5"
    directory.mkdir()
    with pytest.raises(lrchain.InputError, match="dir.h5.*directory"):
        result.to_hdf5(directory)
    assert directory.is_dir() and list(directory.iterdir()) == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.h5", "pipe.h5"]  # no temporary left
    result.to_hdf5(tmp_path / "result.h5")  # a new name is written
    with h5py.File(tmp_path / "result.h5", "r") as f:
        assert f.attrs["lrchain_result"] == kind


def test_to_hdf5_replaces_a_regular_file(tmp_path):
    path = tmp_path / "old.h5"
    path.write_text("an earlier result")
    lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=21).to_hdf5(path)
    with h5py.File(path, "r") as f:
        assert f.attrs["lrchain_result"] == "DarkSolution"
