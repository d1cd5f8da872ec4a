"""Case: a checked case file in memory, read and changed by the paths of ``--set``; load()."""

import os

from . import _vibroimpact


class Case:
    """A checked case: what a case file holds (docs/case-files.md), in SI units.

    Make one with :meth:`from_file`, :meth:`from_string`, :meth:`from_dict` or :func:`load`.
    Its numbers are read and changed by the paths of ``sweep --set`` (:meth:`paths` lists them),
    and every change is checked as a case file is: on :class:`InputError` the case is unchanged.
    """

    __slots__ = ("_case",)

    def __init__(self, compiled):
        if not isinstance(compiled, _vibroimpact.Case):
            raise TypeError("make a Case with Case.from_file, Case.from_string, Case.from_dict or vibroimpact.load")
        self._case = compiled

    @classmethod
    def from_file(cls, path):
        """Reads and checks a TOML case file.

        Parameters
        ----------
        path : str or os.PathLike
            The case file.

        Returns
        -------
        Case

        Raises
        ------
        InputError
            With ``file``, ``line`` and ``key`` of the first problem (an unreadable file has no line).
        """
        return cls(_vibroimpact.Case.from_file(os.fspath(path)))

    @classmethod
    def from_string(cls, text, source="<string>"):
        """Reads and checks a case from TOML text.

        Parameters
        ----------
        text : str
            The case file's text.
        source : str or os.PathLike, optional
            Stands for the file in messages; files the case names (load tables) are looked for
            next to it.

        Returns
        -------
        Case
        """
        return cls(_vibroimpact.Case.from_string(text, os.fspath(source)))

    @classmethod
    def from_dict(cls, data, source="<dict>"):
        """Reads and checks a case from a dict shaped as the TOML file.

        Parameters
        ----------
        data : dict
            Tables as dicts, ``[[supports]]`` as a list of dicts; values as in the file, e.g.
            ``"2 um"`` or ``2e-6`` (SI). :meth:`to_dict` gives one.
        source : str or os.PathLike, optional
            Stands for the file in messages (``InputError.file``).

        Returns
        -------
        Case
        """
        return cls(_vibroimpact.Case.from_dict(data, os.fspath(source)))

    @property
    def name(self):
        """str: The case's name."""
        return self._case.name

    @property
    def file(self):
        """str: Where the case was read from, or the ``source`` name it was given."""
        return self._case.file

    def get(self, path):
        """The value at a path.

        Parameters
        ----------
        path : str
            A path such as ``"supports[0].gap"`` (:meth:`paths`).

        Returns
        -------
        float or int
            In SI units (m, Pa, kg/m^3, N/m, s, ...; x/l for positions along the beam); int for
            whole-number paths (``beam.elements``).
        """
        return self._case.get(path)

    def set(self, path, value):
        """Sets the value at a path and checks the case.

        Parameters
        ----------
        path : str
            A path such as ``"supports[0].gap"`` (:meth:`paths`).
        value : float or str
            A number in SI units (``5e-7`` for a gap of 0.5 um), or a text as ``--set`` takes it,
            with a unit of the path's dimension (``"0.5 um"``, ``"2 GPa"``, ``"150 us"``).

        Raises
        ------
        InputError
            For an unknown path, a bad number or unit, or a case the value makes invalid; the key
            and its line in the case's file are named, and the case is left unchanged.
        """
        self._case.set(path, value)

    def update(self, values):
        """Sets several values together, then checks the case once.

        Parameters
        ----------
        values : dict
            ``{path: value}``, each value as :meth:`set` takes it.
        """
        self._case.update(values)

    def to_toml(self):
        """The case as a case file: every key in effect with its value in SI units.

        Returns
        -------
        str
            TOML text that :meth:`from_string` reads back to the same case.
        """
        return self._case.to_toml()

    def to_dict(self):
        """The case as a dict shaped as its TOML file (:meth:`to_toml`), values in SI units.

        Returns
        -------
        dict
            What ``tomllib.loads(case.to_toml())`` gives; :meth:`from_dict` reads it back to the
            same case.
        """
        return self._case.to_dict()

    def copy(self):
        """An independent copy.

        Returns
        -------
        Case
        """
        return Case(self._case.copy())

    def __copy__(self):
        return self.copy()

    def __deepcopy__(self, memo):
        return self.copy()

    def __repr__(self):
        return f"<vibroimpact.Case {self.name!r} from {self.file}>"

    @staticmethod
    def paths():
        """Every path :meth:`get`, :meth:`set` and ``sweep`` take.

        Returns
        -------
        list of str
            Forms such as ``"supports[i].position"``: i is a support or load number from 0, k 0 or 1.
        """
        return _vibroimpact.Case.paths()


def load(source):
    """A Case from a path, TOML text, a dict or another Case.

    Parameters
    ----------
    source : str, os.PathLike, dict or Case
        An ``os.PathLike`` (``pathlib.Path``) is always a file. A ``str`` holding a line break is
        TOML text (a case file has several keys, each on its own line); any other ``str`` is a
        file path, whatever characters it holds (``"runs/kc=500/case.toml"``). A dict is read as
        :meth:`Case.from_dict` reads it; a Case is copied.

    Returns
    -------
    Case
    """
    if isinstance(source, Case):
        return source.copy()
    if isinstance(source, dict):
        return Case.from_dict(source)
    if isinstance(source, os.PathLike):
        return Case.from_file(source)
    if isinstance(source, str):
        if "\n" in source or "\r" in source:
            return Case.from_string(source)
        return Case.from_file(source)
    raise TypeError(f"vibroimpact.load: a path, TOML text, a dict or a Case, not {type(source).__name__}")


def as_case(case):
    """The compiled case of ``case`` (anything :func:`load` takes), not copied when it is a Case."""
    if isinstance(case, Case):
        return case._case
    return load(case)._case
