"""Result tables: a CSV file the command line writes, as a dict of numpy arrays with ``to_pandas()``."""


class Table(dict):
    """The columns of one CSV result file: ``{column name: 1-D numpy array}`` in the file's order.

    A column's name carries its unit as in the CSV (``t_s`` [s], ``tip_m`` [m],
    ``contact0_force_n`` [N], ``supports[0].position_over_l`` [x/l]). Columns are float64 (NaN where
    the CSV holds its missing-value marker), int64 for counts and whole-number paths without a
    missing value, and numpy str for text. A Table is a dict: ``table["t_s"]``, ``list(table)``.
    """

    __slots__ = ()

    def to_pandas(self):
        """The table as a pandas DataFrame, one column per array, in the same order.

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            When pandas is not installed (Debian: python3-pandas).
        """
        try:
            import pandas
        except ImportError as e:
            raise ImportError(f"Table.to_pandas needs pandas ({e}); Debian: apt-get install python3-pandas") from e
        return pandas.DataFrame(dict(self))

    def __repr__(self):
        rows = len(next(iter(self.values()))) if self else 0
        return f"<vibroimpact.Table: {rows} rows, columns {list(self)}>"


def tables(result):
    """``result`` with every dict of numpy arrays (a CSV's columns), at any depth of dicts, made a Table."""
    import numpy

    if not isinstance(result, dict):
        return result
    if result and all(isinstance(v, numpy.ndarray) for v in result.values()):
        return Table(result)
    # A JSON file's dict holds lists, never arrays: it comes back as it was.
    return {k: tables(v) for k, v in result.items()}

