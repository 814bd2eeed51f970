"""The dark job's one option schema (lrchain/jobs/dark_schema.hpp) against what the front ends show:
every option's default in lrchain.dark's signatures and its help text, range, default and
required-ness in `lrchain dark <step> --help` come from it, so they agree by construction; this walks
the schema and fails on any front end that spells a default or a help text of its own."""

import inspect
import subprocess

import pytest

import lrchain
from lrchain import _lrchain, dark

from conftest import _cli_path

OPTIONS = _lrchain.dark_options()
FUNCTIONS = {"solve": dark.solve, "floquet": dark.floquet, "continue": dark.continue_branch, "evolve": dark.evolve}
# DarkConfig keys the schema must hold (the options lrchain dark and lrchain.dark offer).
EXPECTED_KEYS = {"omega_b", "branch", "center", "sites", "mode", "tolerance", "max_iterations", "full_monodromy",
                 "points", "ds", "omega_min", "omega_max", "branch_floquet", "t_end", "samples", "format", "out",
                 "solver", "krylov_sites", "krylov_band", "floquet_count", "dark_floquet", "parameter", "to", "perturb",
                 "perturb_size", "seed"}


def _help(step):
    """The option lines of `lrchain dark <step> --help` (CLI11 prints one line per option)."""
    done = subprocess.run([str(_cli_path()), "dark", step, "--help"], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    return [line.strip() for line in done.stdout.splitlines() if line.strip().startswith("-")]


def _option_line(lines, flag):
    """The help line of `flag`, whitespace normalised."""
    found = [" ".join(line.split()) for line in lines if line.split()[0] == flag]
    assert len(found) == 1, f"{flag} not once in the help"
    return found[0]


def test_schema_holds_every_key_once():
    keys = [o["key"] for o in OPTIONS]
    assert len(keys) == len(set(keys))
    assert set(keys) == EXPECTED_KEYS


@pytest.mark.parametrize("step", sorted(FUNCTIONS))
def test_python_defaults_are_the_schema_defaults(step):
    parameters = inspect.signature(FUNCTIONS[step]).parameters
    offered = [o for o in OPTIONS if o["python"] and step in o["steps"]]
    assert offered
    for o in offered:
        assert o["python"] in parameters, f"{step}: {o['python']} missing"
        default = parameters[o["python"]].default
        # no schema default (required, or chosen by the job): Python's None selects its documented fallback
        expected = None if o["default"] is None else o["default"]
        assert default == expected and type(default) is type(expected), (step, o["key"], default, expected)
    # and no keyword of the dark job outside the schema
    known = {o["python"] for o in OPTIONS if o["python"]} | {"params", "model", "progress"}  # progress: how the call is shown, not a job option
    assert set(parameters) <= known, set(parameters) - known


@pytest.mark.parametrize("step", sorted(FUNCTIONS))
def test_cli_help_is_the_schema_help(step):
    text = _help(step)
    offered = [o for o in OPTIONS if o["cli"] and step in o["steps"]]
    assert offered
    for o in offered:
        entry = _option_line(text, o["cli"])
        assert " ".join(o["help"].split()) in entry, (o["cli"], entry)
        assert o["range"] in entry
        if o["default"] is not None:
            assert "default " + (o["default"] if isinstance(o["default"], str) else
                                 str(o["default"]).lower() if isinstance(o["default"], bool) else
                                 f"{o['default']:g}") in entry, entry
        assert ("REQUIRED" in entry) == o["required"], (o["cli"], entry)
    # options of other steps are not offered here
    flags = {line.split()[0] for line in text}
    for o in OPTIONS:
        if o["cli"] and step not in o["steps"]:
            assert o["cli"] not in flags, (step, o["cli"])


def test_help_text_says_default_and_range():
    """help = doc [range; default D]: sites has no single default (None), its help says the two
    default_dark_sites gives (dark_job.hpp): 101 at a theta = pi edge, 100 at theta = 0."""
    sites = next(o for o in OPTIONS if o["key"] == "sites")
    assert sites["default"] is None
    assert sites["help"] == sites["doc"] + " [" + sites["range"] + "; default 101 at a theta = pi edge, 100 at theta = 0]"
    omega_b = next(o for o in OPTIONS if o["key"] == "omega_b")
    assert omega_b["required"] and omega_b["help"].endswith("; required]")
