"""Invalid input raises InvalidParameterError (a ValueError) naming the parameter and its range."""

import math

import numpy as np
import pytest

import lrchain


@pytest.mark.parametrize("name, value, range_text", [
    # the ranges of lib/include/lrchain/params.hpp
    ("alpha", 1.0, "(1, 5]"),
    ("delta0", 0.0, "(0, 10]"),
    ("kappa", -1.0, "(0, 10000]"),
    ("rho", math.nan, "(0, 10000]"),
    ("rho", math.inf, "(0, 10000]"),
    ("rho", 1e308, "(0, 10000]"),
])
def test_params(name, value, range_text):
    with pytest.raises(ValueError) as err:
        lrchain.Params(**{name: value})
    assert isinstance(err.value, lrchain.InvalidParameterError)
    assert err.value.parameter == name
    assert name in str(err.value) and range_text in str(err.value)


def test_params_replace_validates():
    with pytest.raises(lrchain.InvalidParameterError, match="rho"):
        lrchain.Params().replace(rho=-2)
    with pytest.raises(TypeError, match="unknown parameter 'beta'"):
        lrchain.Params().replace(beta=1)
    assert lrchain.Params().replace(rho=3).rho == 3


def test_theta_out_of_range_names_theta_and_index():
    p = lrchain.Params()
    with pytest.raises(lrchain.InvalidParameterError, match=r"theta.*\(-pi, pi\]") as err:
        lrchain.coefficients(p, "optical", 4.0)
    assert err.value.parameter == "theta"
    with pytest.raises(lrchain.InvalidParameterError, match=r"theta\[2\] = nan"):
        lrchain.coefficients(p, "optical", np.array([0.1, 0.2, np.nan]))
    with pytest.raises(lrchain.InvalidParameterError, match="nonzero on the acoustic branch"):
        lrchain.coefficients(p, "acoustic", 0.0)


def test_branch_names_branch():
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.coefficients(lrchain.Params(), "optic", 1.0)
    assert err.value.parameter == "branch" and "optical" in str(err.value)


def test_simulation_options():
    # Lattice sizes are `sites` as in the command's --sites: bright takes the odd 2N + 1.
    with pytest.raises(lrchain.InvalidParameterError, match="odd") as err:
        lrchain.simulate.bright(sites=2)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError, match="odd") as err:
        lrchain.simulate.bright(sites=100)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(periods=-1)
    assert err.value.parameter == "periods"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(stepper="euler")
    assert err.value.parameter == "stepper"
    with pytest.raises(lrchain.InvalidParameterError, match="must be an integer, not float") as err:
        lrchain.simulate.bright(sites=10.5)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.bright(sample_every=-1)
    assert err.value.parameter == "sample_every" and str(err.value).startswith("invalid sample_every:")
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.drive(sites=3)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.modulated(modulation_depth=2)
    assert err.value.parameter == "modulation_depth"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.simulate.modulated(sites=4)
    assert err.value.parameter == "sites"


@pytest.mark.parametrize("call, old, new", [
    (lambda: lrchain.simulate.bright(N=40), "N", "sites"),
    (lambda: lrchain.simulate.drive(beads=50), "beads", "sites"),
    (lambda: lrchain.simulate.drive(t_m=2), "t_m", "switch_off_time"),
    (lambda: lrchain.simulate.modulated(N=21), "N", "sites"),
    (lambda: lrchain.simulate.modulated(b=0.1), "b", "modulation_depth"),
    (lambda: lrchain.dark.solve(edge="optical"), "edge", "branch"),
    (lambda: lrchain.dark.floquet(edge="optical"), "edge", "branch"),
    (lambda: lrchain.dark.continue_branch(edge="optical"), "edge", "branch"),
    (lambda: lrchain.dark.evolve(edge="optical"), "edge", "branch"),
])
def test_old_keyword_names_raise_naming_the_new_one(call, old, new):
    # One name per concept, the command's (--sites, --branch, --switch-off-time, --modulation-depth):
    # an old keyword is a TypeError naming its new name, never silently accepted.
    with pytest.raises(TypeError, match=f"'{old}', which is now '{new}'"):
        call()


# The note of the config key's rename (sim/include/lrchain/sim/strain_sites.hpp): sites is 2N + 1, so
# bright(N=500) must not be retyped as sites=500 or 501, which would run half the lattice.
HALF_WIDTH_NOTE = "the number of strain sites 2N + 1 (the old N was the half-width)"


@pytest.mark.parametrize("call, message", [
    (lambda: lrchain.simulate.bright(N=500),
     f"bright() got the keyword argument 'N', which is now 'sites', {HALF_WIDTH_NOTE}; use sites="),
    (lambda: lrchain.simulate.bright(lrchain.load_model("fput"), "acoustic", N=500),
     f"bright() got the keyword argument 'N', which is now 'sites', {HALF_WIDTH_NOTE}; use sites="),
    (lambda: lrchain.simulate.drive(beads=50), "drive() got the keyword argument 'beads', which is now 'sites'; use sites="),
    (lambda: lrchain.simulate.drive(t_m=2),
     "drive() got the keyword argument 't_m', which is now 'switch_off_time'; use switch_off_time="),
    (lambda: lrchain.simulate.modulated(N=21),
     "modulated() got the keyword argument 'N', which is now 'sites'; use sites="),
    (lambda: lrchain.simulate.modulated(b=0.1),
     "modulated() got the keyword argument 'b', which is now 'modulation_depth'; use modulation_depth="),
])
def test_old_keyword_message_says_what_changed_besides_the_name(call, message):
    # The messages come from the config schemas' renamed lists, notes included; only bright's N
    # changed meaning (half-width -> odd count), so only its message carries "2N + 1".
    with pytest.raises(TypeError) as err:
        call()
    assert str(err.value).startswith(message)
    assert ("2N + 1" in str(err.value)) == ("2N + 1" in message)


def test_renamed_options_are_the_config_schemas_lists():
    # One list per table, read from the schema that refuses the old config keys (docs/configs.md).
    note = f"'sites', {HALF_WIDTH_NOTE}"
    assert lrchain._lrchain.renamed_options("bright") == [("N", "sites", note)]
    assert lrchain._lrchain.renamed_options("model bright") == [("N", "sites", note)]
    assert lrchain._lrchain.renamed_options("drive") == [("beads", "sites", "'sites'"),
                                                         ("t_m", "switch_off_time", "'switch_off_time'")]
    assert lrchain._lrchain.renamed_options("modulated") == [("N", "sites", "'sites'"),
                                                             ("b", "modulation_depth", "'modulation_depth'")]
    assert lrchain._lrchain.renamed_options("dark") == [("edge", "branch", "'branch'")]
    with pytest.raises(ValueError, match="no table"):
        lrchain._lrchain.renamed_options("ring")


@pytest.mark.parametrize("run, options, old, new", [
    ("simulate_bright", {"N": 40}, "N", "sites', the number of strain sites 2N \\+ 1"),
    ("simulate_drive", {"beads": 50}, "beads", "sites"),
    ("simulate_drive", {"t_m": 2.0}, "t_m", "switch_off_time"),
    ("simulate_modulated", {"N": 21}, "N", "sites"),
    ("simulate_modulated", {"b": 0.1}, "b", "modulation_depth"),
])
def test_run_option_dicts_take_the_config_keys_and_refuse_the_old_ones(run, options, old, new):
    # The option dicts of the compiled runs have the config files' keys; an old key is refused naming
    # the new one, as in a config file.
    with pytest.raises(TypeError, match=f"got the option '{old}', which is now '{new}"):
        getattr(lrchain._lrchain, run)(options, False, None)


def test_bright_sites_is_the_odd_count_in_the_compiled_run_too():
    # sites = 2N + 1 reaches the run as the half-width N: 61 strain sites are n = -30..30 (the snapshot's n).
    r = lrchain._lrchain.simulate_bright({"sites": 61, "theta": math.pi / 2, "periods": 1.0, "spacetime_every": 0.5,
                                         "snapshot_periods": [0.0]}, False, None)
    n = r["record"]["snapshots"][0]["columns"]["n"]
    assert len(n) == 61 and n[0] == -30 and n[-1] == 30
    with pytest.raises(lrchain.InvalidParameterError, match=r"must be an odd integer in \[5, 2000000000000001\]") as err:
        lrchain._lrchain.simulate_bright({"sites": 60}, False, None)
    assert err.value.parameter == "sites"


def test_dark_options():
    with pytest.raises(lrchain.InvalidParameterError, match="odd") as err:
        lrchain.dark.solve(sites=100)
    assert err.value.parameter == "sites"
    # Above the optical edge omega_+(pi) = sqrt(6) there is no dark breather (the gap side is below).
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.solve(omega_b=2.5)
    assert err.value.parameter == "omega_b" and str(err.value).startswith("invalid omega_b:")
    # Too large for the machine: refused before Newton starts, naming what to lower.
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.solve(sites=2_000_001)
    assert err.value.parameter == "sites"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.evolve(t_end=1e12)
    assert err.value.parameter == "t_end"


def test_regime_options():
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.0, 1.0, 10))
    assert err.value.parameter == "rho"
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.regime.boundary_curves(lrchain.Params(), "optical", axis="kappa")
    assert err.value.parameter == "axis"


@pytest.mark.parametrize("option, value", [
    # the same window as `lrchain dark continue` (sim/src/dark/continuation_window.cpp): omega_max in
    # (omega_b, 2 omega_top], omega_top = 2.4495 the top of the optical band at the paper's parameters
    ("omega_max", 1e308),
    ("omega_max", 2.40),
    ("omega_min", 2.43),
    ("ds", 5.0),
])
def test_continuation_window(option, value):
    with pytest.raises(lrchain.InvalidParameterError) as err:
        lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, points=3, **{option: value})
    assert err.value.parameter == option
