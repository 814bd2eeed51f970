"""lrchain.wave: the travelling wave job through Python (numbers: tests/unit/wave_nls_test.cpp and
wave_job_test.cpp; here the keywords, numpy outputs and errors)."""

import numpy as np
import pytest

import lrchain


def test_solve_gives_the_profile_as_numpy_and_the_nls_shift():
    w = lrchain.wave.solve(lrchain.load_model("klein_gordon"), theta=3 * np.pi / 4, amplitude=0.01)  # its only branch
    assert w.summary["branch"] == "branch0"
    assert isinstance(w.profile, np.ndarray) and w.profile.shape == (1, 2 * w.harmonics + 1)
    assert w.xi.shape == (2 * w.harmonics + 1,)
    # the first harmonic of the first field is A cos xi (the phase condition)
    c1 = 2 * np.mean(w.profile[0] * np.exp(-1j * w.xi))
    assert abs(c1 - 0.01) < 1e-12
    # omega - omega_linear = h A^2/4 to O(A^4): relative 1.1e-5 at A = 0.01 (docs/waves.md)
    assert abs((w.omega - w.omega_linear) / w.nls_omega_shift - 1) < 1e-4


def test_continue_reports_where_the_paper_chain_loses_contact():
    b = lrchain.wave.continue_branch(branch="optical", theta=np.pi / 2, amplitudes=[0.1, 0.2, 0.4])
    assert b["omega"].shape == (2,)
    assert "contact" in b["stopped"]


def test_bad_keyword_names_the_python_keyword():
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.wave.solve(lrchain.load_model("fput"), branch="acoustic", theta=2.5, amplitude=0.1, harmonics=1)
    assert e.value.parameter == "harmonics"
    with pytest.raises(lrchain.InvalidParameterError):
        lrchain.wave.solve(lrchain.load_model("fput"), branch="acoustic", theta=2.5)
    # the paper's chain has two branches: branch may not be left out (its names are listed)
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.wave.solve(theta=2.5, amplitude=0.1)
    assert e.value.parameter == "branch" and "'acoustic', 'optical'" in str(e.value)


def test_stability_arrays():
    w = lrchain.wave.stability(lrchain.load_model("fput"), branch="acoustic", theta=2.5, amplitude=0.02, k_points=50)
    s = w.stability
    assert s["k"].shape == s["growth_rate"].shape == s["nls_growth_rate"].shape == (50,)
    assert not s["stable"]
    assert abs(s["largest_rate"] / s["nls_largest_rate"] - 1) < 2e-3


def test_to_xarray_labels_profile_and_growth_rate(tmp_path):
    w = lrchain.wave.stability(lrchain.load_model("fput"), branch="acoustic", theta=2.5, amplitude=0.02, k_points=50)
    ds = w.to_xarray()
    assert ds.profile.dims == ("field", "xi") and list(ds.field.values) == ["u0"]
    assert ds.growth_rate.dims == ("K",) and ds.K.size == 50
    # the same numbers as the result's arrays, relabelled
    assert np.array_equal(ds.profile.values, w.profile)
    assert np.array_equal(ds.growth_rate.values, w.stability["growth_rate"])
    assert ds.attrs["omega"] == w.omega and ds.attrs["lrchain_result"] == "travelling_wave"
    # the largest rate in the Dataset is the job's (|h_tilde| A^2/4 at the NLS's K within 0.2 %:
    # tests/unit/wave_nls_test.cpp)
    assert float(ds.growth_rate.max()) <= w.stability["largest_rate"] * (1 + 1e-12)
    ds.to_netcdf(tmp_path / "wave.nc")
    solved = lrchain.wave.solve(lrchain.load_model("fput"), branch="acoustic", theta=2.5, amplitude=0.02).to_xarray()
    assert "growth_rate" not in solved and solved.profile.shape == (1, 2 * w.harmonics + 1)


def test_branch_result_reads_as_before_and_labels_on_amplitude():
    b = lrchain.wave.continue_branch(lrchain.load_model("fput"), theta=2.5, amplitudes=[0.05, 0.1, 0.2])
    assert isinstance(b, lrchain.wave.WaveBranch) and b.stopped is None
    assert b["omega"] is b.omega and b.omega.shape == (3,)  # the dict-style reading of earlier versions
    ds = b.to_xarray()
    assert ds.omega.dims == ("amplitude",) and ds.amplitude.values.tolist() == [0.05, 0.1, 0.2]
    # omega - omega_linear approaches the NLS shift h A^2/4 as A -> 0 (docs/waves.md: O(A^4) apart)
    ratio = ds.omega_shift.values / ds.nls_omega_shift.values
    assert abs(ratio[0] - 1) < abs(ratio[-1] - 1) and abs(ratio[0] - 1) < 1e-2
    assert ds.attrs["lrchain_result"] == "wave_branch" and ds.attrs["stopped"] == "null"


def test_fate_gives_the_ring_run_as_numpy_and_loads_back(tmp_path):
    w = lrchain.wave.fate(lrchain.load_model("fput"), theta=2.5, amplitude=0.3, ring_sites=64, periods=200)
    f = w.fate
    assert f["t"].shape == f["deviation"].shape == f["participation"].shape == f["dark"].shape == (201,)
    # fput's band omega = 2 sin(theta / 2): [0, 2]
    assert f["band"]["low"] == 0 and abs(f["band"]["high"] - 2) < 1e-12
    assert f["energy_density"].shape == (64,)
    # the exact wave at t = 0 is the wave to the noise (1e-4 A) plus its sampling on the ring
    assert f["deviation"][0] < 1e-3
    assert f["broke_at"] is not None and f["fate"] in ("modulated", "localized", "disordered")
    w.to_hdf5(tmp_path / "fate.h5")
    loaded = lrchain.load(tmp_path / "fate.h5")
    assert loaded.fate["fate"] == f["fate"] and np.array_equal(loaded.fate["entropy"], f["entropy"])
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.wave.fate(lrchain.load_model("fput"), theta=2.5, amplitude=0.3, ring_sites=4)
    assert e.value.parameter == "ring_sites"
    # the paper's seed instead of noise: the wave times 1 + b cos(2 pi n / N) starts about b away from it;
    # on fput's strains max_n |b (c_{n+1} U_{n+1} - c_n U_n)| / (2 A sin(theta / 2)) = 0.0095083, computed
    # from the solved profile (`lrchain wave solve --model fput --theta 10*pi/64 --amplitude 0.03`,
    # interpolated by its Fourier series; tests/unit/wave_fate_stage_test.cpp)
    m = lrchain.wave.fate(lrchain.load_model("fput"), theta=0.5, amplitude=0.03, ring_sites=64, periods=1,
                          noise=0, modulation=0.01).fate
    assert abs(m["deviation"][0] - 0.0095083) < 1e-6 and m["modulation"] == 0.01 and m["predicted_breakup"] is None
    assert m["deviation_of"] == "strain" and m["dark_from"] is None and m["bright_from"] is None


def test_standing_wave_as_numpy_with_its_multipliers_and_the_refusal_at_pi():
    # fput at theta = 2 pi/5 on 20 sites: the shift 9.11051e-5 at A = 0.02 (Lindstedt-Poincare 9.11157e-5,
    # tests/unit/wave_standing_test.cpp)
    s = lrchain.wave.standing(lrchain.load_model("fput"), theta=2 * np.pi / 5, amplitude=0.02, ring_sites=20)
    assert abs((s.omega - s.omega_linear) / 9.11157e-5 - 1) < 5e-4
    assert s.coefficients.shape == (1, 5, s.harmonics + 1)
    # the first field's cos(theta n) cos(omega t) part is A
    n = np.arange(5)
    assert abs(2 / 5 * np.sum(s.coefficients[0, :, 1] * np.cos(s.theta * n)) - 0.02) < 1e-12
    assert s.multipliers.dtype == complex and s.multipliers.shape == (40,) and s.stable
    assert [w["amplitude"] for w in s.branch] == pytest.approx([0.005, 0.01, 0.015, 0.02])
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.wave.standing(lrchain.load_model("fput"), theta=3.1, amplitude=0.02, ring_sites=20)
    assert e.value.parameter == "theta"
