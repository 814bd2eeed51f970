"""Every job's one option schema (lrchain/jobs/option_schema.hpp: _lrchain.job_options) against what the
front ends show. For each job: the option lines of `lrchain <command> --help` carry the schema's help
text (its range and default) and REQUIRED exactly where the schema says so, and the command offers no
option of its own outside the schema; the Python functions of the job take the schema's keywords with
its default (None: the job's default, which is the schema's) and list them in their docstrings. CLI
and Python agree because both are compared with the same schema; a default or range spelled by hand
in either front end makes this fail."""

import inspect
import subprocess

import pytest

import lrchain
from lrchain import _lrchain, bright, dark, regime, simulate, wave
from lrchain._keywords import schema_line

from conftest import _cli_path

# job -> the `lrchain` commands that show it (one per step for a job with steps), None: not on the command line
COMMANDS = {
    "bright": [["simulate", "bright"]],
    "bright --model": None,  # the options of `simulate bright` a model run takes (checked there)
    "drive": [["simulate", "drive"]],
    "modulated": [["simulate", "modulated"]],
    "ring": [["simulate", "ring"]],
    "coeffs": [["coeffs"]],
    "dark": [["dark", "solve"], ["dark", "floquet"], ["dark", "continue"], ["dark", "evolve"]],
    "bright breather": [["bright", "solve"], ["bright", "floquet"], ["bright", "continue"], ["bright", "evolve"]],
    "regime intervals": [["regime", "intervals"]],
    "regime map": [["regime", "map"]],
    "regime curves": None,  # Python only (lrchain.regime.boundary_curves)
    "regime thresholds": [["regime", "thresholds"]],
    "wave": [["wave", "solve"], ["wave", "continue"], ["wave", "stability"], ["wave", "fate"], ["wave", "standing"]],
}
# job -> the Python functions that run it
FUNCTIONS = {
    "bright": [simulate.bright],
    "bright --model": [simulate.bright],
    "drive": [simulate.drive],
    "modulated": [simulate.modulated],
    "ring": [simulate.ring],
    "coeffs": [lrchain.coefficients],
    "dark": [dark.solve, dark.floquet, dark.continue_branch, dark.evolve],
    "bright breather": [bright.solve, bright.floquet, bright.continue_branch, bright.evolve],
    "regime intervals": [regime.intervals],
    "regime map": [regime.theta_rho_map, regime.theta_parameter_map, regime.delta0_omega_map],
    "regime curves": [regime.boundary_curves],
    "regime thresholds": [regime.thresholds],
    "wave": [wave.solve, wave.continue_branch, wave.stability, wave.fate, wave.standing],
}
# Options a command has that are no job option: how it reports (--out, --json, figures, files), the model
# (--model, --set and the resonant chain's parameters, lrchain/params.hpp) and the memory limit.
FRONT_END_OPTIONS = {"--help", "--out", "--json", "--no-figures", "--figure-format", "--format", "--restart",
                     "--checkpoint", "--max-memory", "--model", "--set", "--rho", "--kappa", "--delta0", "--alpha",
                     "--quiet", "--config"}
# Python keywords that are no job option: the lattice, what a result keeps, callbacks, progress display,
# an array to reuse.
FRONT_END_KEYWORDS = {"params", "model", "record_strains", "record_displacements", "observer", "progress", "out", "hi",
                      "branch"}


def test_every_job_is_walked():
    assert set(_lrchain.job_names()) == set(COMMANDS) == set(FUNCTIONS)


def _help_lines(command):
    """{option: its help line, whitespace normalised} of `lrchain <command> --help`."""
    done = subprocess.run([str(_cli_path()), *command, "--help"], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    lines = {}
    for line in done.stdout.splitlines():
        words = line.split()
        if line.startswith("  -") and words:
            lines[words[0].split(",")[-1]] = " ".join(words)
    return lines


def _steps(command, job):
    return command[-1:] if job in ("dark", "bright breather", "wave") else []


@pytest.mark.parametrize("job", sorted(j for j, c in COMMANDS.items() if c))
def test_cli_help_is_the_schema(job):
    options = _lrchain.job_options(job)
    for command in COMMANDS[job]:
        lines = _help_lines(command)
        step = _steps(command, job)
        offered = [o for o in options if o["cli"] and (not o["steps"] or step[0] in o["steps"])]
        assert offered, (job, command)
        for o in offered:
            assert o["cli"] in lines, (command, o["cli"])
            entry = lines[o["cli"]]
            help_text = " ".join(o["help"].split())
            assert help_text in entry, (command, o["cli"], entry, o["help"])
            signature = entry[:entry.index(help_text)]  # "--sites INT REQUIRED"
            assert ("REQUIRED" in signature.split()) == o["required"], (command, o["cli"], entry)
        # every option of the command is the schema's or the front end's own
        schema_flags = {o["cli"] for o in offered}
        unknown = set(lines) - schema_flags - FRONT_END_OPTIONS
        assert not unknown, (command, unknown)


@pytest.mark.parametrize("job", sorted(FUNCTIONS))
def test_python_keywords_take_the_schema_defaults(job):
    options = {o["python"]: o for o in _lrchain.job_options(job) if o["python"]}
    seen = set()
    for function in FUNCTIONS[job]:
        parameters = inspect.signature(function).parameters
        for name, parameter in parameters.items():
            if name not in options:
                # a keyword of another of the function's jobs (bright and bright --model) or the front end's
                others = {o["python"] for j, fs in FUNCTIONS.items() if function in fs for o in _lrchain.job_options(j)}
                assert name in FRONT_END_KEYWORDS or name in others, (job, function.__name__, name)
                continue
            seen.add(name)
            o = options[name]
            default = parameter.default
            # None (or no default: Python requires it) leaves the Config's default, the schema's
            if default is None or default is inspect.Parameter.empty:
                continue
            assert default == o["default"] and type(default) is type(o["default"]), \
                (job, function.__name__, name, default, o["default"])
            # and the docstring lists the keyword as the schema has it
        for name in set(parameters) & set(options):
            assert schema_line(options[name]) in " ".join(function.__doc__.split()), (job, function.__name__, name)
    assert seen == set(options), (job, set(options) - seen)


@pytest.mark.parametrize("job", sorted(j for j, c in COMMANDS.items() if c))
def test_cli_and_python_show_the_same_default_and_range(job):
    """An option both front ends offer: the CLI's help line and Python's docstring line state the same
    default and range (the schema's)."""
    options = [o for o in _lrchain.job_options(job) if o["cli"] and o["python"]]
    lines = {}
    for command in COMMANDS[job]:
        lines.update(_help_lines(command))
    docs = " ".join(" ".join(f.__doc__.split()) for f in FUNCTIONS[job])
    for o in options:
        entry = lines[o["cli"]]
        line = schema_line(o)
        assert line in docs, (job, line)
        if o["default_text"] and o["help"].count(o["default_text"]):
            assert o["default_text"] in entry and o["default_text"] in line, (job, o["key"])
        if o["range"] and o["range"] in o["help"]:
            assert o["range"] in entry and o["range"] in line, (job, o["key"])


def test_model_bright_defaults_are_the_bright_defaults():
    """`simulate bright --model` takes the options of `simulate bright` (the CLI copies them into the model
    run's config): ModelBrightConfig's defaults must be BrightRunConfig's (sim/bright_run.hpp)."""
    bright = {o["key"]: o for o in _lrchain.job_options("bright")}
    for o in _lrchain.job_options("bright --model"):
        if o["default"] is not None:
            assert o["default"] == bright[o["key"]]["default"], o["key"]


def test_help_form():
    """The two forms of a help text: "doc [range; default D]" (dark: the sites default_dark_sites gives,
    dark_job.hpp) and a job's own form with the range and default filled in (drive: DriveRunConfig's
    t_end 2400, sim/drive_run.hpp)."""
    sites = next(o for o in _lrchain.job_options("dark") if o["key"] == "sites")
    assert sites["help"] == sites["doc"] + " [" + sites["range"] + "; default 101 at a theta = pi edge, 100 at theta = 0]"
    t_end = next(o for o in _lrchain.job_options("drive") if o["key"] == "t_end")
    assert t_end["help"] == "final time (default 2400)" and t_end["default"] == 2400
