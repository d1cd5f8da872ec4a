"""sweep(): the same table as `vibroimpact sweep` writes, and the --set forms."""

import numpy as np
import pytest

import vibroimpact as vi
from conftest import assert_column_equals_cells, read_csv, run_cli


def test_twenty_point_sweep_equals_the_command_line_csv(small_case, vi_exe):
    case = vi.Case.from_file(str(small_case))
    result = vi.sweep(case, {"supports[0].position": "0.6:1:20"}, threads=2)
    table = result["table"]
    cli = read_csv(run_cli(vi_exe, "sweep", small_case, "--set", "supports[0].position=0.6:1:20", "--threads", "2"))
    assert list(table) == list(cli), "the same columns in the same order"
    assert all(isinstance(a, np.ndarray) and len(a) == 20 for a in table.values())
    for name, cells in cli.items():
        assert_column_equals_cells(name, table[name], cells)
    assert (table["status"] == "ok").all()
    assert table["impacts"].dtype == np.int64
    assert table["T_s"].dtype == np.float64
    assert result["summary"]["points"] == 20 and result["summary"]["ok"] == 20


def test_two_axes_and_list_values_give_the_grid_of_the_command_line(small_case, vi_exe):
    case = vi.Case.from_file(str(small_case))
    table = vi.sweep(case, {"supports[0].position": [0.6, 0.8, 1.0], "supports[0].stiffness": "500,1000"})["table"]
    cli = read_csv(run_cli(vi_exe, "sweep", small_case, "--set", "supports[0].position=0.6,0.8,1",
                           "--set", "supports[0].stiffness=500,1000"))
    for name, cells in cli.items():
        assert_column_equals_cells(name, table[name], cells)
    # The last axis varies fastest.
    assert table["supports[0].stiffness_n_m"].tolist() == [500.0, 1000.0] * 3
    assert table["supports[0].position_over_l"].tolist() == [0.6, 0.6, 0.8, 0.8, 1.0, 1.0]


def test_modes_sweep(small_case):
    case = vi.Case.from_file(str(small_case))
    table = vi.sweep(case, ["supports[0].position=0.5,1"], analysis="modes", modes=2)["table"]
    assert table["f_supported_1_hz"].shape == (2,)
    assert (table["f_supported_1_hz"] > table["f_unsupported_1_hz"]).all()


def test_a_bad_path_is_an_input_error_naming_the_key(small_case):
    case = vi.Case.from_file(str(small_case))
    with pytest.raises(vi.InputError) as e:
        vi.sweep(case, {"supports[0].foo": "0.5"})
    assert e.value.key == "supports[0].foo"
    assert "unknown key" in e.value.reason
    with pytest.raises(vi.InputError):
        vi.sweep(case, {"supports[0].position": "0.5"}, analysis="transient")


def test_pullin_and_stiction_sweeps_equal_the_command_line_csv(source_dir, vi_exe):
    for analysis, path, setting in [
        ("pullin", "tests/cases/full_electrode_cantilever.toml", "beam.thickness=1.8um,2um"),
        ("stiction", "examples/switch/cantilever_stiction.toml", "supports[0].work_of_adhesion=0.2,0.5"),
    ]:
        case_file = source_dir / path
        table = vi.sweep(vi.Case.from_file(str(case_file)), [setting], analysis=analysis)["table"]
        cli = read_csv(run_cli(vi_exe, "sweep", case_file, "--analysis", analysis, "--set", setting))
        assert list(table) == list(cli)
        for name, cells in cli.items():
            assert_column_equals_cells(name, table[name], cells)
    assert table["stuck"].tolist() == [0, 1]
