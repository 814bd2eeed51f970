"""help() of every public function of lrchain shows an example that runs: each function of the package
and of lrchain.regime, lrchain.simulate, lrchain.dark and lrchain.bright has an "Example" section with doctest lines,
and running them (doctest) gives the output the docstring shows."""

import doctest
import inspect

import pytest

import lrchain

_MODULES = (lrchain, lrchain.regime, lrchain.simulate, lrchain.dark, lrchain.bright)


def _public_functions():
    """(name, function) of every public function: the package's __all__ and each submodule's own
    functions (not the names it imports)."""
    found = {}
    for module in _MODULES:
        names = module.__all__ if module is lrchain else dir(module)
        for name in names:
            item = getattr(module, name)
            if name.startswith("_") or not inspect.isfunction(item):
                continue
            if module is not lrchain and item.__module__ != module.__name__:
                continue
            found[f"{module.__name__}.{name}"] = item
    return sorted(found.items())


FUNCTIONS = _public_functions()


def test_the_walk_finds_the_public_functions():
    names = {name for name, _ in FUNCTIONS}
    # a sample from each module, so that an empty walk cannot pass
    assert {"lrchain.load", "lrchain.sweep", "lrchain.coefficients", "lrchain.regime.intervals",
            "lrchain.simulate.ring", "lrchain.dark.continue_branch", "lrchain.bright.floquet"} <= names
    assert len(names) >= 23


@pytest.mark.parametrize("name, function", FUNCTIONS, ids=[name for name, _ in FUNCTIONS])
def test_example_runs(name, function, tmp_path, monkeypatch):
    doc = inspect.getdoc(function) or ""
    assert "Example::" in doc, f"{name}: no Example section in its docstring"
    tests = doctest.DocTestFinder(recurse=False).find(function, name, globs={})
    assert tests and tests[0].examples, f"{name}: the Example section has no >>> lines"
    monkeypatch.chdir(tmp_path)  # an example that writes files writes them here
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0, f"{name}: its example's output differs from the docstring (doctest report above)"
    lrchain.set_progress(None)
