"""uq(): the same summary as `vibroimpact uq` writes to uq.json, and the same table as samples.csv."""

import json

import numpy as np
import pytest

import vibroimpact as vi
from conftest import assert_column_equals_cells, read_csv, run_cli


def test_uq_equals_the_command_line(source_dir, vi_exe, tmp_path):
    case_file = source_dir / "tests/cases/full_electrode_cantilever.toml"
    vary = {"beam.thickness": "lognormal:2um:0.03", "electrodes[0].gap": "lognormal:2um:0.04"}
    result = vi.uq(vi.Case.from_file(str(case_file)), vary, analysis="pullin", samples=32, method="sobol",
                   sensitivity=True, specs=["pullin_voltage_v<=60"], threads=2)
    run_cli(vi_exe, "uq", case_file, "--analysis", "pullin", "--vary", "beam.thickness=lognormal:2um:0.03",
            "--vary", "electrodes[0].gap=lognormal:2um:0.04", "--samples", "32", "--method", "sobol",
            "--sensitivity", "--spec", "pullin_voltage_v<=60", "--out", tmp_path / "uq")
    cli = json.loads((tmp_path / "uq" / "uq.json").read_text())
    summary = result["summary"]
    cli.pop("case")
    summary.pop("case")
    assert summary == cli
    table = result["table"]
    assert all(isinstance(a, np.ndarray) and len(a) == 32 * 4 for a in table.values())
    for name, cells in read_csv((tmp_path / "uq" / "samples.csv").read_text()).items():
        assert_column_equals_cells(name, table[name], cells)
    sobol = summary["columns"]["pullin_voltage_v"]["sobol"]
    assert set(sobol) == {"beam.thickness", "electrodes[0].gap"}


def test_uq_refuses_bad_input(source_dir):
    case = vi.Case.from_file(str(source_dir / "tests/cases/full_electrode_cantilever.toml"))
    with pytest.raises(vi.InputError, match="unknown distribution 'gauss'"):
        vi.uq(case, {"beam.thickness": "gauss:2um:1um"}, analysis="pullin")
    with pytest.raises(vi.InputError, match="at least 32 base samples"):
        vi.uq(case, {"beam.thickness": "normal:2um:0.1um"}, analysis="pullin", samples=16, sensitivity=True)
