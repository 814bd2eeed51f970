"""`pip install .`: builds the Python module lrchain with CMake and packages it.

CMake builds the compiled modules (_lrchain, _hdf5, _model_compiler) and assembles the package in
<build>/python/lrchain; this script copies that folder into the wheel. The CMake build folder is
build-python/ in the checkout, kept between installs so that a second install only rebuilds what
changed; LRCHAIN_CMAKE_BUILD_DIR names another (e.g. an existing Release build folder), and
LRCHAIN_CMAKE_ARGS adds arguments to its configuration (split on spaces).
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent
TARGETS = ["_lrchain", "_hdf5", "_model_compiler"]
SETUPTOOLS_DIR = SOURCE / "build-python" / "setuptools"
SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)


def project_version():
    """The version of project(lrchain VERSION x.y.z) in CMakeLists.txt."""
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(lrchain VERSION ([0-9.]+)", text).group(1)


def cmake_build_dir():
    named = os.environ.get("LRCHAIN_CMAKE_BUILD_DIR")
    return Path(named).resolve() if named else SOURCE / "build-python"


class CMakeBuild(build_ext):
    """Runs CMake instead of compiling sources itself."""

    def run(self):
        build = cmake_build_dir()
        cmake = shutil.which("cmake") or "cmake"
        if not (build / "CMakeCache.txt").is_file():
            configure = [cmake, "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                         f"-DPython3_EXECUTABLE={sys.executable}", "-DLRCHAIN_BUILD_TESTS=OFF",
                         "-DLRCHAIN_BUILD_BENCH=OFF"]
            configure += os.environ.get("LRCHAIN_CMAKE_ARGS", "").split()
            subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        cache = (build / "CMakeCache.txt").read_text()
        targets = [t for t in TARGETS if t != "_model_compiler" or "LRCHAIN_BUILD_DERIVATION:BOOL=ON" in cache]
        subprocess.run([cmake, "--build", str(build), "--target", *targets, "-j", jobs], check=True)
        package = Path(self.build_lib) / "lrchain"
        if package.exists():
            shutil.rmtree(package)
        shutil.copytree(build / "python" / "lrchain", package,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))


setup(
    name="lrchain",
    version=project_version(),
    description="Nonlinear waves in one-dimensional lattices: NLS coefficients, regime maps, "
                "lattice runs and exact breathers for any lattice given as a model file",
    license="MIT",
    python_requires=">=3.9",
    install_requires=["numpy"],
    # One placeholder extension: it makes the wheel platform-specific and runs CMakeBuild.
    packages=[],  # the package comes from the CMake build (CMakeBuild), not from this folder
    ext_modules=[Extension("lrchain._lrchain", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own folders out of the checkout's build/ (a CMake build folder in the README).
    options={"build": {"build_base": str(SETUPTOOLS_DIR / "build")},
             "egg_info": {"egg_base": str(SETUPTOOLS_DIR)}},
    zip_safe=False,
)
