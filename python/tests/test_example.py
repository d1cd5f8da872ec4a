"""examples/python/sweep_plot.py runs and draws its figure (matplotlib, Agg backend)."""

import subprocess
import sys

import pytest


def test_sweep_plot_example_writes_a_png(source_dir, small_case, tmp_path):
    pytest.importorskip("matplotlib")
    png = tmp_path / "sweep.png"
    r = subprocess.run([sys.executable, str(source_dir / "examples/python/sweep_plot.py"), str(small_case),
                        "--points", "6", "--out", str(png)], capture_output=True, text=True, timeout=600,
                       env={**__import__("os").environ, "MPLBACKEND": "Agg"})
    assert r.returncode == 0, r.stderr
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "6 points" in r.stdout
