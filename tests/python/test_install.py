"""`cmake --install` puts an importable package into site-packages under the install prefix."""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import lrchain


def test_installed_package_imports(tmp_path):
    build = Path(lrchain.__file__).resolve().parents[2]
    cache = (build / "CMakeCache.txt").read_text()
    site = re.search(r"^LRCHAIN_PYTHON_INSTALL_DIR:\w+=(.*)$", cache, re.M).group(1)
    cmake = os.environ.get("LRCHAIN_CMAKE") or shutil.which("cmake")
    done = subprocess.run([cmake, f"-DCMAKE_INSTALL_PREFIX={tmp_path}", "-P", str(build / "python" / "cmake_install.cmake")],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    package = tmp_path / site / "lrchain"
    assert (package / "__init__.py").is_file()
    # The run-time model compiler's module is installed next to the main one when the build has it.
    built = sorted(p.name for p in (build / "python" / "lrchain").glob("_*.so"))
    assert sorted(p.name for p in package.glob("_*.so")) == built
    assert (package / "model.py").is_file() and (package / "hdf5.py").is_file()
    # lrchain.reproduce's executable: a relative link to the installed <prefix>/bin/lrchain
    link = package / "bin" / "lrchain"
    assert link.is_symlink() and not os.path.isabs(os.readlink(link))
    assert (link.parent / os.readlink(link)).resolve() == (tmp_path / "bin" / "lrchain").resolve()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(tmp_path / site)
    code = ("import lrchain; c = lrchain.coefficients(lrchain.Params(rho=1/3), 'optical', 1.5707963267948966); "
            "print(lrchain.__file__); print(c.regime, repr(c.omega))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path, check=False)
    assert run.returncode == 0, run.stderr
    where, values = run.stdout.splitlines()
    assert Path(where).resolve().is_relative_to(package.resolve())
    # Same number as the build tree's module (the same compiled code).
    expected = lrchain.coefficients(lrchain.Params(rho=1 / 3), "optical", 1.5707963267948966)
    assert values == f"focusing {expected.omega!r}"
