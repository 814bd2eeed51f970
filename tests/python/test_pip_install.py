"""`pip install --no-build-isolation <checkout>` into a fresh virtual environment gives a working module.

The venv is created with --system-site-packages (numpy, setuptools and wheel from Debian) and pip
reuses this test build's CMake folder (LRCHAIN_CMAKE_BUILD_DIR), so that the test costs an install,
not a second build of the library. From outside the source tree, the installed module computes
coefficients equal to the build tree's, compiles a model file of its own and runs a short lattice
run; `python3 -m build --no-isolation --wheel` gives a wheel that installs into a second venv.
"""

import importlib.util
import json
import os
import subprocess
import sys
import textwrap
import venv
from pathlib import Path

import pytest

import lrchain
from conftest import SOURCE_DIR, _cli_path

BUILD = Path(lrchain.__file__).resolve().parents[2]
SOURCE = SOURCE_DIR  # ctest's LRCHAIN_SOURCE_DIR, or this checkout by hand

# A model file written for this test: a Fermi-Pasta-Ulam-Tsingou chain with cubic and quartic terms.
MODEL = textwrap.dedent("""\
    name = "pip_fpu"
    [parameters]
    a = { default = "1/4" }
    b = { default = "1/2" }
    [[field]]
    name = "u"
    mass = "1"
    force = "(u[n+1]-u[n]) + a*(u[n+1]-u[n])^2 + b*(u[n+1]-u[n])^3 - (u[n]-u[n-1]) - a*(u[n]-u[n-1])^2 - b*(u[n]-u[n-1])^3"
    """)

# Runs inside the installed module, outside the source tree; prints one JSON line.
PROBE = textwrap.dedent("""\
    import json, sys, math
    import lrchain
    c = lrchain.coefficients(lrchain.Params(rho=1/3), "optical", math.pi / 2)
    m = lrchain.load_model(sys.argv[1])
    k = lrchain.coefficients(m, "acoustic", math.pi / 2)
    run = lrchain.simulate.ring(m, "acoustic", math.pi / 2, amplitudes=[0.01], sites=32, periods=10)
    print(json.dumps({"file": lrchain.__file__, "version": lrchain.__version__,
                      "version_line": lrchain.provenance()["version_line"],
                      "omega": c.omega, "model_omega": float(k.omega), "ring_rows": len(run.amplitude)}))
    """)


def make_venv(where):
    venv.EnvBuilder(system_site_packages=True, with_pip=True, clear=True).create(where)
    return where / "bin" / "python"


def pip_env():
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_REQUIRE_VIRTUALENV")}
    env.update(LRCHAIN_CMAKE_BUILD_DIR=str(BUILD), PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1",
               XDG_CACHE_HOME=str(Path(env.get("TMPDIR", "/tmp")) / "lrchain-pip-test-cache"))
    return env


def probe(python, workdir, env):
    model = workdir / "pip_fpu.toml"
    model.write_text(MODEL)
    script = workdir / "probe.py"
    script.write_text(PROBE)
    (workdir / "cache").mkdir(exist_ok=True)
    env = dict(env, XDG_CACHE_HOME=str(workdir / "cache"))  # the compiled model goes to a cache of its own
    done = subprocess.run([str(python), str(script), str(model)], cwd=workdir, env=env, capture_output=True,
                          text=True, check=False, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


def check_probe(result, venv_dir):
    assert Path(result["file"]).resolve().is_relative_to(venv_dir.resolve())
    assert result["version"] == lrchain.__version__
    cli = subprocess.run([str(_cli_path()), "--version"], capture_output=True, text=True, check=True)
    assert result["version_line"] == cli.stdout.strip()
    # The same compiled code as the build tree's module: bit-equal omega.
    assert result["omega"] == lrchain.coefficients(lrchain.Params(rho=1 / 3), "optical", 1.5707963267948966).omega
    # FPU dispersion omega = 2 sin(theta/2) (textbook; unit masses and springs): sqrt(2) at theta = pi/2.
    assert result["model_omega"] == pytest.approx(2 ** 0.5, rel=1e-12)
    assert result["ring_rows"] == 1


def test_pip_install_into_fresh_venv(tmp_path):
    python = make_venv(tmp_path / "venv")
    env = pip_env()
    done = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation", str(SOURCE)], env=env,
                          cwd=tmp_path, capture_output=True, text=True, check=False, timeout=1800)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    check_probe(probe(python, tmp_path, env), tmp_path / "venv")


@pytest.mark.skipif(importlib.util.find_spec("build") is None, reason="python3-build (Debian) is not installed")
def test_wheel_from_python_build_installs(tmp_path):
    env = pip_env()
    dist = tmp_path / "dist"
    done = subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--wheel", "--outdir", str(dist),
                           str(SOURCE)], env=env, cwd=tmp_path, capture_output=True, text=True, check=False,
                          timeout=1800)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    wheels = list(dist.glob("lrchain-*.whl"))
    assert len(wheels) == 1 and wheels[0].name.endswith("linux_x86_64.whl"), wheels
    python = make_venv(tmp_path / "venv")
    done = subprocess.run([str(python), "-m", "pip", "install", str(wheels[0])], env=env, cwd=tmp_path,
                          capture_output=True, text=True, check=False, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    check_probe(probe(python, tmp_path, env), tmp_path / "venv")
