"""Python's options have the caps of the lrchain command, both read from one table
(lib/include/lrchain/config/option_caps.hpp, listed by _lrchain.option_caps()). For every capped option
the Python function refuses cap + 1 and cap * 10 with InvalidParameterError naming its keyword, before
any computation, and the command refuses the same values with exit 2 and one line on stderr naming the
option. Before the table, dark.evolve(samples=10**7) and regime maps of 10**6 pixels per axis ran
unbounded (the command capped them at 10**6 and 20000)."""

import math
import subprocess

import pytest

import lrchain
from lrchain import _lrchain

from conftest import _cli_path

CAPS = _lrchain.option_caps()  # (command, option, least, most, counted unit or "", "function keyword")

DARK_OMEGA_B = 2.42  # the paper chain's dark breather below the optical edge (docs/dark-breathers.md)
DARK_PERIOD = 2 * math.pi / DARK_OMEGA_B


def _theta_rho(keyword, value):
    """theta_rho_map's axis tuples (lo, hi, n) with n = value on the axis `keyword`."""
    axes = {"rho": (0.01, 30.0, 10), "theta": (0.1, math.pi, 10)}
    lo, hi, _ = axes[keyword]
    axes[keyword] = (lo, hi, value)
    return lambda: lrchain.regime.theta_rho_map(lrchain.Params(), "optical", **axes)


# The Python call of each table entry ("function keyword") with the keyword's value.
PYTHON_CALLS = {
    "dark.solve sites": lambda v: lambda: lrchain.dark.solve(lrchain.Params(), omega_b=DARK_OMEGA_B, sites=v),
    "dark.continue_branch points": lambda v: lambda: lrchain.dark.continue_branch(
        lrchain.Params(), omega_b=DARK_OMEGA_B, sites=21, points=v),
    "dark.evolve samples": lambda v: lambda: lrchain.dark.evolve(lrchain.Params(), omega_b=DARK_OMEGA_B, sites=21,
                                                                 samples=v),
    "dark.evolve t_end": lambda v: lambda: lrchain.dark.evolve(lrchain.Params(), omega_b=DARK_OMEGA_B, sites=21,
                                                               t_end=v),
    "simulate.ring sites": lambda v: lambda: lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic",
                                                                   math.pi / 2, sites=v),
    "regime.intervals samples": lambda v: lambda: lrchain.regime.intervals(lrchain.Params(), "optical", samples=v),
    "regime.theta_rho_map rho": lambda v: _theta_rho("rho", v),
    "regime.theta_rho_map theta": lambda v: _theta_rho("theta", v),
}

# The command line of each table entry (command, option) with the option's value.
CLI_ARGS = {
    ("dark solve", "sites"): lambda v, out: ["dark", "solve", "--omega-b", DARK_OMEGA_B, "--sites", v],
    ("dark continue", "points"): lambda v, out: ["dark", "continue", "--omega-b", DARK_OMEGA_B, "--points", v],
    ("dark evolve", "samples"): lambda v, out: ["dark", "evolve", "--omega-b", DARK_OMEGA_B, "--t-end", 100,
                                                "--samples", v],
    ("dark evolve", "t-end"): lambda v, out: ["dark", "evolve", "--omega-b", DARK_OMEGA_B, "--t-end", v],
    ("simulate ring", "sites"): lambda v, out: ["simulate", "ring", "--model", "fput", "--branch", "acoustic",
                                                "--theta", "pi/2", "--sites", v],
    ("regime intervals", "samples"): lambda v, out: ["regime", "intervals", "--samples", v],
    ("regime map", "nx"): lambda v, out: ["regime", "map", "--out", out, "--nx", v],
    ("regime map", "ny"): lambda v, out: ["regime", "map", "--out", out, "--ny", v],
}


def _values(most, counted):
    """The refused values of an option capped at `most`: most + 1 and most * 10 (a time counted in
    periods T_b: that many periods and a half)."""
    counts = (most + 1, most * 10)
    if counted == "T_b":
        return [(c + 0.5) * DARK_PERIOD for c in counts]
    assert counted == "", f"no test for caps counted in {counted}"
    return list(counts)


def test_the_table_lists_the_capped_options():
    # The caps of cli/src/dark_command.cpp, regime_command.cpp and simulate_ring.cpp before they moved
    # into the table (f4efd39): dark --samples and --points 1e6, regime intervals --samples 1e7, map
    # --nx/--ny 20000, ring --sites 1e6, dark --sites and t-end / T_b 2^31 - 1.
    table = {(c, o): (least, most) for c, o, least, most, _, _ in CAPS}
    assert table[("dark evolve", "samples")] == (4, 10**6)
    assert table[("dark continue", "points")] == (1, 10**6)
    assert table[("regime intervals", "samples")] == (8, 10**7)
    assert table[("regime map", "nx")] == table[("regime map", "ny")] == (2, 20000)
    assert table[("simulate ring", "sites")] == (8, 10**6)
    assert table[("dark solve", "sites")] == (9, 2**31 - 1)
    assert table[("dark evolve", "t-end")] == (1, 2**31 - 1)
    for command, option, least, most, counted, python in CAPS:
        assert python in PYTHON_CALLS, f"no Python call for the cap of {command} --{option} ({python})"
        assert (command, option) in CLI_ARGS, f"no command line for the cap of {command} --{option}"


@pytest.mark.parametrize("cap", CAPS, ids=[f"{c[0]} --{c[1]}" for c in CAPS])
def test_python_refuses_what_the_command_refuses(cap, tmp_path):
    command, option, least, most, counted, python = cap
    keyword = python.split()[1]
    for value in _values(most, counted):
        with pytest.raises(lrchain.InvalidParameterError) as refused:
            PYTHON_CALLS[python](value)()
        assert refused.value.parameter == keyword, str(refused.value)
        assert keyword in str(refused.value)
        out = tmp_path / "out"
        done = subprocess.run([str(_cli_path()), *map(str, CLI_ARGS[(command, option)](value, out))],
                              capture_output=True, text=True, check=False, timeout=120)
        assert done.returncode == 2, f"{command} --{option} {value}: exit {done.returncode}: {done.stderr}"
        lines = done.stderr.strip().splitlines()
        assert len(lines) == 1 and option in lines[0], done.stderr
        assert not out.exists()  # refused before anything is written


def test_python_names_the_cap_in_its_message():
    # checked_integer's message: the range of the table, e.g. [4, 1000000] for dark --samples.
    with pytest.raises(lrchain.InvalidParameterError, match=r"samples: must be an integer in \[4, 1000000\]"):
        lrchain.dark.evolve(lrchain.Params(), omega_b=DARK_OMEGA_B, sites=21, samples=10**7)
    with pytest.raises(lrchain.InvalidParameterError, match=r"invalid omega: must be an integer in \[2, 20000\]"):
        lrchain.regime.delta0_omega_map(lrchain.Params(), "optical", omega=(2.0, 2.5, 200000))
