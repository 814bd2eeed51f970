"""Model files are data in Python too (issue 25): lrchain.load_model refuses a device, a FIFO, a
directory or a control character in a model file's strings with lrchain.InputError naming the file
(no marker file: nothing of the file runs), and warns (RuntimeWarning) when the model is evaluated
through the GiNaC fallback because no compiler is found, as the CLI does on stderr."""

import os
import time

import pytest

import lrchain

MODEL = """\
name = "{name}"
description = "{description}"
[parameters]
k = {{ default = "1/5", range = "[0, inf)" }}
q = {{ default = 1, range = "(0, inf)" }}
s = {{ default = "1/3" }}
[[field]]
name = "u"
mass = "1"
force = "k*(u[n+1] - 2*u[n] + u[n-1]) - (q^2*u[n] + s*u[n]^3)"
"""


@pytest.mark.parametrize("control", ["\\n", "\\r", "\\u0000", "\\u001b", "\\u007f"])
def test_control_character_in_description_is_refused_and_runs_nothing(tmp_path, monkeypatch, control):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    marker = tmp_path / "marker"
    code = f'#include <cstdlib>{control}static int m = std::system(\\"touch {marker}\\");{control}//'
    path = tmp_path / "m.toml"
    path.write_text(MODEL.format(name="hostile", description="x" + control + code))
    with pytest.raises(lrchain.InputError, match=r"m\.toml:2: key description: .*control character"):
        lrchain.load_model(path)
    assert not marker.exists()
    assert not (tmp_path / "cache" / "lrchain").exists()


def test_devices_fifos_and_directories_are_refused_at_once(tmp_path):
    fifo = tmp_path / "model.fifo"
    os.mkfifo(fifo)
    start = time.monotonic()
    with pytest.raises(lrchain.InputError, match="/dev/zero: a character device"):
        lrchain.load_model("/dev/zero")
    with pytest.raises(lrchain.InputError, match="model.fifo: a FIFO"):
        lrchain.load_model(fifo)  # no writer: a blocking open would hang here
    (tmp_path / "dir.toml").mkdir()
    with pytest.raises(lrchain.InputError, match="dir.toml: a directory"):
        lrchain.load_model(tmp_path / "dir.toml")
    big = tmp_path / "big.toml"
    big.write_text(MODEL.format(name="big", description="big") + "#" * (1 << 20))
    with pytest.raises(lrchain.InputError, match="at most 1 MiB"):
        lrchain.load_model(big)
    assert time.monotonic() - start < 10


def test_ginac_fallback_warns_as_the_cli_does(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setenv("LRCHAIN_MODEL_CXX", "/nonexistent/lrchain-no-such-c++")
    path = tmp_path / "fallback.toml"
    path.write_text(MODEL.format(name="fallback", description="GiNaC fallback"))
    with pytest.warns(RuntimeWarning, match=r"model fallback is evaluated through GiNaC .* "
                                            r"/nonexistent/lrchain-no-such-c\+\+ is not installed"):
        model = lrchain.load_model(path)
    assert model.name == "fallback"
    monkeypatch.delenv("LRCHAIN_MODEL_CXX")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # compiled: no warning
        lrchain.load_model(path)


def test_a_path_written_as_cpp_runs_nothing(tmp_path, monkeypatch, source_dir):
    # A directory and file name that end a // comment and run a command in a static initialiser (the
    # old emitted code printed the path into a comment): loading the model, its coefficients and a
    # ring run (the lattice code compiled too) create no marker; the numbers are fput's.
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.chdir(tmp_path)  # the marker's relative path

    def payload(k):
        return (f'\n#include <cstdlib>\nstatic int lrchain_marker_{k} = std::system("touch marker");\n'
                f'#define LRCHAIN_REST_{k} ')

    directory = tmp_path / ("d" + payload(1))
    directory.mkdir()
    path = directory / ("m" + payload(2) + ".toml")
    text = (source_dir / "models" / "fput.toml").read_text().replace('name = "fput"', 'name = "fput_path"')
    path.write_text(text)
    model = lrchain.load_model(path)
    shipped = lrchain.load_model("fput")
    mine, reference = (lrchain.coefficients(m, "acoustic", 1.0) for m in (model, shipped))
    assert mine.gamma == pytest.approx(reference.gamma, rel=1e-12)
    ring = lrchain.simulate.ring(model, "acoustic", 1.5707963267948966, periods=10, packet_width=12)
    assert ring is not None
    assert not (tmp_path / "marker").exists()
