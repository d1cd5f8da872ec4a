"""vibroimpact: vibro-impact dynamics of MEMS contact switches, from Python.

The computations of the command line run in-process (the GIL released; Ctrl-C stops a run and
raises KeyboardInterrupt). Results are the files the commands write with --out: every CSV as a
:class:`Table` (a dict {column: numpy array} with the CSV's column names, and ``to_pandas()``),
every JSON as a dict. See docs/python.md.

    import vibroimpact as vi
    case = vi.Case.from_file("examples/paper/free_impact_tip.toml")
    case.set("supports[0].stiffness", 500.0)          # the paths of `sweep --set`, SI units
    case.set("supports[0].gap", "0.5 um")             # or a text with a unit, as --set takes it
    run = vi.simulate(case)                           # {'history', 'events', 'summary'}
    table = vi.sweep(case, {"supports[0].position": "0.6:1:20"})["table"]

Errors: InputError (a ValueError) with .file, .line, .key, .option and .reason; SolverError (a
RuntimeError) when a run cannot finish (numerical trouble, a bound on its work or time).
"""

from ._vibroimpact import InputError, SolverError
from ._vibroimpact import __version__
from .case import Case, load
from .runs import fit, modes, optimize, paper, pullin, simulate, sweep, uq
from .tables import Table

__all__ = ["Case", "InputError", "SolverError", "Table", "__version__", "fit", "load", "modes", "optimize", "paper",
           "pullin", "simulate", "sweep", "uq"]
