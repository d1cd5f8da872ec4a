"""The package's API: units in set, paths as os.PathLike, load's path-or-text rule, to_dict, tables
with to_pandas, __version__, and the option and key of a setting's error."""

import json
import pathlib
import re

import numpy as np
import pytest

import vibroimpact as vi
from conftest import SOURCE_DIR, read_csv, run_cli


def test_set_takes_a_value_with_its_unit_as_sweep_set_does(small_case, vi_exe):
    case = vi.Case.from_file(small_case)
    case.set("supports[0].gap", "0.5 um")
    case.set("supports[0].stiffness", "2 kN/m")
    case.update({"beam.thickness": "1.5um", "material.youngs_modulus": "180 GPa"})
    assert case.get("supports[0].gap") == pytest.approx(0.5e-6, rel=1e-15)
    assert case.get("beam.thickness") == pytest.approx(1.5e-6, rel=1e-15)
    # The command line reads the same texts to the same doubles (its sweep.csv columns).
    cli = read_csv(run_cli(vi_exe, "sweep", small_case, "--set", "supports[0].gap=0.5 um", "--set", "supports[0].stiffness=2 kN/m",
                           "--set", "beam.thickness=1.5um", "--set", "material.youngs_modulus=180 GPa"))
    assert float(cli["supports[0].gap_m"][0]) == case.get("supports[0].gap")
    assert float(cli["supports[0].stiffness_n_m"][0]) == case.get("supports[0].stiffness") == 2000.0
    assert float(cli["beam.thickness_m"][0]) == case.get("beam.thickness")
    assert float(cli["material.youngs_modulus_pa"][0]) == case.get("material.youngs_modulus")
    # A plain float is SI, as before; an int is a number too.
    case.set("supports[0].gap", 7e-7)
    assert case.get("supports[0].gap") == 7e-7
    case.set("beam.elements", 12)
    assert case.get("beam.elements") == 12


def test_a_wrong_unit_names_the_key_and_its_line_and_leaves_the_case(small_case):
    case = vi.Case.from_file(small_case)
    with pytest.raises(vi.InputError) as e:
        case.set("supports[0].gap", "0.5 GPa")
    assert e.value.key == "supports[0].gap"
    assert e.value.file == str(small_case)
    assert e.value.line == small_case.read_text().splitlines().index('gap = "0 um"') + 1
    assert "expected a length" in e.value.reason and e.value.option is None
    assert case.get("supports[0].gap") == 0.0
    with pytest.raises(vi.InputError) as e:
        case.update({"supports[0].stiffness": "5 N/m", "beam.thickness": object()})
    assert e.value.key == "beam.thickness" and "a number (SI units) or a text" in e.value.reason
    assert case.get("supports[0].stiffness") == 1000.0


def test_every_file_argument_takes_a_path_object(small_case, tmp_path):
    by_path = vi.Case.from_file(small_case)
    assert isinstance(small_case, pathlib.Path) and by_path.file == str(small_case)
    assert vi.simulate(small_case)["summary"] == vi.simulate(str(small_case))["summary"] == vi.simulate(by_path)["summary"]
    assert vi.modes(small_case, count=2)["modes"] == vi.modes(by_path, count=2)["modes"]
    table = vi.sweep(small_case, {"supports[0].position": "0.9,1"})["table"]
    assert table["status"].tolist() == ["ok", "ok"]
    text_case = vi.Case.from_string(small_case.read_text(), source=tmp_path / "named.toml")
    assert text_case.file == str(tmp_path / "named.toml")


def test_load_tells_a_path_from_text_by_a_line_break(small_case, tmp_path):
    folder = tmp_path / "runs" / "kc=500"
    folder.mkdir(parents=True)
    path = folder / "case.toml"
    path.write_text(small_case.read_text())
    # '=' in a path no longer makes it TOML text: a str without a line break is a path.
    assert vi.load(str(path)).file == str(path)
    assert vi.load(path).file == str(path)
    assert vi.load(small_case.read_text()).file == "<string>"
    with pytest.raises(vi.InputError) as e:
        vi.load(str(tmp_path / "no=such.toml"))
    assert e.value.file == str(tmp_path / "no=such.toml") and "cannot read file" in e.value.reason
    with pytest.raises(TypeError):
        vi.load(3.5)


def test_to_dict_is_the_toml_file_and_reads_back_to_the_same_case(small_case):
    import tomllib

    case = vi.Case.from_file(small_case)
    case.set("supports[0].stiffness", "2.5 kN/m")
    data = case.to_dict()
    assert data == tomllib.loads(case.to_toml())
    assert data["supports"][0]["stiffness"] == 2500.0 and data["beam"]["elements"] == 10
    back = vi.Case.from_dict(data)
    assert back.to_toml() == case.to_toml()


def test_results_are_tables_of_arrays_with_to_pandas(small_case):
    run = vi.simulate(small_case)
    history = run["history"]
    assert isinstance(history, vi.Table) and isinstance(history, dict)
    assert all(isinstance(a, np.ndarray) for a in history.values())
    assert isinstance(run["summary"], dict) and not isinstance(run["summary"], vi.Table)
    pandas = pytest.importorskip("pandas", reason="pandas is not installed (Debian: python3-pandas)")
    frame = history.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(history) and len(frame) == len(history["t_s"])
    assert (frame["tip_m"].to_numpy() == history["tip_m"]).all()
    table = vi.sweep(small_case, {"supports[0].position": "0.8,1"})["table"]
    sweep_frame = table.to_pandas()
    assert sweep_frame["impacts"].dtype == np.int64 and sweep_frame["status"].tolist() == ["ok", "ok"]


def test_to_pandas_says_what_to_install_without_pandas(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="python3-pandas"):
        vi.Table({"t_s": np.zeros(2)}).to_pandas()


def test_the_version_is_the_projects():
    written = re.findall(r"project\(vibroimpact VERSION ([0-9.]+)", (SOURCE_DIR / "CMakeLists.txt").read_text())
    assert vi.__version__ == written[0]


@pytest.mark.parametrize("values, key, reason", [
    ({"supports[0].position": "0.5:1"}, "supports[0].position", "a linear range is start:stop:count"),
    ({"supports[0].positio": "0.5"}, "supports[0].positio", "unknown key 'positio' in supports[i] (did you mean 'position'?)"),
    ({"supports[0].gap": "1:2:3:4"}, "supports[0].gap", None),
    (["supports[0].position=0.5,1", "supports[0].position=0.7"], "supports[0].position", None),
])
def test_a_bad_setting_names_its_option_and_key_not_a_file(small_case, values, key, reason):
    with pytest.raises(vi.InputError) as e:
        vi.sweep(small_case, values)
    assert e.value.option == "--set" and e.value.key == key
    assert e.value.file is None and e.value.line is None
    if reason is not None:
        assert e.value.reason == reason
    assert str(e.value).startswith("--set " + key + "=")


def test_the_setting_errors_of_uq_fit_and_optimize_name_their_option(small_case, tmp_path):
    with pytest.raises(vi.InputError) as e:
        vi.uq(small_case, {"supports[0].stiffness": "normal:1:2:3"}, samples=4)
    assert (e.value.option, e.value.key, e.value.file) == ("--vary", "supports[0].stiffness", None)
    with pytest.raises(vi.InputError) as e:
        vi.optimize(small_case, {"supports[0].position": "1:0.5"}, minimize="z_max")
    assert (e.value.option, e.value.key, e.value.reason) == ("--vary", "supports[0].position", "LOW must be below HIGH")
    data = tmp_path / "d.csv"
    data.write_text("t_s,tip_m\n0,1e-6\n1e-6,0.9e-6\n2e-6,0.8e-6\n")
    with pytest.raises(vi.InputError) as e:
        vi.fit(small_case, ["supports[0].stiffness=1:0.5:2"], data=data)
    assert (e.value.option, e.value.key) == ("--fit", "supports[0].stiffness")
