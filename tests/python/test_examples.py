"""The scripts in examples/python run (shortened) and each writes its PNG."""

import os
import subprocess
import sys

import pytest

EXAMPLES = [
    ("fig2_regime_map.py", ["--pixels", "120"], "fig2_regime_map.png"),
    ("exp1_bright_breather.py", ["--periods", "20"], "exp1_bright_breather.png"),
    ("dark_branch_floquet.py", ["--points", "4", "--sites", "41"], "dark_branch_floquet.png"),
]


@pytest.mark.parametrize("script, options, png", EXAMPLES)
def test_example_writes_png(source_dir, tmp_path, script, options, png):
    path = source_dir / "examples" / "python" / script
    done = subprocess.run([sys.executable, str(path), "--out", str(tmp_path), *options], capture_output=True,
                          text=True, env=os.environ.copy(), check=False)
    assert done.returncode == 0, done.stderr
    image = tmp_path / png
    assert image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and image.stat().st_size > 10_000
