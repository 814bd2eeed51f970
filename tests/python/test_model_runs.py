"""Lattice runs of model files from Python: lrchain.simulate.bright(model=...), lrchain.simulate.ring
and lrchain.dark.solve|floquet|continue_branch|evolve(model=...) give the numbers of the lrchain
command run with the same options (the same C++ runs: equal to round-off), for shipped models and a
user's model file written into a temporary directory (its lattice code compiled at run time)."""

import numpy as np
import pytest

import lrchain

from test_model import SCRATCH_MODEL


def _close(python, cli, rtol=1e-12):
    """Python's number equals the CLI's: the same C++ run, so equal to round-off (rtol)."""
    assert python == pytest.approx(cli, rel=rtol, abs=0), (python, cli)


# fput, acoustic branch at theta = pi/2 (focusing, docs/simulate-models.md), 2001 sites, 10 T_b.
FPUT_BRIGHT = dict(branch="acoustic", theta=np.pi / 2, sites=2001, periods=10)


def test_model_bright_equals_cli(cli, source_dir):
    model_file = source_dir / "models" / "fput.toml"
    r = lrchain.simulate.bright(model=lrchain.load_model(model_file), **FPUT_BRIGHT)
    expected = cli("simulate", "bright", "--model", model_file, "--branch", "acoustic", "--theta", "pi/2",
                   "--sites", 2001, "--periods", 10, "--json")
    for key in ("max_E_x", "energy0", "max_relative_energy_drift", "centre_speed"):
        _close(r.summary[key], expected[key])
    _close(r.summary["ansatz"]["omega_b"], expected["ansatz"]["omega_b"])
    assert r.summary["steps"] == expected["steps"]
    # The arrays behind the summary: max over the record is the summary's max E_x, the energy starts
    # at energy0 and is conserved by the symplectic stepper to the reported drift.
    assert r.E_x.max() == r.summary["max_E_x"] and r.E_y is None  # fput has one field
    assert r.energy[0] == pytest.approx(r.summary["energy0"], rel=1e-15)
    drift = np.abs(r.energy / r.energy[0] - 1).max()
    assert drift == pytest.approx(r.summary["max_relative_energy_drift"], rel=1e-9)
    assert drift < 1e-9  # srkn11b on an autonomous lattice (measured 2.2e-12)
    assert r.summary["max_E_x"] < 0.05  # the NLS breather holds over 10 T_b (measured 0.79 %)
    assert r.t.shape == r.energy.shape == r.centre.shape == r.E_x.shape
    assert r.summary["model"]["name"] == "fput" and r.summary["model"]["lattice_code"]["compiled_in"] is True
    # The model object of the CLI (name, file_hash, parameters) plus lattice_code; the size as --sites.
    assert {k: v for k, v in r.summary["model"].items() if k != "lattice_code"} == \
        {k: v for k, v in expected["model"].items() if k != "lattice_code"}
    assert r.summary["sites"] == 2001 and "N" not in r.summary


def test_model_bright_positional_model_and_two_fields(cli, source_dir):
    # The diatomic chain (two fields; optical branch focusing at theta = 3 pi/4): E_y is the second
    # field's error; the model given as the first argument, made by lrchain.Model(file).
    model_file = source_dir / "models" / "diatomic_chain.toml"
    model = lrchain.Model(model_file)
    r = lrchain.simulate.bright(model, "optical", 3 * np.pi / 4, sites=101, periods=4)
    expected = cli("simulate", "bright", "--model", model_file, "--branch", "optical", "--theta", "3*pi/4",
                   "--sites", 101, "--periods", 4, "--json")
    assert len(r.E) == 2
    _close(r.E_x.max(), expected["max_E"][0])
    _close(r.E_y.max(), expected["max_E"][1])


def test_model_bright_refusals():
    model = lrchain.load_model("fput")
    with pytest.raises(lrchain.InputError, match="stepper is not available with model="):
        lrchain.simulate.bright(model=model, branch="acoustic", theta=np.pi / 2, stepper="rkf78")
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(model=lrchain.Params(), branch="acoustic", theta=np.pi / 2)
    assert err.value.parameter == "model"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(model=model, branch="acoustic", theta=np.pi / 2, sites=11)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(model=model, branch="optical", theta=np.pi / 2)
    assert err.value.parameter == "branch"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(model=model, branch="acoustic", theta=np.pi / 2, sample_every=-1)
    assert err.value.parameter == "sample_every"
    # klein_gordon (default b = 1/2) is defocusing at small theta (lrchain.coefficients' regime):
    # no bright breather there.
    kg = lrchain.load_model("klein_gordon")
    assert lrchain.coefficients(kg, "branch0", np.pi / 4).regime == "defocusing"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(model=kg, branch="branch0", theta=np.pi / 4)
    assert err.value.parameter == "theta"


def test_ring_equals_cli(cli, source_dir):
    model_file = source_dir / "models" / "fput.toml"
    r = lrchain.simulate.ring(lrchain.load_model(model_file), "acoustic", np.pi / 2, periods=100, packet_width=12)
    expected = cli("simulate", "ring", "--model", model_file, "--branch", "acoustic", "--theta", "pi/2",
                   "--periods", 100, "--packet-width", 12, "--json")
    for python, row in zip(r.measured_frequency, expected["amplitudes"]):
        _close(python, row["measured_frequency"])
    _close(r.summary["packet"]["measured_speed"], expected["packet"]["measured_speed"])
    for key in ("h", "omega", "group_velocity"):
        _close(r.summary["prediction"][key], expected["prediction"][key])
    np.testing.assert_array_equal(r.amplitude, [0.02, 0.01])
    # The ring's frequency shift measures h (Landau-Lifshitz-type NLS shift h U^2/4): within 1 %.
    assert np.all(r.relative_disagreement < 0.01)


@pytest.fixture(scope="module")
def kg_defocusing(source_dir):
    # klein_gordon with b = -1/2: defocusing at theta = pi (docs/dark-models.md: omega_b = 1.17).
    return source_dir / "models" / "klein_gordon.toml", lrchain.load_model(source_dir / "models" / "klein_gordon.toml", b=-0.5)


def test_dark_model_solve_equals_cli(cli, kg_defocusing):
    model_file, model = kg_defocusing
    s = lrchain.dark.floquet(model=model, omega_b=1.17, sites=31)
    expected = cli("dark", "floquet", "--model", model_file, "--set", "b=-1/2", "--omega-b", 1.17, "--sites", 31,
                   "--json", "--quiet")
    _close(s.measures["E_b"], expected["measures"]["E_b"], rtol=1e-6)  # E_b ~ 1e-14: round-off itself
    assert s.measures["E_b"] <= 1e-10
    for key in ("norm_squared", "K_x", "C_x"):
        _close(s.measures[key], expected["measures"][key], rtol=1e-10)
    _close(s.omega_edge, expected["omega_edge"])
    assert s.branch == expected["branch"] and s.theta == expected["theta"] and s.lattice_form == "displacement"
    assert s.measures["K_y"] is None and expected["measures"]["K_y"] is None
    _close(s.floquet.max_modulus, expected["floquet"]["max_modulus"], rtol=1e-8)
    assert s.floquet.pairing_defect < 1e-8
    assert len(s.newton_residuals) - 1 == expected["newton_iterations"]
    assert s.z.shape == s.seed.shape == (1, 31) and s.variables == ("u0",)


def test_dark_model_continue_and_evolve(cli, kg_defocusing, tmp_path):
    model_file, model = kg_defocusing
    b = lrchain.dark.continue_branch(model=model, omega_b=1.17, sites=31, points=3, ds=0.02, floquet=False)
    expected = cli("dark", "continue", "--model", model_file, "--set", "b=-1/2", "--omega-b", 1.17, "--sites", 31,
                   "--points", 3, "--ds", 0.02, "--json", "--quiet", "--out", tmp_path / "branch")
    rows = np.genfromtxt(tmp_path / "branch" / "branch.csv", delimiter=",", names=True)
    assert len(b.omega_b) == expected["points"] == len(rows)
    np.testing.assert_allclose(b.omega_b, rows["omega_b"], rtol=1e-11)  # the CSV prints 12 digits
    np.testing.assert_allclose(b.norm_squared, rows["norm_squared"], rtol=1e-11)
    assert b.z.shape == (3, 1, 31)
    e = lrchain.dark.evolve(model=model, omega_b=1.17, sites=31, t_end=3 * 2 * np.pi / 1.17 + 1e-9)
    assert len(e.t) == 3 and e.E_b.max() < 1e-8 and e.z.shape == (4, 1, 31)


def test_dark_model_refusals(kg_defocusing):
    _, model = kg_defocusing
    with pytest.raises(lrchain.InputError, match="omega_b is required"):
        lrchain.dark.solve(model=model)
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.solve(model=model, omega_b=1.17, sites=30)  # theta = pi needs an odd ring
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.solve(model=model, omega_b=1.2)  # above the edge 1.1832: the seed's amplitude is not real
    assert err.value.parameter == "omega_b"
    with pytest.raises(lrchain.InputError, match="full_monodromy"):
        lrchain.dark.floquet(model=model, omega_b=1.17, full_monodromy=True)
    with pytest.raises(lrchain.InvalidParameterError) as err:  # fput has no defocusing edge
        lrchain.dark.solve(model=lrchain.load_model("fput"), omega_b=2.1)
    assert err.value.parameter == "branch"


def test_user_model_file_in_tmp_dir(tmp_path, monkeypatch, cli):
    # A model file outside models/ (a cubic Klein-Gordon chain of test_model.py): its lattice code is
    # compiled at run time into the per-user cache (a fresh XDG_CACHE_HOME, shared with the CLI run).
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    path = tmp_path / "scratch_kg.toml"
    path.write_text(SCRATCH_MODEL)
    model = lrchain.load_model(path)
    # Hardening on-site cubic (s = 1/3): focusing near theta = pi.
    r = lrchain.simulate.bright(model=model, branch="branch0", theta=3 * np.pi / 4, sites=201, periods=10)
    assert r.summary["model"]["lattice_code"]["compiled_in"] is False
    assert r.summary["model"]["lattice_code"]["from_cache"] is False
    # One object (evaluators and lattice kernels) for the file: load_model compiled it, the run reused it.
    assert len(list((tmp_path / "cache" / "lrchain").glob("model-*.so"))) == 1
    expected = cli("simulate", "bright", "--model", path, "--branch", "branch0", "--theta", "3*pi/4", "--sites", 201,
                   "--periods", 10, "--json")
    assert expected["model"]["lattice_code"]["from_cache"] is True  # the library Python compiled
    for key in ("max_E_x", "energy0", "max_relative_energy_drift"):
        _close(r.summary[key], expected[key])
    # Softening on-site cubic (s = -1/3): defocusing at theta = pi, so a dark breather 1 % below the
    # edge omega(pi) = sqrt(q^2 + 4 k) = sqrt(1.8) (the textbook Klein-Gordon dispersion).
    omega_b = 0.99 * np.sqrt(1.8)
    s = lrchain.dark.solve(model=model.replace(s=-1 / 3), omega_b=omega_b, sites=31)
    expected = cli("dark", "solve", "--model", path, "--set", "s=-1/3", "--omega-b", repr(omega_b), "--sites", 31,
                   "--json", "--quiet")
    _close(s.omega_edge, np.sqrt(1.8), rtol=1e-14)
    assert s.measures["E_b"] <= 1e-10
    _close(s.measures["norm_squared"], expected["measures"]["norm_squared"], rtol=1e-10)
    # Editing the file after loading: the loaded model keeps the bytes it was loaded from (read once),
    # so its lattice code is that of the original file, found in the cache (the edited file's would
    # be compiled afresh), and a new load sees the edit.
    stale = lrchain.load_model(path, q=1.2)
    path.write_text(SCRATCH_MODEL.replace("cubic on-site force (test", "cubic on-site force (edited test"))
    ring = lrchain.simulate.ring(stale, "branch0", np.pi / 2, periods=20)
    assert ring.summary["model"]["lattice_code"]["from_cache"] is True
    assert ring.summary["model"]["file_hash"] == model.file_hash != lrchain.load_model(path).file_hash


# The resonant chain's model file on its optical branch, site-centred, omega_b = 2.42: the far-site
# amplitude K_x = 0.473 exceeds delta0 = 4/9, so the beads lose contact every period
# (docs/dark-models.md: 70 contact changes per period on 41 sites). 15 sites keep the contacts
# opening (18 changes per period, measured) at a fraction of the cost.
RC_CONTACTS = dict(omega_b=2.42, branch="optical", center="site", sites=15)
RC_CONTACTS_CLI = ("--branch", "optical", "--center", "site", "--omega-b", 2.42, "--sites", 15, "--json", "--quiet")


def test_dark_model_contacts_equal_cli(cli, source_dir, tmp_path):
    model_file = source_dir / "models" / "resonant_chain.toml"
    model = lrchain.load_model(model_file)
    s = lrchain.dark.solve(model=model, **RC_CONTACTS)
    expected = cli("dark", "solve", "--model", model_file, *RC_CONTACTS_CLI)
    # The same bonds (exported by the generated lattice code) and the same located contact changes.
    assert s.one_sided_contacts == tuple(expected["one_sided_contacts"]) == ("F(u[n+1] - u[n])",)
    assert s.contact_changes_per_period == expected["contact_changes_per_period"]
    assert s.contact_changes_per_period > 0 and s.contact_changes_per_period % 2 == 0  # each opened contact closes
    # The same C++ run: Newton's history and E_b to every digit the JSON prints (17 significant).
    assert len(s.newton_residuals) - 1 == expected["newton_iterations"]
    assert list(s.newton_residuals) == expected["newton_residuals"]
    assert s.measures["E_b"] == expected["measures"]["E_b"] and s.measures["E_b"] <= 1e-10
    assert s.measures["K_x"] == expected["measures"]["K_x"]
    # Continuation: every point reports its own contact changes, as the command's JSON and CSV do.
    b = lrchain.dark.continue_branch(model=model, points=3, ds=0.02, **RC_CONTACTS)  # Floquet at every point, as the CLI
    branch = cli("dark", "continue", "--model", model_file, "--points", 3, "--ds", 0.02, *RC_CONTACTS_CLI,
                 "--out", tmp_path / "branch")
    rows = np.genfromtxt(tmp_path / "branch" / "branch.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    assert len(b.omega_b) == len(branch["branch_points"]) == len(rows) == 3
    assert b.contact_changes_per_period == [p["contact_changes_per_period"] for p in branch["branch_points"]]
    assert list(rows["contact_changes_per_period"]) == b.contact_changes_per_period
    assert b.contact_changes_per_period[0] == s.contact_changes_per_period
    assert all(c > 0 for c in b.contact_changes_per_period)
    np.testing.assert_allclose(b.omega_b, [p["omega_b"] for p in branch["branch_points"]], rtol=1e-14)


def test_dark_model_smooth_has_no_contacts(kg_defocusing):
    _, model = kg_defocusing
    s = lrchain.dark.solve(model=model, omega_b=1.17, sites=15)
    assert s.one_sided_contacts == () and s.contact_changes_per_period is None
    b = lrchain.dark.continue_branch(model=model, omega_b=1.17, sites=15, points=2, ds=0.02, floquet=False)
    assert b.contact_changes_per_period == [None, None]
