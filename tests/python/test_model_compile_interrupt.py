"""Ctrl-C in lrchain.load_model (docs/models.md): SIGINT while a model file is derived or compiled
raises KeyboardInterrupt within about a second; the compiler's whole process group is killed (a fake
compiler's grandchild `sleep` plays cc1plus) and nothing is left in the cache. Before, load_model
ignored SIGINT until the compile ended (the compile runs without the GIL and polled nothing)."""

import os
import signal
import subprocess
import sys
import time

import lrchain

MORSE = """\
name = "morse"
description = "Morse chain for the interrupt test"
[parameters]
a = {{ default = "1", range = "(0, inf)" }}
b = {{ default = "1", range = "(0, inf)" }}
[functions.F]
argument = "r"
expression = "2*a*b*(exp(-a*r) - exp(-2*a*r))*{extra}"
[[field]]
name = "u"
mass = "1"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1])"
"""

# Mass in mass in mass; the sum of parameters in the inner springs' forces makes the derivation take
# seconds.
SLOW_THREE_FIELDS = """\
name = "mass_in_mass3_slow"
[parameters]
a1 = { default = "1/4", range = "(-inf, inf)" }
b1 = { default = "1/2", range = "(-inf, inf)" }
k2 = { default = 1, range = "(0, inf)" }
m2 = { default = "1/2", range = "(0, inf)" }
k3 = { default = "1/2", range = "(0, inf)" }
g3 = { default = 1, range = "(-inf, inf)" }
m3 = { default = "1/4", range = "(0, inf)" }
[functions.F]
argument = "r"
expression = "r + a1*r^2 + b1*r^3"
[functions.G]
argument = "s"
expression = "k3*s + g3*s^3"
[[field]]
name = "u"
mass = "1"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1]) - k2*(1 + a1 + b1)*(u[n] - v[n])"
[[field]]
name = "v"
mass = "m2"
force = "k2*(1 + a1 + b1)*(u[n] - v[n]) - G(v[n] - w[n])"
[[field]]
name = "w"
mass = "m3"
force = "G(v[n] - w[n])"
"""

FAKE_COMPILER = """\
#!/bin/sh
if [ "$1" = --version ]; then echo 'fake-cxx 1'; exit 0; fi
sleep 300 &
echo $! > {pid_file}.tmp
mv {pid_file}.tmp {pid_file}
wait
"""


def start_load_model(tmp_path, model_path, compiler):
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path / "cache"), LRCHAIN_MODEL_CXX=str(compiler),
               PYTHONPATH=os.pathsep.join(p for p in [os.path.dirname(os.path.dirname(lrchain.__file__)),
                                                      os.environ.get("PYTHONPATH", "")] if p))
    code = ("import sys, lrchain\nprint('loading', flush=True)\n"
            "try:\n    lrchain.load_model(sys.argv[1])\nexcept KeyboardInterrupt as e:\n"
            "    print('KeyboardInterrupt', e, flush=True)\n    sys.exit(7)\n")
    child = subprocess.Popen([sys.executable, "-c", code, str(model_path)], env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "loading"
    return child


def gone(pid):
    for _ in range(100):
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        with open(f"/proc/{pid}/stat") as stat:
            if stat.read().split()[2] == "Z":  # killed, waiting for init to reap it
                return True
        time.sleep(0.02)
    return False


def cache_files(tmp_path):
    cache = tmp_path / "cache" / "lrchain"
    return sorted(os.listdir(cache)) if cache.exists() else []


def test_sigint_while_compiling_raises_keyboard_interrupt_and_kills_the_compiler(tmp_path):
    pid_file = tmp_path / "cc1plus.pid"
    compiler = tmp_path / "fake-cxx.sh"
    compiler.write_text(FAKE_COMPILER.format(pid_file=pid_file))
    compiler.chmod(0o700)
    model = tmp_path / "morse.toml"
    model.write_text(MORSE.format(extra="1"))
    child = start_load_model(tmp_path, model, compiler)
    deadline = time.monotonic() + 60
    while not pid_file.exists() and time.monotonic() < deadline:
        time.sleep(0.02)
    grandchild = int(pid_file.read_text())
    start = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=30)
    elapsed = time.monotonic() - start
    assert child.returncode == 7, err
    assert out.startswith("KeyboardInterrupt")
    assert elapsed < 20  # before: not until the compiler ended (here: 300 s)
    assert gone(grandchild)
    assert cache_files(tmp_path) == []


def test_sigint_while_deriving_raises_keyboard_interrupt(tmp_path):
    # `lrchain derive` takes 16 s for this three-field model on an idle 2-core machine (measured), so
    # SIGINT at 0.7 s lands inside the derivation. (A one-field law derives in under 0.6 s.)
    model = tmp_path / "slow.toml"
    model.write_text(SLOW_THREE_FIELDS)
    child = start_load_model(tmp_path, model, tmp_path / "no-compiler-needed")
    time.sleep(0.7)
    start = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=60)
    assert child.returncode == 7, err
    assert out.startswith("KeyboardInterrupt")
    assert time.monotonic() - start < 2
    assert cache_files(tmp_path) == []
