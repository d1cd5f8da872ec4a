"""vibroimpact: vibro-impact dynamics of MEMS contact switches, from Python.

The computations of the command line run in-process (the GIL released; Ctrl-C stops a run and
raises KeyboardInterrupt). Results are the files the commands write with --out: every CSV as a dict
{column: numpy array} with the CSV's column names, every JSON as a dict. See docs/python.md.

    import vibroimpact as vi
    case = vi.Case.from_file("examples/paper/free_impact_tip.toml")
    case.set("supports[0].stiffness", 500.0)          # the paths of `sweep --set`, SI units
    run = vi.simulate(case)                           # {'history', 'events', 'summary'}
    table = vi.sweep(case, {"supports[0].position": "0.6:1:20"})["table"]

Errors: InputError (a ValueError) with .file, .line, .key and .reason; SolverError (a
RuntimeError) when a run cannot finish (numerical trouble, a bound on its work or time).
"""

from ._vibroimpact import Case, InputError, SolverError, modes, pullin, simulate, sweep, uq


def load(source, **kwargs):
    """A Case from a path (str or os.PathLike), a dict shaped as the TOML file, or TOML text.

    A str holding a newline or an '=' is read as TOML text; any other str is a file path.
    """
    import os

    if isinstance(source, Case):
        return source.copy()
    if isinstance(source, dict):
        return Case.from_dict(source, **kwargs)
    if isinstance(source, os.PathLike):
        return Case.from_file(os.fspath(source))
    if isinstance(source, str):
        if "\n" in source or "=" in source:
            return Case.from_string(source, **kwargs)
        return Case.from_file(source)
    raise TypeError(f"vibroimpact.load: a path, a dict or TOML text, not {type(source).__name__}")


__all__ = ["Case", "InputError", "SolverError", "load", "modes", "pullin", "simulate", "sweep", "uq"]
