"""The computations of the command line, in-process: each returns the files the command writes with
``--out``, CSV files as :class:`~vibroimpact.Table` and JSON files as dicts (docs/python.md).

Every function runs off the interpreter with the GIL released; Ctrl-C stops it and raises
KeyboardInterrupt. ``case`` is anything :func:`~vibroimpact.load` takes: a Case, a file path
(str or os.PathLike), TOML text or a dict.
"""

import os

from . import _vibroimpact
from .case import as_case
from .tables import tables


def modes(case, count=5, support_model="pin"):
    """Natural modes of the beam, without and with its supports (``vibroimpact modes``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The case (:func:`load`).
    count : int, optional
        Bending modes, 1 to 1000.
    support_model : {"pin", "spring"}, optional
        A support as a pin (zero displacement) or as its contact spring.

    Returns
    -------
    dict
        ``"modes"``: modes.json (frequencies in Hz); ``"frequencies"``: Table (``f_unsupported_hz``,
        ``f_supported_hz``, ...); ``"shapes_unsupported"``, ``"shapes_supported"``: Tables of the
        mode shapes along the beam (``x_over_l``, ``mode1``, ...); ``"released_shape"`` (a curled beam
        only): its released shape at the nodes (``x_over_l``, ``x_m``, ``v_m``, ``theta_rad``).
    """
    return tables(_vibroimpact.modes(as_case(case), count, support_model))


def simulate(case):
    """The free transient of a case (``vibroimpact simulate``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The case (:func:`load`).

    Returns
    -------
    dict
        ``"history"``: Table of the watched point and the contacts against time (``t_s`` [s],
        ``tip_m`` [m], ``tip_velocity_m_s`` [m/s], ``contact0_force_n`` [N], ...); ``"events"``:
        Table of contact onsets and releases; ``"summary"``: summary.json (impacts, ``T_s``,
        ``Tp_s`` [s], ...).

    Raises
    ------
    SolverError
        When the run cannot finish (numerical trouble, a bound such as ``solver.max_events``).
    """
    return tables(_vibroimpact.simulate(as_case(case)))


def pullin(case, steps=200):
    """Static pull-in of an electrostatically driven case (``vibroimpact pullin``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        A case with an electrode (:func:`load`).
    steps : int, optional
        Steps along the equilibrium branch, 10 to 100000.

    Returns
    -------
    dict
        ``"pullin"``: pullin.json (``pullin_voltage_v`` [V], the deflection there [m], ...);
        ``"pullin_branch"``: Table of the branch (voltage [V], deflection [m]);
        ``"pullin_frequencies"``: Table of the first frequencies [Hz] along it.
    """
    return tables(_vibroimpact.pullin(as_case(case), steps))


def sweep(case, values, analysis="simulate", modes=3, support_model="pin", threads=0, point_timeout=60.0, progress=None,
          progress_interval=10.0):
    """A sweep over a grid of case values (``vibroimpact sweep``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The base case (:func:`load`).
    values : dict or list of str
        ``{path: spec}``, the first path varying slowest, where spec is a ``--set`` SPEC
        (``"0.6:1:20"``, ``"log:100:1e5:20"``, ``"0.5um,0.7um"``; units as in case files, plain
        numbers SI), a number or a list of numbers [SI]; or a list of ``"PATH=SPEC"`` texts.
    analysis : {"simulate", "modes", "pullin", "stiction", "air-q"}, optional
        What each point computes (``sweep --analysis``).
    modes : int, optional
        Bending modes of a modes analysis, 1 to 100.
    support_model : {"pin", "spring"}, optional
        The supports of a modes analysis.
    threads : int, optional
        Worker threads; 0 for every CPU this process may use.
    point_timeout : float, optional
        Wall-clock limit of one point [s]; 0 for none.
    progress : {"auto", "bar", "lines", "none"}, optional
        Progress on ``sys.stderr`` as the command's ``--progress``: a bar redrawn in place, one line
        every ``progress_interval`` seconds (done of total, rate, time left) or nothing; ``"auto"``
        is a bar when ``sys.stderr`` is a terminal and lines otherwise (a notebook, a log). None:
        ``$VIBROIMPACT_PROGRESS``, else ``"auto"``.
    progress_interval : float, optional
        Seconds between two progress lines [s]; 0 for a line at every step.

    Returns
    -------
    dict
        ``"table"``: Table as sweep.csv (a swept path's column carries its unit,
        ``supports[0].position_over_l``; ``status`` is ``"ok"`` or why a point failed);
        ``"summary"``: sweep.json.
    """
    return tables(_vibroimpact.sweep(as_case(case), values, analysis, modes, support_model, threads, point_timeout,
                                     progress, progress_interval))


def uq(case, vary, analysis="simulate", samples=256, method="mc", seed=1, specs=(), sensitivity=False, modes=3, threads=0,
       point_timeout=60.0, bootstrap=1000, progress=None, progress_interval=10.0):
    """A spread study: outputs under random inputs, yield and Sobol indices (``vibroimpact uq``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The base case (:func:`load`).
    vary : dict or list of str
        ``{path: dist}`` or ``["PATH=DIST"]``: ``"normal:MEAN:SD"``, ``"uniform:LOW:HIGH"``,
        ``"lognormal:MEDIAN:SIGMA_LN"``, ``"truncnormal:MEAN:SD:LOW:HIGH"``, units as in case files.
    analysis : {"simulate", "modes", "pullin", "stiction", "air-q"}, optional
        What each sample computes.
    samples : int, optional
        Samples (base samples with ``sensitivity``).
    method : {"mc", "lhs", "sobol"}, optional
        Monte Carlo, Latin hypercube or a Sobol sequence.
    seed : int, optional
        Seed of the sample design.
    specs : sequence of str, optional
        Yield specifications ``"COLUMN<=VALUE"`` or ``"COLUMN>=VALUE"`` (VALUE in the column's SI unit).
    sensitivity : bool, optional
        Sobol indices (Saltelli design, samples x (inputs + 2) runs).
    modes, threads, point_timeout
        As :func:`sweep`.
    bootstrap : int, optional
        Bootstrap resamples of the intervals, at least 100.
    progress, progress_interval
        As :func:`sweep`.

    Returns
    -------
    dict
        ``"table"``: Table as samples.csv; ``"summary"``: uq.json.
    """
    return tables(_vibroimpact.uq(as_case(case), vary, analysis, samples, method, seed, list(specs), sensitivity, modes,
                                  threads, point_timeout, bootstrap, progress, progress_interval))


def _settings(values, what):
    """``["PATH=LOW:HIGH", ...]`` from a list of such texts or a dict ``{path: (low, high)}`` (numbers
    [SI] or texts with units), ``{path: "LOW:HIGH"}`` or ``{path: None}`` (a fit's path without bounds)."""
    if isinstance(values, str):
        raise TypeError(f"{what}: a list of texts or a dict {{path: bounds}}, not one str")
    if not isinstance(values, dict):
        return [str(v) for v in values]
    out = []
    for path, bounds in values.items():
        if bounds is None:
            out.append(str(path))
        elif isinstance(bounds, str):
            out.append(f"{path}={bounds}")
        else:
            low, high = bounds
            out.append(f"{path}={_bound_text(low)}:{_bound_text(high)}")
    return out


def _bound_text(value):
    """A bound as a setting writes it: a text with its unit as is, a number [SI] as the shortest
    text that reads back the same float."""
    return value if isinstance(value, str) else repr(float(value))


def _path_or_empty(path):
    return "" if path is None else os.fspath(path)


def fit(case, parameters, data=None, features=None, column=None, time_shift=False, time_shift_range=None,
        scale=False, scale_range=None, two_stage=False, starts=1, max_iterations=50, threads=0, progress=None,
        progress_interval=10.0):
    """Case values estimated from a measured trajectory or measured features (``vibroimpact fit``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The model; its values are the start of every fitted value (:func:`load`).
    parameters : list of str or dict
        The fitted values: ``["PATH", "PATH=LOW:HIGH"]`` as ``--fit`` (bounds SI or with units,
        ``"supports[0].gap=0.1um:2um"``), or ``{path: (low, high)}`` with numbers [SI] or texts
        with units (``("0.1 um", "2 um")``), ``{path: None}`` for no bounds.
    data : str or os.PathLike, optional
        CSV trajectory: ``t_s`` [s], the measured column and optionally ``sigma`` (docs/calibration.md).
    features : str or os.PathLike, optional
        CSV features: ``name, value, sigma`` per row (``f1_hz``, ``q1``, ``T_s``, ``V_PI_V``, ...).
        Exactly one of data and features.
    column : str, optional
        The measured column of data; by default the watched point's ``<name>_m`` (``tip_m`` [m]).
    time_shift : bool, optional
        Fit the record's time offset t0 [s] (a nuisance parameter).
    time_shift_range : str, optional
        ``"LOW:HIGH"`` bounds of t0, in s or with a time unit; by default +-10 % of the record.
    scale : bool, optional
        Fit the measurement's gain g (data = g * model).
    scale_range : str, optional
        ``"LOW:HIGH"`` bounds of g; by default ``"0.5:2"``.
    two_stage : bool, optional
        Non-contact values before the first impact first, then the contact values (``supports[...]``).
    starts : int, optional
        Starting points: the case's values, then a Halton sample within the bounds.
    max_iterations : int, optional
        Levenberg-Marquardt iterations per start.
    threads : int, optional
        Threads for the starts; 0 for every CPU this process may use.
    progress, progress_interval
        As :func:`sweep`; what is counted is iterations of the budget
        (``starts`` x ``max_iterations``, twice with ``two_stage``).

    Returns
    -------
    dict
        ``"fit"``: fit.json (``converged``, ``parameters`` with ``estimate``, ``std_error`` and
        ``ci95`` in the path's SI unit, ``correlation``, ...); ``"fit_residuals"``: Table as
        fit_residuals.csv; ``"text"``: the summary the command prints. A fit that does not
        converge is a result (``fit["converged"]`` is False), not an error.
    """
    return tables(_vibroimpact.fit(as_case(case), _settings(parameters, "parameters"), _path_or_empty(data),
                                   _path_or_empty(features), column or "", time_shift, time_shift_range or "", scale,
                                   scale_range or "", two_stage, starts, max_iterations, threads, progress,
                                   progress_interval))


def optimize(case, vary, minimize=None, maximize=None, constraints=(), analysis="simulate", modes=3, max_evals=100,
             global_evals=0, threads=0, point_timeout=60.0, progress=None, progress_interval=10.0):
    """The design that minimises (or maximises) a reported quantity in a box of case values
    (``vibroimpact optimize``).

    Parameters
    ----------
    case : Case, str, os.PathLike or dict
        The base design (:func:`load`).
    vary : list of str or dict
        ``["PATH=LOW:HIGH"]`` as ``--vary`` (SI or with units), or ``{path: (low, high)}`` with
        numbers [SI] or texts with units.
    minimize, maximize : str
        One of them: a reported quantity, a sweep column of the analysis (``"z_max"``, ``"Tp_s"``).
    constraints : sequence of str, optional
        ``"NAME<=VALUE"`` or ``"NAME>=VALUE"`` on reported quantities (VALUE in the column's SI unit).
    analysis : {"simulate", "modes", "pullin", "stiction", "air-q"}, optional
        What each design computes.
    modes : int, optional
        Bending modes of a modes analysis.
    max_evals : int, optional
        Designs computed at most, both stages together.
    global_evals : int, optional
        Of those, the global stage's; 0 for half.
    threads : int, optional
        Worker threads; the result does not depend on them.
    point_timeout : float, optional
        Wall-clock limit of one design [s]; 0 for none.
    progress, progress_interval
        As :func:`sweep`; what is counted is designs of ``max_evals``, with
        the best objective so far.

    Returns
    -------
    dict
        ``"optimize"``: optimize.json (``best`` with ``x`` {path: value [SI]}, ``objective`` and
        ``constraints``; None when no design is feasible); ``"evaluations"``: Table as
        evaluations.csv.
    """
    return tables(_vibroimpact.optimize(as_case(case), _settings(vary, "vary"), minimize or "", maximize or "",
                                        list(constraints), analysis, modes, max_evals, global_evals, threads,
                                        point_timeout, progress, progress_interval))


def paper(out=None, positions=50, modal_positions=100, prestress_points=26, scan_horizon="500 us", examples=None,
          threads=0, gnuplot="gnuplot", progress=None, progress_interval=10.0):
    """The paper's numerical study, Figs. 2-11, with its claims checked (``vibroimpact paper``).

    Parameters
    ----------
    out : str or os.PathLike, optional
        A folder to write the command's files into (figures drawn with gnuplot, report.html,
        claims.json); None writes nothing and needs no gnuplot.
    positions : int, optional
        Support positions of the transient scans, evenly over x0/l in [0.3, 1].
    modal_positions : int, optional
        Support positions of the modal scans (Figs. 6-8).
    prestress_points : int, optional
        Prestress values of Fig. 9, evenly over Delta/l in [0, 0.05].
    scan_horizon : str, optional
        Horizon of the support-position transients, a time with its unit.
    examples : str or os.PathLike, optional
        A folder holding cantilever.toml, free_impact_tip.toml and free_impact_prestress.toml
        instead of the built-in copies of examples/paper/.
    threads : int, optional
        Worker threads; 0 for every CPU this process may use.
    gnuplot : str, optional
        The gnuplot executable, for ``out``.
    progress, progress_interval
        As :func:`sweep`; what is counted is the study's jobs, and a line is written as each part
        of the study ends (``paper: [ 12.3 s] Fig. 3 transient: done ...``).

    Returns
    -------
    dict
        ``"claims"``: claims.json (per claim ``id``, ``paper``, ``ours``, ``verdict``);
        ``"figures"``: ``{figure name: {csv name: Table}}``, the data of each figure (``fig4``:
        ``{"fig4": Table}``); ``"timing"``: wall time [s], threads, transients.
    """
    return tables(_vibroimpact.paper(_path_or_empty(out), positions, modal_positions, prestress_points, scan_horizon,
                                     _path_or_empty(examples), threads, gnuplot, progress, progress_interval))
