"""lrchain.load_model: shipped models by name or file, a user's model file compiled at run time, and
the coefficients of a loaded model (equal to the Params path for the resonant chain, the textbook
dispersion for Klein-Gordon), with ValueErrors naming bad parameters."""

import numpy as np
import pytest

import lrchain

from test_coefficients import FIELDS

# A user's model file (outside models/): a Klein-Gordon chain with a purely cubic on-site force and
# its own parameter names, so that its bytes differ from every shipped file.
SCRATCH_MODEL = """\
# A test model: harmonic coupling k, on-site force q^2 u + s u^3.
name = "scratch_kg"
description = "Klein-Gordon chain with a cubic on-site force (test model)"

[parameters]
k = { default = "1/5", range = "[0, inf)", description = "coupling" }
q = { default = 1,     range = "(0, inf)", description = "on-site frequency" }
s = { default = "1/3", description = "cubic on-site coefficient" }

[[field]]
name = "u"
mass = "1"
force = "k*(u[n+1] - 2*u[n] + u[n-1]) - (q^2*u[n] + s*u[n]^3)"
"""


def kg_omega(w0, C, theta):
    # Textbook linear dispersion of the discrete Klein-Gordon chain: omega^2 = w0^2 + 4 C sin^2(theta/2).
    return np.sqrt(w0**2 + 4 * C * np.sin(theta / 2) ** 2)


@pytest.mark.parametrize("source", ["resonant_chain", "models/resonant_chain.toml"])
def test_resonant_chain_equals_params_to_the_last_bit(source, source_dir):
    # The loaded resonant chain is evaluated by the same C++ evaluators as Params (as `lrchain coeffs
    # --model` does): bit-identical at random parameters, both branches, every field.
    if "/" in source:
        source = source_dir / source
    rng = np.random.default_rng(21)
    for _ in range(5):
        values = dict(alpha=rng.uniform(1.1, 3.0), delta0=rng.uniform(0.05, 2.0), kappa=rng.uniform(0.2, 5.0),
                      rho=rng.uniform(0.01, 30.0))
        model = lrchain.load_model(source, **values)
        assert model.name == "resonant_chain" and model.params == lrchain.Params(**values)
        theta = rng.uniform(-np.pi, np.pi, size=1000)
        for branch in ("acoustic", "optical"):
            got = lrchain.coefficients(model, branch, theta)
            expected = lrchain.coefficients(lrchain.Params(**values), branch, theta)
            for name in FIELDS:
                assert np.array_equal(got[name], expected[name], equal_nan=True), (name, values, branch)
            assert np.array_equal(got.regime_code, expected.regime_code)


def test_klein_gordon_textbook_dispersion(source_dir):
    # omega from det M = 0 of the shipped file against the closed form; c = omega'(theta) =
    # C sin(theta) / omega (derivative of the closed form); on-site: no mean flow, lambda NaN.
    for model in (lrchain.load_model("klein_gordon", C=0.3, w0=1.2),
                  lrchain.load_model(source_dir / "models" / "klein_gordon.toml", C=0.3, w0=1.2)):
        assert model.parameters == {"C": 0.3, "w0": 1.2, "a": 0.25, "b": 0.5}
        assert model.branches == ("branch0",) and not model.mean_flow and model.params is None
        theta = np.linspace(-np.pi + 1e-9, np.pi, 10001)
        c = lrchain.coefficients(model, "branch0", theta)
        np.testing.assert_allclose(c.omega, kg_omega(1.2, 0.3, theta), rtol=4e-16, atol=0)
        np.testing.assert_allclose(c.group_velocity, 0.3 * np.sin(theta) / c.omega, rtol=1e-13, atol=1e-16)
        assert np.all(np.isnan(c.lambda_))
        assert np.all(np.isfinite(c.omega)) and np.all(np.isfinite(c.curvature))


def test_scratch_model_file_compiled_at_run_time(tmp_path, monkeypatch):
    # A model file outside models/ is derived and compiled into the per-user cache (here a fresh
    # XDG_CACHE_HOME), then reused from there; its dispersion is Klein-Gordon's with w0 = q, C = k.
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    path = tmp_path / "scratch_kg.toml"
    path.write_text(SCRATCH_MODEL)
    model = lrchain.load_model(path, k=0.7, q=1.5)
    assert model.name == "scratch_kg" and model.parameters == {"k": 0.7, "q": 1.5, "s": pytest.approx(1 / 3)}
    cached = list((tmp_path / "cache" / "lrchain").glob("model-*.so"))
    assert len(cached) == 1
    theta = np.linspace(0.01, np.pi, 257)
    c = lrchain.coefficients(model, "branch0", theta)
    np.testing.assert_allclose(c.omega, kg_omega(1.5, 0.7, theta), rtol=4e-16, atol=0)
    # The same file again: loaded from the cache, with other values, same evaluators.
    again = lrchain.load_model(str(path), q=2.0)
    assert list((tmp_path / "cache" / "lrchain").glob("model-*.so")) == cached
    np.testing.assert_allclose(lrchain.coefficients(again, "branch0", 1.0).omega, kg_omega(2.0, 0.2, 1.0),
                               rtol=4e-16)
    assert again.replace(k=0.7, q=1.5).parameters == model.parameters


def test_unknown_parameter_name_is_named():
    with pytest.raises(ValueError) as err:
        lrchain.load_model("klein_gordon", omega0=1.0)
    assert isinstance(err.value, lrchain.InvalidParameterError) and err.value.parameter == "omega0"
    assert "no such parameter" in str(err.value) and "C, w0, a, b" in str(err.value)
    with pytest.raises(lrchain.InvalidParameterError, match="rhoo"):
        lrchain.load_model("resonant_chain").replace(rhoo=1)


@pytest.mark.parametrize("name, value, range_text", [
    ("w0", -1.0, "(0, inf)"),   # models/klein_gordon.toml
    ("C", -0.5, "[0, inf)"),
    ("w0", np.nan, "(0, inf)"),
])
def test_out_of_range_value_names_parameter_and_range(name, value, range_text):
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.load_model("klein_gordon", **{name: value})
    assert err.value.parameter == name and range_text in str(err.value)


def test_resonant_chain_model_ranges():
    # The ranges of models/resonant_chain.toml, as Params has them.
    with pytest.raises(lrchain.InvalidParameterError, match=r"alpha.*\(1, 5\]"):
        lrchain.load_model("resonant_chain", alpha=1.0)
    with pytest.raises(lrchain.InvalidParameterError, match="delta0"):
        lrchain.load_model("resonant_chain", delta0="x")


def test_bad_sources_and_branches(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    with pytest.raises(lrchain.InputError, match="no shipped model 'kleingordon'.*klein_gordon"):
        lrchain.load_model("kleingordon")
    with pytest.raises(lrchain.InputError, match="cannot read the model file"):
        lrchain.load_model(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\n[[field]]\nname = "u"\nmass = "1"\nforce = "u[n+1] - "\n')
    with pytest.raises(lrchain.InputError, match="bad.toml"):
        lrchain.load_model(bad)
    assert not (tmp_path / "cache" / "lrchain").exists() or not list((tmp_path / "cache" / "lrchain").glob("*.so"))
    kg = lrchain.load_model("klein_gordon")
    with pytest.raises(lrchain.InvalidParameterError, match="branch0") as err:
        lrchain.coefficients(kg, "optical", 1.0)
    assert err.value.parameter == "branch"
    with pytest.raises(lrchain.InvalidParameterError, match=r"theta\[1\] = 4"):
        lrchain.coefficients(kg, "branch0", np.array([1.0, 4.0]))
    fput = lrchain.load_model("fput")
    with pytest.raises(lrchain.InvalidParameterError, match=r"theta.*\(theta\[2\] = 0"):
        lrchain.coefficients(fput, fput.branches[0], np.array([1.0, 0.5, 0.0]))


def test_repr():
    assert repr(lrchain.load_model("klein_gordon", w0=2)) == "Model('klein_gordon', C=0.1, w0=2, a=0.25, b=0.5)"
    assert "klein_gordon" in lrchain.SHIPPED_MODELS and "resonant_chain" in lrchain.SHIPPED_MODELS


def test_loaded_model_equals_cli_json_to_the_last_bit(cli, source_dir):
    # Expected: `lrchain coeffs --model FILE --set ... --json` (the same library path, printed with
    # round-trip precision) for models other than the resonant chain.
    for name, values, theta in [("klein_gordon", {"C": 0.3, "w0": 1.2}, 1.1), ("fput", {"a": 0.1}, -2.0),
                                ("diatomic_chain", {"m": 3.0}, 0.7)]:
        model = lrchain.load_model(name, **values)
        sets = [arg for k, v in values.items() for arg in ("--set", f"{k}={v!r}")]
        for branch in model.branches:
            expected = cli("coeffs", "--model", source_dir / "models" / f"{name}.toml", *sets, "--branch", branch,
                           "--theta", repr(theta), "--json")
            got = lrchain.coefficients(model, branch, theta)
            for field in FIELDS:
                if expected[field] is None:
                    assert np.isnan(got[field]), (name, branch, field)
                else:
                    assert got[field] == expected[field], (name, branch, field)
            assert got.regime == expected["regime"]
