"""lrchain.simulate: exp1 from Python gives the CLI's numbers; the records as arrays; observers."""

import numpy as np
import pytest

import lrchain

# Experiment 1 (examples/exp1_optical_pi2.toml): optical breather at theta = pi/2, rho = 1/3, N = 500,
# 200 T_b, Blanes-Moan srkn11b with dt = 0.37.
EXP1 = dict(branch="optical", theta=np.pi / 2, sites=1001, periods=200, sample_every=0.25, spacetime_every=1.0,
            snapshot_periods=[0.0, 50.125, 200.0], stepper="srkn11b", dt=0.37)


@pytest.fixture(scope="module")
def exp1():
    return lrchain.simulate.bright(lrchain.Params(), **EXP1)


def test_exp1_max_E_x_equals_cli(cli, source_dir, tmp_path, exp1):
    # Expected: the CLI running the same experiment file (same C++ run_bright).
    expected = cli("simulate", "--config", source_dir / "examples" / "exp1_optical_pi2.toml", "--out",
                   tmp_path / "exp1", "--json")
    assert exp1.summary["max_E_x"] == expected["max_E_x"]
    assert exp1.summary["max_E_y"] == expected["max_E_y"]
    assert exp1.summary["ansatz"]["T_b"] == expected["ansatz"]["T_b"]
    # Paper (Sec. 4.2): E_x, E_y < 3.5 % over 200 T_b, T_b = 2.8885.
    assert exp1.E_x.max() == exp1.summary["max_E_x"] < 0.035
    assert exp1.summary["ansatz"]["T_b"] == pytest.approx(2.8885, rel=2e-5)


def test_exp1_record_arrays(exp1):
    T_b = exp1.summary["ansatz"]["T_b"]
    # 801 samples every 0.25 T_b plus the snapshot time 50.125 T_b between two of them.
    assert len(exp1.t) == 802 and exp1.t[-1] == pytest.approx(200 * T_b)
    for series in (exp1.E_x, exp1.E_y, exp1.energy, exp1.centre):
        assert series.shape == exp1.t.shape and np.all(np.isfinite(series))
    e = exp1.energy_density
    assert e.values.shape == (201, 1002) and e.n[0] == -501 and e.n[-1] == 500
    assert e.values.dtype == np.float32
    # Energy density sums to the total energy (eq. edensity; float32 storage).
    assert e.values[0].sum(dtype=np.float64) == pytest.approx(exp1.energy[0], rel=1e-5)
    # The breather moves right at about c_+ = 0.23 (Sec. 4.2).
    slope = np.polyfit(exp1.t, exp1.centre, 1)[0]
    assert slope == pytest.approx(0.23, rel=0.02)
    assert [round(s.t / T_b, 3) for s in exp1.snapshots] == [0.0, 50.125, 200.0]
    assert exp1.x is None and exp1.y is None


def test_record_strains_and_observer():
    seen = []

    def observer(t, x, y, e):
        seen.append((t, x.copy(), e.sum()))

    r = lrchain.simulate.bright(lrchain.Params(), theta=np.pi / 2, sites=121, periods=4, record_strains=True,
                                observer=observer)
    assert r.x.values.shape == (len(r.t), 121) and r.y.values.shape == (len(r.t), 121)
    assert r.x.n[0] == -60 and r.x.n[-1] == 60
    # The summary names the size as the keyword does and echoes the model as `lrchain coeffs --json`.
    assert r.summary["sites"] == 121 and "N" not in r.summary and "params" not in r.summary
    assert r.summary["model"]["name"] == "resonant_chain"
    assert r.summary["model"]["parameters"] == pytest.approx({"alpha": 1.5, "delta0": 4 / 9, "kappa": 1.0, "rho": 1 / 3},
                                                             rel=1e-15)
    assert [s[0] for s in seen] == list(r.t)
    assert np.array_equal(seen[-1][1], r.x.values[-1])
    # The observer's e_n sums to the recorded energy at every sample.
    assert np.allclose([s[2] for s in seen], r.energy, rtol=1e-12)
    # E_x(t) recomputed from the recorded strains and the first row: max|x - x_ansatz| / max|x(0)|
    # needs the ansatz; here check the normalisation E_x(0) = 0 (start on the ansatz).
    assert r.E_x[0] == 0.0


def test_observer_exception_propagates():
    def observer(t, x, y, e):
        if t > 1:
            raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        lrchain.simulate.bright(lrchain.Params(), sites=61, periods=3, observer=observer)


def test_drive_short_run():
    r = lrchain.simulate.drive(sites=200, t_end=60, switch_off_time=40, sample_every=1, spacetime_every=2, snapshot_times=[60],
                               record_displacements=True)
    assert len(r.t) == 61 and r.energy_density.values.shape == (31, 200)
    assert r.u.values.shape == (61, 200)
    # Energy enters through the driven first bead: zero at t = 0, positive afterwards.
    assert r.energy[0] == 0 and r.energy[-1] > 0
    assert r.summary["t_end"] == pytest.approx(60)
    assert r.summary["sites"] == 200 and r.summary["drive"]["switch_off_time"] == pytest.approx(40)
    assert r.summary["model"]["parameters"]["rho"] == pytest.approx(10, rel=1e-15)  # drive's default rho
    assert not {"beads", "params"} & set(r.summary) and "t_m" not in r.summary["drive"]


def test_modulated_short_run():
    r = lrchain.simulate.modulated(sites=101, theta_waves=63, t_end=200, sample_every=10, snapshot_times=[0, 200])
    assert len(r.t) == 21 and r.energy_density.values.shape == (21, 101)
    # The symplectic stepper conserves the energy of the periodic chain closely.
    assert np.max(np.abs(r.energy / r.energy[0] - 1)) < 1e-6
    assert r.summary["sites"] == 101 and "N" not in r.summary
    assert r.summary["initial"]["modulation_depth"] == pytest.approx(0.01, rel=1e-15)  # the library default
    assert "b" not in r.summary["initial"] and "params" not in r.summary
    assert r.summary["model"]["parameters"]["delta0"] == pytest.approx(0.27, rel=1e-15)


def test_bright_dt_fixes_the_step_of_the_default_stepper():
    # The default srkn11b chooses its step from an energy-error probe unless dt is given, as with
    # `lrchain simulate bright --dt`: a given dt is the step used (the summary's integrator.dt), not
    # replaced by the probe's choice.
    small = dict(sites=61, theta=np.pi / 2, periods=2.0, spacetime_every=0.5, snapshot_periods=[0.0])
    given = lrchain.simulate.bright(dt=0.2, **small).summary
    assert given["integrator"] == {"stepper": "srkn11b", "dt": 0.2, "abs_tol": 1e-12, "rel_tol": 1e-12}
    assert given["step_choice"] is None
    chosen = lrchain.simulate.bright(**small).summary
    assert chosen["integrator"]["stepper"] == "srkn11b"
    assert chosen["step_choice"]["method"] == "energy-error probe"
    assert chosen["integrator"]["dt"] != 0.2
