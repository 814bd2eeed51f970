"""lrchain.load_model from several threads (issue 25): GiNaC and CLN are not thread-safe, so the C++
compile path holds one process-wide lock around derivation, emission, compilation and the GiNaC
fallback evaluators. 8 threads load the same new model and different new models, 20 repetitions
(through the GiNaC fallback, where every load derives: no compiler is found), then with the compiler:
no crash, and every thread gets the numbers of its model (the textbook Klein-Gordon dispersion
omega^2 = q^2 + 4 k sin^2(theta/2), and the same bits for the same file)."""

import threading

import numpy as np
import pytest

import lrchain

THETA = np.linspace(0.05, np.pi, 33)


def model_text(name, q):
    return f"""\
name = "{name}"
description = "Klein-Gordon chain for the thread test"
[parameters]
k = {{ default = "1/5", range = "[0, inf)" }}
q = {{ default = "{q}", range = "(0, inf)" }}
s = {{ default = "1/3" }}
[[field]]
name = "u"
mass = "1"
force = "k*(u[n+1] - 2*u[n] + u[n-1]) - (q^2*u[n] + s*u[n]^3)"
"""


def expected_omega(q):
    # Textbook linear dispersion of the discrete Klein-Gordon chain, k = 1/5.
    return np.sqrt(q**2 + 4 * 0.2 * np.sin(THETA / 2) ** 2)


def load_in_threads(paths_and_q):
    """Loads every (path, q) in its own thread, all released at once; returns omegas and errors."""
    barrier = threading.Barrier(len(paths_and_q))
    results, errors = [None] * len(paths_and_q), []

    def work(i, path):
        try:
            barrier.wait()
            model = lrchain.load_model(path)
            results[i] = lrchain.coefficients(model, "branch0", THETA)
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(repr(e))

    threads = [threading.Thread(target=work, args=(i, p)) for i, (p, _) in enumerate(paths_and_q)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return results, errors


def run_repetitions(tmp_path, repetitions):
    for rep in range(repetitions):
        # 4 threads on one new file, 4 on new files of their own (new bytes every repetition).
        same = tmp_path / f"same_{rep}.toml"
        same.write_text(model_text(f"same{rep}", "3/2"))
        jobs = [(same, 1.5)] * 4
        for j in range(4):
            path = tmp_path / f"other_{rep}_{j}.toml"
            q = 1 + (j + 1) / 8
            path.write_text(model_text(f"other{rep}x{j}", f"{8 + j + 1}/8"))
            jobs.append((path, q))
        results, errors = load_in_threads(jobs)
        assert errors == []
        for (path, q), c in zip(jobs, results):
            np.testing.assert_allclose(c.omega, expected_omega(q), rtol=1e-13, atol=0)
        for c in results[1:4]:  # the same file: the same bits
            np.testing.assert_array_equal(c.omega, results[0].omega)
            np.testing.assert_array_equal(c.gamma, results[0].gamma)


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # the fallback's warning, once per load
def test_eight_threads_derive_at_once_through_the_ginac_fallback(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setenv("LRCHAIN_MODEL_CXX", "/nonexistent/lrchain-no-such-c++")
    run_repetitions(tmp_path, 20)


def test_eight_threads_compile_at_once(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    run_repetitions(tmp_path, 2)
    # Every compile left one object and one manifest per model (evaluators and kernels in one), and no temporary.
    cache = tmp_path / "cache" / "lrchain"
    assert not [p for p in cache.iterdir() if p.name.startswith(".model-")]
    assert len(list(cache.glob("model-*.so"))) == 2 * 5
    assert len(list(cache.glob("model-*.manifest"))) == 2 * 5
