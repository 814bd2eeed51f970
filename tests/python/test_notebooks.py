"""The notebooks of examples/notebooks run top to bottom without error (nbclient, Debian
python3-nbclient and python3-ipykernel), each within its time limit, and are kept without outputs."""

import importlib.util
import time

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
if importlib.util.find_spec("ipykernel") is None:  # not imported here: lrchain would think it runs in a kernel
    pytest.skip("ipykernel (Debian python3-ipykernel) is not installed", allow_module_level=True)
pytest.importorskip("xarray")
pytest.importorskip("matplotlib")

from conftest import SOURCE_DIR, _cli_path  # noqa: E402  (ctest's LRCHAIN_SOURCE_DIR, or this checkout by hand)

NOTEBOOKS = sorted((SOURCE_DIR / "examples" / "notebooks").glob("*.ipynb"))


def test_there_are_three_notebooks():
    assert [p.name[:2] for p in NOTEBOOKS] == ["1_", "2_", "3_"]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_stripped(path):
    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            assert cell.outputs == [] and cell.execution_count is None, f"{path.name}: outputs are kept"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs(path, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    monkeypatch.setenv("LRCHAIN_CLI", str(_cli_path()))  # notebook 3 runs the command-line tool
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))  # a model file compiled afresh, into a cache of its own
    nb = nbformat.read(path, as_version=4)
    start = time.monotonic()
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert not errors
    assert time.monotonic() - start < 300
