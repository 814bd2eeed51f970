"""lrchain.regime and `lrchain regime` run the same jobs: Python's defaults and ranges are the job
Config's (the CLI's), and model files (here klein_gordon.toml and fput, not the paper's chain) give
intervals, maps, curves and thresholds, checked against lrchain.coefficients and the CLI."""

import inspect
from pathlib import Path

import numpy as np
import pytest

import lrchain

R = lrchain.regime
KLEIN_GORDON = Path(__file__).resolve().parents[2] / "models" / "klein_gordon.toml"


def _default(function, name):
    return inspect.signature(function).parameters[name].default


def test_python_defaults_are_the_jobs():
    # Expected: the job Configs (lrchain/jobs/regime_job.hpp), exported by the module.
    d = lrchain._lrchain.regime_job_defaults()
    assert _default(R.intervals, "samples") == d["samples"] == 2048
    assert _default(R.intervals, "tolerance") == d["tolerance"] == 1e-12
    assert tuple(d["samples_range"]) == (8, 10**7)
    assert d["nx"] == d["ny"] == 600 and tuple(d["nx_range"]) == tuple(d["ny_range"]) == (2, 20000)
    # None means "the job's default": the CLI's, per branch.
    for f, name in [(R.theta_rho_map, "rho"), (R.theta_rho_map, "theta"), (R.delta0_omega_map, "delta0"),
                    (R.delta0_omega_map, "omega"), (R.boundary_curves, "lo"), (R.boundary_curves, "hi"),
                    (R.theta_parameter_map, "x"), (R.thresholds, "scan")]:
        assert _default(f, name) is None, f"{f.__name__}({name}=...)"
    assert tuple(d["rho_range_optical"]) == (0.01, 30.0)
    assert tuple(d["rho_range_acoustic"]) == (0.01, 2.5)
    assert tuple(d["delta0_range"]) == (0.001, 1.0)
    p = lrchain.Params(rho=3.0)
    for branch in ("optical", "acoustic"):
        m = R.theta_rho_map(p, branch, theta=(0.5, 3.0, 3))
        rho = d[f"rho_range_{branch}"]
        assert (m.rho[0], m.rho[-1], len(m.rho)) == (rho[0], rho[1], d["nx"])
        m = R.delta0_omega_map(p, branch, delta0=(0.001, 1.0, 3))
        assert (m.omega[0], m.omega[-1], len(m.omega)) == (*R.map_defaults(p, branch)["omega"], d["ny"])
        assert m.delta0[0] == d["delta0_range"][0] and m.delta0[-1] == d["delta0_range"][1]


def test_python_default_ranges_equal_the_cli_map(cli, tmp_path):
    # Expected: the ranges `lrchain regime map` reports with no range options.
    p = lrchain.Params(rho=3.0)
    out = cli("regime", "map", "--plane", "delta0-omega", "--branch", "acoustic", "--rho", "3", "--nx", "4",
              "--ny", "4", "--no-curves", "--no-figures", "--out", tmp_path / "do")
    assert tuple(out["maps"][0]["omega_range"]) == R.map_defaults(p, "acoustic")["omega"]
    assert tuple(out["maps"][0]["delta0_range"]) == R.map_defaults(p, "acoustic")["delta0"]
    out = cli("regime", "map", "--branch", "acoustic", "--nx", "4", "--ny", "4", "--no-curves", "--no-figures",
              "--out", tmp_path / "tr")
    assert tuple(out["panels"][0]["rho_range"]) == R.map_defaults(lrchain.Params(), "acoustic")["rho"]


def test_model_file_map_is_the_sign_of_curvature_times_h():
    # Independent check: lrchain.coefficients of the model at every pixel (focusing iff omega'' h < 0;
    # klein_gordon has no mean flow, so h_tilde = h).
    model = lrchain.load_model(KLEIN_GORDON, C=0.5)
    m = R.theta_parameter_map(model, model.branches[0], axis="b", x=(0.5, 2.0, 7), theta=(0.1, np.pi, 9))
    assert m.x_name == "b" and m.values.shape == (9, 7)
    checked = 0
    for i, b in enumerate(m.b):
        c = lrchain.coefficients(lrchain.load_model(KLEIN_GORDON, C=0.5, b=b), model.branches[0], m.theta)
        product = c.curvature * c.h
        for j in range(len(m.theta)):
            if abs(product[j]) < 1e-9:
                continue  # on a boundary
            expected = R.FOCUSING if product[j] < 0 else R.DEFOCUSING
            assert m.values[j, i] == expected, (b, m.theta[j])
            checked += 1
    assert checked > 40


def test_model_file_intervals_and_thresholds_equal_the_cli(cli):
    # Expected: `lrchain regime intervals|thresholds --model FILE` (the same job).
    model = lrchain.load_model(KLEIN_GORDON, C=0.5, a=1, b=1.2)
    got = R.intervals(model)
    expected = cli("regime", "intervals", "--model", KLEIN_GORDON, "--set", "C=0.5", "--set", "a=1", "--set",
                   "b=6/5", "--json")
    assert [(e["lo"], e["hi"]) for e in expected["intervals"]] == list(zip(got.lo, got.hi))
    assert len(got) > 0
    for lo, hi in got:  # inside a focusing interval curvature * h < 0
        c = lrchain.coefficients(model, model.branches[0], 0.5 * (lo + hi))
        assert c.curvature * c.h < 0
    model = lrchain.load_model(KLEIN_GORDON, C=0.5, a=1)
    t = R.thresholds(model, axis="b", axis_range=(1.15, 1.5))
    e = cli("regime", "thresholds", "--model", KLEIN_GORDON, "--set", "C=0.5", "--set", "a=1", "--axis", "b",
            "--axis-range", "1.15", "1.5")
    for scan in t["scans"] + e["scans"]:
        scan.pop("seconds")
    assert t["scans"] == e["scans"] and t["model"] == e["model"]


def test_model_boundary_curves_are_zero_sets():
    # Points of klein_gordon's curvature_zero curve (over its parameter b) have omega'' ~ 0 there, and
    # fput's h_tilde_zero curve has h_tilde ~ 0 (lrchain.coefficients, an independent evaluation).
    for source, field in [(KLEIN_GORDON, "curvature"), ("fput", "h_tilde")]:
        model = lrchain.load_model(source)
        curves = [c for c in R.boundary_curves(model, model.branches[0], axis="b", lo=0.1, hi=2.0)
                  if c.cause == f"{field}_zero"]
        assert curves, source
        for curve in curves:
            for b, theta in curve.points[:: max(1, len(curve.points) // 10)]:
                c = lrchain.coefficients(lrchain.load_model(source, b=b), model.branches[0], theta)
                scale = abs(c.group_velocity) + abs(c.omega) if field == "curvature" else abs(c.h) + abs(c.beta) + 1
                assert abs(getattr(c, field)) < 1e-6 * scale, (source, b, theta)


def test_map_errors_name_the_python_keyword():
    with pytest.raises(lrchain.InvalidParameterError) as e:
        R.theta_rho_map(lrchain.Params(), "optical", rho=(5.0, 1.0, 10))
    assert e.value.parameter == "rho"
    with pytest.raises(lrchain.InvalidParameterError) as e:
        R.theta_parameter_map(lrchain.load_model("fput"), "acoustic", axis="b")
    assert e.value.parameter == "x"  # fput's b has no declared range: x is required
