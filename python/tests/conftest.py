"""Shared fixtures: the command line (VI_EXE), the source tree (VI_SOURCE_DIR) and a small, fast case.

CTest sets VI_EXE, VI_SOURCE_DIR and PYTHONPATH (the build's python/ folder); see python/CMakeLists.txt.
"""

import csv
import io
import math
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("VI_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def vi_exe():
    exe = os.environ.get("VI_EXE")
    if not exe:
        pytest.skip("VI_EXE (the vibroimpact command) is not set; run through ctest")
    return exe


@pytest.fixture()
def small_case(tmp_path):
    """The paper's free-impact example at 10 elements over 40 us (a run takes milliseconds), as a file."""
    text = (SOURCE_DIR / "examples/paper/free_impact_tip.toml").read_text()
    for old, new in (("elements = 50", "elements = 10"), ('horizon = "150 us"', 'horizon = "40 us"')):
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / "small.toml"
    path.write_text(text)
    return path


def run_cli(exe, *args):
    """Runs the command line; returns its stdout, failing the test on a non-zero exit."""
    r = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return r.stdout


def read_csv(text):
    """A CSV text as {column: [cells as text]}."""
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def assert_column_equals_cells(name, array, cells):
    """Every value of a numpy column equals the CSV cell read back ("nan", the missing marker: NaN), exactly."""
    assert len(array) == len(cells), name
    for i, (value, cell) in enumerate(zip(array.tolist(), cells)):
        if isinstance(value, str):
            assert value == cell, (name, i)
        elif cell == "":
            assert math.isnan(value), (name, i, value)
        elif isinstance(value, int):
            assert value == int(cell), (name, i)
        else:
            expected = float(cell)
            assert value == expected or (math.isnan(value) and math.isnan(expected)), (name, i, value, cell)
