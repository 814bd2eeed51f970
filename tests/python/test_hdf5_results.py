"""The HDF5 files of coefficients, regime results and bright breathers: the command (`lrchain coeffs
--out`, `lrchain regime intervals --out`, `lrchain regime map --format hdf5`, `lrchain bright ... --format
hdf5`) and Python's to_hdf5() of the same job write the same datasets with the same bits (one writer in
the job layer serves both), lrchain.load reads the command's file back into the result class with the
numbers of the Python call, and every file carries the provenance (version, commit, model with its
parameters)."""

import json
import math
import subprocess

import numpy as np
import pytest

import lrchain
from conftest import _cli_path

h5py = pytest.importorskip("h5py")
from test_hdf5 import _assert_same_file  # noqa: E402

P = lrchain.Params(rho=3)


def _provenance(path):
    """The root attributes every lrchain result file has, checked, with the model as a dict."""
    with h5py.File(path, "r") as f:
        a = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
    assert a["lrchain_version"] == lrchain.__version__
    assert a["git_commit"] == "unknown" or len(a["git_commit"]) >= 7
    model = json.loads(a["model"])
    assert {"name", "file_hash", "parameters"} <= set(model)
    return a, model


def test_coeffs_cli_file_equals_python(tmp_path, cli):
    cli("coeffs", "--branch", "optical", "--theta", "1", "--rho", "3", "--json", "--out", tmp_path / "one")
    python = lrchain.coefficients(P, "optical", 1.0)
    python.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(tmp_path / "one" / "result.h5", tmp_path / "python.h5") >= 14
    loaded = lrchain.load(tmp_path / "one")
    assert loaded.omega == python.omega and loaded.h_tilde == python.h_tilde and loaded.regime == python.regime
    attrs, model = _provenance(tmp_path / "one" / "result.h5")
    assert attrs["lrchain_result"] == "Coefficients" and attrs["branch"] == "optical"
    assert model["name"] == "resonant_chain" and model["parameters"]["rho"] == 3
    # the table: one file per branch at theta = pi/8 ... pi, equal to the Python call at those wavenumbers
    printed = cli("coeffs", "--table", "--rho", "3", "--json", "--out", tmp_path / "table")
    for branch in printed["branches"]:
        table = lrchain.load(tmp_path / "table" / f"result_{branch['branch']}.h5")
        direct = lrchain.coefficients(P, branch["branch"], table.theta)
        np.testing.assert_array_equal(table.omega, direct.omega)
        np.testing.assert_array_equal(table.h_tilde, direct.h_tilde)
        assert [r["omega"] for r in branch["rows"]] == table.omega.tolist()


def test_intervals_cli_file_equals_python(tmp_path, cli):
    printed = cli("regime", "intervals", "--branch", "acoustic", "--rho", "3", "--out", tmp_path / "cli")
    python = lrchain.regime.intervals(P, "acoustic")
    python.to_hdf5(tmp_path / "python.h5")
    assert _assert_same_file(tmp_path / "cli" / "result.h5", tmp_path / "python.h5") >= 8
    loaded = lrchain.load(tmp_path / "cli")
    np.testing.assert_array_equal(loaded.lo, python.lo)
    assert loaded.hi_cause == python.hi_cause and loaded.branch == "acoustic"
    assert [i["lo"] for i in printed["intervals"]] == loaded.lo.tolist()
    _provenance(tmp_path / "cli" / "result.h5")


def test_regime_map_cli_file_equals_python(tmp_path, cli):
    args = ["regime", "map", "--plane", "theta-rho", "--rho", "3", "--rho-range", "0.1", "5",
            "--nx", "20", "--ny", "15", "--no-figures", "--format", "hdf5"]
    printed = cli(*args, "--branch", "both", "--no-curves", "--out", tmp_path / "cli")
    assert printed["hdf5_files"] == ["result_optical.h5", "result_acoustic.h5"]
    for branch in ("optical", "acoustic"):
        python = lrchain.regime.theta_rho_map(P, branch, rho=(0.1, 5, 20), theta=(math.pi / 15, math.pi, 15))
        python.to_hdf5(tmp_path / f"python_{branch}.h5")
        cli_file = tmp_path / "cli" / f"result_{branch}.h5"
        assert _assert_same_file(cli_file, tmp_path / f"python_{branch}.h5") >= 10
        loaded = lrchain.load(cli_file)
        np.testing.assert_array_equal(loaded.values, python.values)
        assert (loaded.x_name, loaded.y_name, loaded.plane, loaded.branch) == ("rho", "theta", "theta-rho", branch)
    # with its boundary curves: as many of each cause as the JSON counts, each within the map's rho range
    printed = cli(*args, "--branch", "optical", "--out", tmp_path / "curves")
    m = lrchain.load(tmp_path / "curves")
    counts = {k: v for k, v in printed["panels"][0]["boundary_polylines"].items() if k != "seconds"}
    assert {cause: sum(c.cause == cause for c in m.curves) for cause in counts} == counts and m.curves
    # (the tracer's last step may pass the range's end by a fraction of a step: 0.0987 and 5.016 seen)
    assert all(c.points.shape[1] == 2 and 0.09 <= c.points[:, 0].min() and c.points[:, 0].max() <= 5.1 for c in m.curves)
    again = tmp_path / "again.h5"
    m.to_hdf5(again)  # the loaded map with its curves writes the same file
    assert _assert_same_file(tmp_path / "curves" / "result.h5", again) >= 10


def test_bright_cli_file_equals_python(tmp_path, cli):
    fput = lrchain.load_model("fput", a=0)
    cli("bright", "floquet", "--model", "fput", "--set", "a=0", "--center", "bond", "--omega-b", "2.2", "--sites", "41",
        "--quiet", "--out", tmp_path / "cli", "--format", "hdf5")
    assert (tmp_path / "cli" / "profile.csv").is_file()  # the CSV files stay; result.h5 beside them
    python = lrchain.bright.floquet(fput, omega_b=2.2, center="bond", sites=41)
    python.to_hdf5(tmp_path / "python.h5")
    loaded = lrchain.load(tmp_path / "cli")
    assert isinstance(loaded, lrchain.bright.BrightBreather)
    np.testing.assert_array_equal(loaded.z, python.z)  # the same job: the same bits
    np.testing.assert_array_equal(loaded.floquet.multipliers, python.floquet.multipliers)
    assert loaded.summary["profile"] == python.summary["profile"]
    with h5py.File(tmp_path / "cli" / "result.h5", "r") as a, h5py.File(tmp_path / "python.h5", "r") as b:
        for name in ("n", "z", "seed", "floquet_multipliers"):
            np.testing.assert_array_equal(a[name][()], b[name][()])
    attrs, model = _provenance(tmp_path / "cli" / "result.h5")
    assert attrs["lrchain_result"] == "BrightBreather" and model["name"] == "fput" and model["parameters"]["a"] == 0


def test_bright_evolve_cli_file_equals_python(tmp_path, cli):
    # the FPU chain's Sievers-Takeno mode started along its unstable eigenvector, as in
    # docs/bright-breathers.md ("Evolution"): its deviation grows at the rate ln|lambda| / T_b
    fput = lrchain.load_model("fput", a=0)
    cli("bright", "evolve", "--model", "fput", "--set", "a=0", "--center", "site", "--omega-b", "2.2", "--sites", "41",
        "--periods", "12", "--perturb", "unstable", "--quiet", "--out", tmp_path / "cli", "--format", "hdf5")
    assert (tmp_path / "cli" / "evolution.csv").is_file()  # the CSV files stay; result.h5 beside them
    python = lrchain.bright.evolve(fput, omega_b=2.2, center="site", sites=41, periods=12, perturb="unstable")
    python.to_hdf5(tmp_path / "python.h5")
    loaded = lrchain.load(tmp_path / "cli")
    assert isinstance(loaded, lrchain.bright.BrightEvolution)
    for name in ("t", "deviation", "energy"):  # the same job: the same bits, m = 0..12
        np.testing.assert_array_equal(getattr(loaded, name), getattr(python, name))
    assert len(loaded.t) == 13
    np.testing.assert_array_equal(loaded.breather.z, python.breather.z)
    assert loaded.growth_rate == python.growth_rate and loaded.perturbation == python.perturbation
    # the file's deviation grows as exp(rate t) at the Floquet prediction ln(1.0282387) / T_b = 0.00975
    # (docs/bright-breathers.md): from its first and last samples within 1e-6 (measured 9.6e-7), 1e-5 allowed
    rate = np.log(loaded.deviation[-1] / loaded.deviation[0]) / loaded.t[-1]
    assert rate == pytest.approx(loaded.predicted_growth_rate, rel=1e-5)
    with h5py.File(tmp_path / "cli" / "result.h5", "r") as a, h5py.File(tmp_path / "python.h5", "r") as b:
        for name in ("n", "z", "seed", "t", "deviation", "energy", "floquet_multipliers"):
            np.testing.assert_array_equal(a[name][()], b[name][()])
    attrs, model = _provenance(tmp_path / "cli" / "result.h5")
    assert attrs["lrchain_result"] == "BrightEvolution" and model["name"] == "fput"
    # the same series as the CSV view of the command (17 significant digits)
    csv = np.loadtxt(tmp_path / "cli" / "evolution.csv", delimiter=",", skiprows=1)
    np.testing.assert_array_equal(csv[:, 1], loaded.t)
    np.testing.assert_array_equal(csv[:, 2], loaded.deviation)
    np.testing.assert_array_equal(csv[:, 4], loaded.energy)


def test_wave_cli_file_equals_python(tmp_path, cli):
    fput = lrchain.load_model("fput")
    cli("wave", "stability", "--model", "fput", "--theta", "2.5", "--amplitude", "0.02", "--k-points", "20",
        "--out", tmp_path / "cli", "--format", "hdf5")
    assert (tmp_path / "cli" / "growth.csv").is_file()  # the CSV files stay; result.h5 beside them
    python = lrchain.wave.stability(fput, theta=2.5, amplitude=0.02, k_points=20)
    python.to_hdf5(tmp_path / "python.h5")
    loaded = lrchain.load(tmp_path / "cli")
    assert isinstance(loaded, lrchain.wave.TravellingWave)
    np.testing.assert_array_equal(loaded.profile, python.profile)  # the same job: the same bits
    np.testing.assert_array_equal(loaded.stability["growth_rate"], python.stability["growth_rate"])
    with h5py.File(tmp_path / "cli" / "result.h5", "r") as a, h5py.File(tmp_path / "python.h5", "r") as b:
        for name in ("amplitude", "omega", "xi", "profile", "K", "growth_rate", "nls_growth_rate"):
            np.testing.assert_array_equal(a[name][()], b[name][()])
    attrs, model = _provenance(tmp_path / "cli" / "result.h5")
    assert attrs["lrchain_result"] == "TravellingWave" and model["name"] == "fput"
    # a branch (continue): WaveBranch, its omega(A) as in the JSON
    printed = cli("wave", "continue", "--model", "fput", "--theta", "2.5", "--amplitudes", "0.05", "0.1",
                  "--out", tmp_path / "branch", "--format", "hdf5")
    branch = lrchain.load(tmp_path / "branch")
    assert isinstance(branch, lrchain.wave.WaveBranch) and branch.stopped is None
    assert branch["omega"].tolist() == [w["omega"] for w in printed["waves"]]


def test_standing_wave_file_holds_the_json_numbers_and_equals_python(tmp_path, cli):
    # klein_gordon (not the paper's chain): theta = 2 pi/5 on 10 sites, A = 0.3 after the ramp 0.15, 0.3
    printed = cli("wave", "standing", "--model", "klein_gordon", "--theta", "2*pi/5", "--amplitude", "0.3",
                  "--ramp", "2", "--ring-sites", "10", "--out", tmp_path / "cli", "--format", "hdf5")
    assert (tmp_path / "cli" / "standing.csv").is_file()  # the CSV files stay; result.h5 beside them
    s = printed["standing"]
    path = tmp_path / "cli" / "result.h5"
    with h5py.File(path, "r") as f:
        # every number of the file is the printed JSON's, bit for bit
        for key in ("amplitude", "omega", "omega_shift", "harmonics", "residual"):
            assert f[key][()].tolist() == [w[key] for w in s["waves"]], key
        assert f["coefficients"][()].tolist() == s["coefficients"]  # [field][site][k]
        assert f["coefficients"].shape == (1, s["period_sites"], s["waves"][-1]["harmonics"] + 1)
        # the profiles at t = 0 and a quarter period: standing_profile.csv's (printed to 17 digits)
        csv = np.loadtxt(tmp_path / "cli" / "standing_profile.csv", delimiter=",", skiprows=1)
        assert f["profile"][()].tolist() == [csv[:, 1].tolist()]
        assert f["profile_quarter_period"][()].tolist() == [csv[:, 2].tolist()]
        # and the orbit's: u(0) = sum_k c_k, u(T/4) = sum_k c_k cos(k pi/2)
        c = f["coefficients"][()]
        k = np.arange(c.shape[2])
        np.testing.assert_allclose(f["profile"][()], c.sum(axis=2), rtol=0, atol=1e-15)
        np.testing.assert_allclose(f["profile_quarter_period"][()], (c * np.cos(k * np.pi / 2)).sum(axis=2), rtol=0,
                                   atol=1e-15)
        mu = f["floquet_multipliers"][()]
        assert mu.dtype == np.complex128 and mu.real.tolist() == s["floquet"]["re"]
        assert mu.imag.tolist() == s["floquet"]["im"]
        assert f.attrs["ring_sites"] == 10 and f.attrs["period_sites"] == s["period_sites"] == 5
        assert f.attrs["theta"] == printed["theta"] == s["ring_theta"]
    attrs, model = _provenance(path)
    assert attrs["lrchain_result"] == "StandingWave" and model["name"] == "klein_gordon"
    # Python's to_hdf5 writes the same datasets (one writer); lrchain.load gives Python's numbers
    python = lrchain.wave.standing(lrchain.load_model("klein_gordon"), theta=2 * math.pi / 5, amplitude=0.3, ramp=2,
                                   ring_sites=10)
    python.to_hdf5(tmp_path / "python.h5")
    with h5py.File(path, "r") as a, h5py.File(tmp_path / "python.h5", "r") as b:
        for name in ("amplitude", "omega", "omega_shift", "harmonics", "residual", "coefficients", "profile",
                     "profile_quarter_period", "floquet_multipliers"):
            np.testing.assert_array_equal(a[name][()], b[name][()])
    loaded = lrchain.load(tmp_path / "cli")
    assert isinstance(loaded, lrchain.wave.StandingWave)
    np.testing.assert_array_equal(loaded.coefficients, python.coefficients)
    np.testing.assert_array_equal(loaded.multipliers, python.multipliers)
    assert (loaded.omega, loaded.stable, loaded.branch) == (python.omega, python.stable, python.branch)
    # no wave at the amplitude (exit 3): the file holds the ramp before it; lrchain.load says why there is no wave
    done = subprocess.run([str(_cli_path()), "wave", "standing", "--model", "fput", "--theta", "9*pi/10", "--amplitude",
                           "0.8", "--ring-sites", "20", "--out", str(tmp_path / "failed"), "--format", "hdf5"],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 3, done.stderr
    with h5py.File(tmp_path / "failed" / "result.h5", "r") as f:
        assert f["amplitude"][()].tolist() == [0.2] and "coefficients" not in f and "floquet_multipliers" not in f
    with pytest.raises(lrchain.NumericalFailure, match="no standing wave at A = 0.8.*Newton did not converge"):
        lrchain.load(tmp_path / "failed")


def test_new_options_refuse_bad_input_and_write_nothing(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    for args, names in ((["coeffs", "--branch", "optical", "--theta", "1", "--out", blocker / "d"], "file"),
                        (["regime", "map", "--format", "netcdf", "--out", tmp_path / "m"], "--format"),
                        (["bright", "solve", "--model", "fput", "--omega-b", "2.2", "--format", "hdf5"], "--format"),
                        (["wave", "solve", "--model", "fput", "--theta", "2.5", "--amplitude", "0.1", "--format",
                          "hdf5"], "--format")):
        done = subprocess.run([str(_cli_path()), *map(str, args)], capture_output=True, text=True, check=False)
        assert done.returncode == 2, (args, done.stderr)
        assert len(done.stderr.strip().splitlines()) == 1 and names in done.stderr, done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


def test_bright_results_to_xarray():
    b = lrchain.bright.floquet(lrchain.load_model("fput", a=0), omega_b=2.2, center="bond", sites=41)
    ds = b.to_xarray()
    assert ds.z.dims == ("field", "site") and ds.site.values.tolist() == b.n.tolist()
    np.testing.assert_array_equal(ds.z.values, b.z)
    np.testing.assert_array_equal(ds.floquet_multiplier_real.values, b.floquet.multipliers.real)
    assert ds.attrs["lrchain_result"] == "bright_breather" and json.loads(ds.attrs["model"])["name"] == "fput"
    branch = lrchain.bright.continue_branch(lrchain.load_model("klein_gordon"), omega_b=1.19, sites=81, points=3)
    ds = branch.to_xarray()
    assert ds.z.dims == ("point", "field", "site")
    np.testing.assert_array_equal(ds.omega_b.values, branch.omega_b)
    np.testing.assert_array_equal(ds.peak.values, branch.peak)
    fl = b.floquet.to_xarray()
    assert fl.attrs["stable"] == int(b.floquet.stable) and fl.multiplier_real.size == len(b.floquet.multipliers)
