"""Progress of the long calls on sys.stderr, as the commands' --progress: one line per step with
progress_interval=0 (done of total, rate, time left), a bar redrawn in place, nothing with "none";
"auto" is lines when sys.stderr is no terminal (pytest's capture, a notebook, a log); None takes
$VIBROIMPACT_PROGRESS. The tests read lines at interval 0 only, so nothing depends on the speed."""

import re

import numpy as np
import pytest

import vibroimpact as vi


def progress_lines(err, what, unit, total):
    """The counts of `what`'s progress lines in err, each checked for its form; every line of err is one."""
    form = re.compile(rf"{what}: (\d+)/{total} {unit}, (?:-|[0-9.e+-]+) {unit}/s, left (?:-|(?:at most )?(?:\d+:)?\d+:\d\d), "
                      rf"elapsed (?:\d+:)?\d+:\d\d(?:; .+)?")
    counts = []
    for line in err.splitlines():
        m = form.fullmatch(line)
        assert m, f"not a progress line of {what}: {line!r}"
        counts.append(int(m.group(1)))
    return counts


@pytest.fixture()
def measured(small_case, tmp_path):
    """The small case's tip trajectory with a contact stiffness of 1500 N/m (the file says 1000)."""
    truth = vi.Case.from_file(small_case)
    truth.set("supports[0].stiffness", "1500 N/m")
    history = vi.simulate(truth)["history"]
    keep = np.arange(len(history["t_s"])) % 4 == 0
    path = tmp_path / "measured.csv"
    path.write_text("t_s,tip_m\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(history["t_s"][keep].tolist(),
                                                                             history["tip_m"][keep].tolist())))
    return path


def fit(small_case, measured, **progress):
    return vi.fit(small_case, {"supports[0].stiffness": (300.0, 5000.0)}, data=measured, max_iterations=4, threads=1,
                  **progress)


def test_fit_writes_a_line_per_step_counting_iterations_of_its_budget(small_case, measured, capsys):
    quiet = fit(small_case, measured, progress="none")
    assert capsys.readouterr().err == ""
    result = fit(small_case, measured, progress="lines", progress_interval=0)
    counts = progress_lines(capsys.readouterr().err, "fit", "iterations", 4)
    assert counts, "no progress line"
    assert counts == sorted(counts) and counts[-1] == 4  # a converged start counts the rest of its budget as done
    assert result["fit"]["parameters"] == quiet["fit"]["parameters"]  # the report changes nothing


def test_optimize_writes_a_line_per_design_with_the_best_so_far(small_case, capsys):
    result = vi.optimize(small_case, ["supports[0].position=0.6:1"], minimize="z_max", max_evals=6, threads=1,
                         progress="lines", progress_interval=0)
    err = capsys.readouterr().err
    counts = progress_lines(err, "optimize", "designs", 6)
    used = len(result["evaluations"]["z_max"])
    assert counts == list(range(1, used + 1))
    best = result["optimize"]["best"]["objective"]
    assert err.splitlines()[-1].endswith(f"; best z_max {best:.6g}")


def test_sweep_and_uq_count_their_points(small_case, capsys):
    vi.sweep(small_case, {"supports[0].position": "0.7:1:3"}, threads=1, progress="lines", progress_interval=0)
    assert progress_lines(capsys.readouterr().err, "sweep", "points", 3) == [1, 2, 3]
    vi.uq(small_case, {"supports[0].stiffness": "normal:1000:10"}, samples=3, threads=1, bootstrap=100,
          progress="lines", progress_interval=0)
    assert progress_lines(capsys.readouterr().err, "uq", "runs", 3) == [1, 2, 3]


def test_auto_is_lines_off_a_terminal_and_bar_redraws_in_place(small_case, capsys):
    values = {"supports[0].position": "0.8,1"}
    vi.sweep(small_case, values, threads=1, progress="auto", progress_interval=0)
    assert progress_lines(capsys.readouterr().err, "sweep", "points", 2) == [1, 2]
    vi.sweep(small_case, values, threads=1, progress="bar")
    err = capsys.readouterr().err
    assert err.startswith("\r\x1b[Ksweep [") and err.endswith("\n") and err.count("\n") == 1
    assert "2/2 points" in err.rsplit("\r\x1b[K", 1)[1]


def test_none_takes_the_environment_and_a_bad_mode_is_refused(small_case, capsys, monkeypatch):
    values = {"supports[0].position": "0.8,1"}
    monkeypatch.setenv("VIBROIMPACT_PROGRESS", "none")
    vi.sweep(small_case, values, threads=1, progress_interval=0)
    assert capsys.readouterr().err == ""
    monkeypatch.setenv("VIBROIMPACT_PROGRESS", "lines")
    vi.sweep(small_case, values, threads=1, progress_interval=0)
    assert progress_lines(capsys.readouterr().err, "sweep", "points", 2) == [1, 2]
    with pytest.raises(vi.InputError, match=r'progress: must be auto, bar, lines or none \(got "yes"\)'):
        vi.sweep(small_case, values, progress="yes")
    with pytest.raises(vi.InputError, match="progress_interval"):
        vi.optimize(small_case, ["supports[0].position=0.6:1"], minimize="z_max", progress_interval=-1)
    monkeypatch.setenv("VIBROIMPACT_PROGRESS", "sometimes")
    with pytest.raises(vi.InputError, match="VIBROIMPACT_PROGRESS=sometimes: must be auto, bar, lines or none"):
        vi.optimize(small_case, ["supports[0].position=0.6:1"], minimize="z_max")
