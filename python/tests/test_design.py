"""fit, optimize and paper: the same results as the commands write (fit.json, optimize.json,
evaluations.csv, claims.json and the figures' CSV files)."""

import json
import re

import numpy as np
import pytest

import vibroimpact as vi
from conftest import assert_column_equals_cells, read_csv, run_cli


@pytest.fixture()
def measured(small_case, tmp_path):
    """A tip trajectory of the small case with a contact stiffness of 1500 N/m (the file says 1000),
    every 4th sample of the first 30 us, with noise of 2 nm from a fixed seed."""
    truth = vi.Case.from_file(small_case)
    truth.set("supports[0].stiffness", "1500 N/m")
    history = vi.simulate(truth)["history"]
    keep = (history["t_s"] <= 30e-6) & (np.arange(len(history["t_s"])) % 4 == 0)
    t, tip = history["t_s"][keep], history["tip_m"][keep]
    tip = tip + 2e-9 * np.random.default_rng(5).standard_normal(len(tip))
    path = tmp_path / "measured.csv"
    path.write_text("t_s,tip_m\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(t.tolist(), tip.tolist())))
    return path


def without_command(j):
    return {k: v for k, v in j.items() if k != "command"}


def test_fit_recovers_the_stiffness_and_equals_the_command(small_case, measured, vi_exe, tmp_path):
    result = vi.fit(small_case, {"supports[0].stiffness": (300.0, 5000.0)}, data=measured, threads=1)
    out = tmp_path / "fit"
    run_cli(vi_exe, "fit", small_case, "--data", measured, "--fit", "supports[0].stiffness=300:5000", "--threads", "1",
            "--out", out, "--progress", "none")
    cli = json.loads((out / "fit.json").read_text())
    assert without_command(result["fit"]) == without_command(cli)
    for column, cells in read_csv((out / "fit_residuals.csv").read_text()).items():
        assert_column_equals_cells(column, result["fit_residuals"][column], cells)
    (estimate,) = result["fit"]["parameters"]
    assert result["fit"]["converged"]
    # The truth lies within the 95 % interval, which is narrow (noise 2 nm on a 1 um motion).
    assert estimate["ci95"][0] < 1500.0 < estimate["ci95"][1]
    assert estimate["std_error"] < 0.02 * 1500.0
    assert "Fit of " in result["text"] and "supports[0].stiffness" in result["text"]


def test_optimize_equals_the_command(small_case, vi_exe, tmp_path):
    result = vi.optimize(small_case, ["supports[0].position=0.6:1"], minimize="z_max", max_evals=8, threads=1)
    out = tmp_path / "opt"
    run_cli(vi_exe, "optimize", small_case, "--vary", "supports[0].position=0.6:1", "--minimize", "z_max",
            "--max-evals", "8", "--threads", "1", "--out", out, "--progress", "none")
    cli = json.loads((out / "optimize.json").read_text())
    for j in (result["optimize"], cli):
        j.pop("command")
        j["run"].pop("wall_s")
        j["run"].pop("look_ahead_s")
    assert result["optimize"] == cli
    for column, cells in read_csv((out / "evaluations.csv").read_text()).items():
        assert_column_equals_cells(column, result["evaluations"][column], cells)
    best = result["optimize"]["best"]
    z = result["evaluations"]["z_max"]
    assert best["objective"] == np.nanmin(z[result["evaluations"]["feasible"] == 1])
    # A dict of bounds is the same problem.
    again = vi.optimize(small_case, {"supports[0].position": (0.6, 1.0)}, minimize="z_max", max_evals=8, threads=1)
    assert again["optimize"]["best"] == best
    with pytest.raises(vi.InputError, match="one of --minimize or --maximize"):
        vi.optimize(small_case, ["supports[0].position=0.6:1"])


def test_paper_gives_the_claims_and_figure_data_of_the_command(vi_exe, tmp_path, capsys):
    options = dict(positions=3, modal_positions=4, prestress_points=2, scan_horizon="100 us", threads=2)
    result = vi.paper(out=tmp_path / "py", progress="lines", progress_interval=0, **options)
    # Its progress as the command's: the jobs counted to their total, and a line as each part ends.
    err = capsys.readouterr().err.splitlines()
    counts = [re.fullmatch(r"paper: (\d+)/(\d+) jobs, .*, elapsed [\d:]+", line) for line in err]
    done = [(int(m.group(1)), int(m.group(2))) for m in counts if m]
    assert done and done[-1][0] == done[-1][1] and [d for d, _ in done] == sorted(d for d, _ in done), err
    assert any(line.startswith("paper: [") for line in err), err
    assert all(m or line.startswith("paper: [") for m, line in zip(counts, err)), err
    run_cli(vi_exe, "paper", "--positions", "3", "--modal-positions", "4", "--prestress-points", "2", "--scan-horizon",
            "100 us", "--threads", "2", "--out", tmp_path / "cli", "--progress", "none")
    cli_claims = json.loads((tmp_path / "cli" / "claims.json").read_text())
    assert result["claims"] == cli_claims
    assert json.loads((tmp_path / "py" / "claims.json").read_text()) == cli_claims
    assert (tmp_path / "py" / "report.html").stat().st_size > 0 and (tmp_path / "py" / "fig4.png").exists()
    for figure, data in result["figures"].items():
        for name, table in data.items():
            assert isinstance(table, vi.Table)
            for column, cells in read_csv((tmp_path / "cli" / f"{name}.csv").read_text()).items():
                assert_column_equals_cells(column, table[column], cells)
    assert {"fig2", "fig3", "fig4", "fig11"} <= set(result["figures"])
    # Without a folder nothing is drawn or written, and the claims are the same.
    assert vi.paper(**options)["claims"] == cli_claims
