"""result.to_xarray() for every result type and lrchain.open_sweep: labelled Datasets whose values
are the result's own numpy arrays (bit-equal), with named dimensions, units and provenance, that
survive a netCDF round trip."""

import math

import numpy as np
import pytest

import lrchain

xr = pytest.importorskip("xarray")


@pytest.fixture(scope="module")
def kg_defocusing():
    # klein_gordon with b = -1/2: defocusing at theta = pi (docs/dark-models.md: omega_b = 1.17).
    return lrchain.load_model("klein_gordon", b=-0.5)


# One cheap result of every type: (result, variable, the result's own array, expected dimensions).
CASES = {
    "Coefficients": lambda kg: (lrchain.coefficients(lrchain.Params(rho=1 / 3), "optical", np.linspace(0.1, 3, 7)),
                                "h_tilde", lambda r: r.h_tilde, ("theta",)),
    "Intervals": lambda kg: (lrchain.regime.intervals(lrchain.Params(rho=1 / 3), "optical"),
                             "lo", lambda r: r.lo, ("interval",)),
    "RegimeMap": lambda kg: (lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.1, 2, 5), theta=(0.1, 3, 6)),
                             "regime", lambda r: r.values, None),
    "BoundaryCurve": lambda kg: (lrchain.regime.boundary_curves(lrchain.Params(), "optical", axis="rho", lo=0.2, hi=2)[0],
                                 "parameter", lambda r: np.asarray(r.points)[:, 0], ("point",)),
    "BrightResult": lambda kg: (lrchain.simulate.bright(lrchain.Params(), sites=41, periods=1, record_strains=True),
                                "E_x", lambda r: r.E_x, ("time",)),
    "DriveResult": lambda kg: (lrchain.simulate.drive(sites=20, t_end=20, switch_off_time=10, sample_every=1,
                                                      spacetime_every=2, snapshot_times=[20], front_fit_start=1,
                                                      front_fit_end=20), "energy_density",
                               lambda r: r.energy_density.values, ("time_field", "site")),
    "ModulatedResult": lambda kg: (lrchain.simulate.modulated(sites=40, theta_waves=25, t_end=20, sample_every=10,
                                                              snapshot_times=[0], speed_fit_start=0, speed_fit_end=20),
                                   "contrast", lambda r: r.contrast, ("time",)),
    "ModelBrightResult": lambda kg: (lrchain.simulate.bright(model=lrchain.load_model("fput"), branch="acoustic",
                                                             theta=math.pi / 2, sites=41, periods=1),
                                     "E", lambda r: np.vstack(r.E), ("field", "time")),
    "RingResult": lambda kg: (lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", math.pi / 2, periods=20,
                                                    packet_width=8),
                              "measured_frequency", lambda r: r.measured_frequency, ("amplitude",)),
    "DarkSolution": lambda kg: (lrchain.dark.floquet(lrchain.Params(), omega_b=2.42, sites=21),
                                "x", lambda r: r.x, ("site",)),
    "Branch": lambda kg: (lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=21, points=2, ds=0.02,
                                                       floquet=False), "y", lambda r: r.y, ("point", "site")),
    "Evolution": lambda kg: (lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=2 * 2 * math.pi / 2.42),
                             "E_b", lambda r: r.E_b, ("time",)),
    "ModelDarkSolution": lambda kg: (lrchain.dark.floquet(model=kg, omega_b=1.17, sites=21),
                                     "z", lambda r: r.z, ("field", "site")),
    "ModelBranch": lambda kg: (lrchain.dark.continue_branch(model=kg, omega_b=1.17, sites=21, points=2, ds=0.02,
                                                            floquet=False), "z", lambda r: r.z, ("point", "field", "site")),
    "ModelEvolution": lambda kg: (lrchain.dark.evolve(model=kg, omega_b=1.17, sites=21, t_end=3 * 2 * math.pi / 1.17),
                                  "z", lambda r: r.z, ("strobe_time", "field", "site")),
}


@pytest.mark.parametrize("kind", list(CASES))
def test_to_xarray_relabels_the_result(tmp_path, kind, kg_defocusing):
    result, name, own, dims = CASES[kind](kg_defocusing)
    assert type(result).__name__ == kind
    ds = result.to_xarray()
    assert isinstance(ds, xr.Dataset)
    # The same numbers as the result's numpy attribute, bit for bit (NaN where it is NaN).
    np.testing.assert_array_equal(ds[name].values, own(result))
    if dims is not None:
        assert ds[name].dims == dims
    assert ds.attrs["lrchain_version"] == lrchain.__version__
    assert ds.attrs["lrchain_version_line"] == lrchain.provenance()["version_line"]
    for var in ds.data_vars.values():
        assert "long_name" in var.attrs
    # Every Dataset can be written to netCDF and read back unchanged.
    path = tmp_path / "result.nc"
    ds.to_netcdf(path)
    with xr.open_dataset(path) as back:
        np.testing.assert_array_equal(back[name].values, ds[name].values)


def test_model_results_carry_the_model(kg_defocusing):
    ds = lrchain.dark.solve(model=kg_defocusing, omega_b=1.17, sites=21).to_xarray()
    assert '"klein_gordon"' in ds.attrs["model"] and ds.attrs["branch"] == "branch0"
    assert list(ds.field.values) == ["u0"] and ds.site.values[0] == -10
    ring = lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", math.pi / 2, periods=20, packet_width=8)
    ds = ring.to_xarray()
    assert '"fput"' in ds.attrs["model"] and ds.amplitude.values.tolist() == list(ring.amplitude)


def test_bright_time_series_plot_axes():
    r = lrchain.simulate.bright(lrchain.Params(), sites=41, periods=1)
    ds = r.to_xarray()
    np.testing.assert_array_equal(ds.time.values, r.t)
    np.testing.assert_array_equal(ds.site.values, r.energy_density.n)
    assert ds.energy_density.dims == ("time_field", "site") and ds.time.attrs["units"]


def test_open_sweep_labels_the_grid(tmp_path, source_dir, cli):
    sweep = tmp_path / "s.toml"
    base = source_dir / "examples" / "sweeps" / "base" / "regime_intervals.toml"
    sweep.write_text(f'job = "regime intervals"\nbase = "{base}"\noutput = "{tmp_path / "out.h5"}"\n'
                     '[[axis]]\nparameter = "model.rho"\nvalues = [0.2, 1.0, 5.0]\n'
                     '[[axis]]\nparameter = "model.alpha"\nvalues = [1.2, 1.5]\n')
    cli("sweep", "--config", str(sweep), "--threads", "1")
    ds = lrchain.open_sweep(tmp_path / "out.h5")
    assert ds.optical_intervals.dims == ("model.rho", "model.alpha")
    assert ds["model.rho"].values.tolist() == [0.2, 1.0, 5.0] and (ds.status.values == 1).all()
    # Each point equals the single job at its parameters (regime intervals of the paper's chain).
    point = ds.sel({"model.rho": 1.0, "model.alpha": 1.2})
    single = lrchain.regime.intervals(lrchain.Params(rho=1.0, alpha=1.2), "optical")
    assert int(point.optical_intervals) == len(single)
    assert float(point.optical_first_lo) == pytest.approx(single.lo[0], abs=1e-10)
    assert ds.attrs["job"] == "regime intervals" and ds.attrs["lrchain_version"] == lrchain.__version__


def test_open_sweep_refuses_other_files(tmp_path):
    h5py = pytest.importorskip("h5py")
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f["x"] = [1.0]
    with pytest.raises(lrchain.InputError, match="not an lrchain sweep results file"):
        lrchain.open_sweep(tmp_path / "other.h5")
