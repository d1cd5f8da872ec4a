"""modes, simulate and pullin: the files the commands write with --out, as arrays and dicts; Ctrl-C."""

import json
import os
import signal
import threading

import numpy as np
import pytest

import vibroimpact as vi
from conftest import assert_column_equals_cells, read_csv, run_cli


def test_simulate_returns_the_files_of_simulate_out(small_case, vi_exe, tmp_path):
    run = vi.simulate(vi.Case.from_file(str(small_case)))
    out = tmp_path / "sim"
    run_cli(vi_exe, "simulate", small_case, "--out", out)
    for name in ("history", "events"):
        cli = read_csv((out / f"{name}.csv").read_text())
        assert list(run[name]) == list(cli), name
        for column, cells in cli.items():
            assert_column_equals_cells(column, run[name][column], cells)
    assert run["summary"] == json.loads((out / "summary.json").read_text())
    assert run["history"]["t_s"].dtype == np.float64 and len(run["history"]["t_s"]) > 100


def test_modes_returns_the_files_of_modes_out(small_case, vi_exe, tmp_path):
    result = vi.modes(vi.Case.from_file(str(small_case)), count=3, support_model="spring")
    out = tmp_path / "modes"
    run_cli(vi_exe, "modes", small_case, "--count", "3", "--support-model", "spring", "--out", out)
    assert set(result) == {p.stem for p in out.iterdir()}
    assert result["modes"] == json.loads((out / "modes.json").read_text())
    cli = read_csv((out / "frequencies.csv").read_text())
    for column, cells in cli.items():
        assert_column_equals_cells(column, result["frequencies"][column], cells)
    with pytest.raises(vi.InputError):
        vi.modes(vi.Case.from_file(str(small_case)), support_model="glue")


def test_pullin_returns_the_files_of_pullin_out(source_dir, vi_exe, tmp_path):
    path = source_dir / "examples/switch/cantilever_switch.toml"
    result = vi.pullin(vi.Case.from_file(str(path)), steps=60)
    out = tmp_path / "pullin"
    run_cli(vi_exe, "pullin", path, "--steps", "60", "--out", out)
    assert result["pullin"] == json.loads((out / "pullin.json").read_text())
    cli = read_csv((out / "pullin_branch.csv").read_text())
    for column, cells in cli.items():
        assert_column_equals_cells(column, result["pullin_branch"][column], cells)


def test_a_run_that_cannot_start_names_the_key_in_the_file(small_case):
    case = vi.Case.from_file(str(small_case))
    with pytest.raises(vi.InputError) as e:
        vi.pullin(case)  # no electrode
    assert e.value.file == str(small_case)


def test_ctrl_c_stops_a_sweep_and_the_next_run_works(source_dir):
    case = vi.Case.from_file(str(source_dir / "examples/paper/free_impact_tip.toml"))
    # 100000 full-size points: far beyond the CTest timeout unless the interrupt stops the sweep.
    # Python's own SIGINT handler, as in an interactive session (a process started in the background
    # by a shell has SIGINT ignored, and then Python installs none).
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            vi.sweep(case, {"supports[0].position": "0.5:1:100000"}, threads=2)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    small = vi.sweep(case, {"supports[0].position": "0.9,1"}, threads=1)["table"]
    assert (small["status"] == "ok").all()
