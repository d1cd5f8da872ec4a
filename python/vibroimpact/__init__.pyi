# Type stub of the package vibroimpact (PEP 561). python/tests/test_stub.py checks that it names
# exactly the package's public names, with the same parameters and defaults as the real objects.

import os
from typing import Any, Iterable, Mapping, Sequence, Union

import numpy

_PathLike = Union[str, "os.PathLike[str]"]
_CaseSource = Union["Case", _PathLike, Mapping[str, Any]]
_Bounds = Union[None, str, tuple[float, float]]

__version__: str

class InputError(ValueError):
    file: str | None
    line: int | None
    key: str | None
    option: str | None
    reason: str

class SolverError(RuntimeError): ...

class Table(dict[str, numpy.ndarray]):
    def to_pandas(self) -> Any: ...

class Case:
    def __init__(self, compiled: Any) -> None: ...
    @classmethod
    def from_file(cls, path: _PathLike) -> Case: ...
    @classmethod
    def from_string(cls, text: str, source: _PathLike = "<string>") -> Case: ...
    @classmethod
    def from_dict(cls, data: Mapping[str, Any], source: _PathLike = "<dict>") -> Case: ...
    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    def get(self, path: str) -> float | int: ...
    def set(self, path: str, value: float | str) -> None: ...
    def update(self, values: Mapping[str, float | str]) -> None: ...
    def to_toml(self) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    def copy(self) -> Case: ...
    @staticmethod
    def paths() -> list[str]: ...

def load(source: _CaseSource) -> Case: ...
def modes(case: _CaseSource, count: int = 5, support_model: str = "pin") -> dict[str, Any]: ...
def simulate(case: _CaseSource) -> dict[str, Any]: ...
def pullin(case: _CaseSource, steps: int = 200) -> dict[str, Any]: ...
def sweep(
    case: _CaseSource,
    values: Mapping[str, str | float | Sequence[float]] | Iterable[str],
    analysis: str = "simulate",
    modes: int = 3,
    support_model: str = "pin",
    threads: int = 0,
    point_timeout: float = 60.0,
    progress: str | None = None,
    progress_interval: float = 10.0,
) -> dict[str, Any]: ...
def uq(
    case: _CaseSource,
    vary: Mapping[str, str] | Iterable[str],
    analysis: str = "simulate",
    samples: int = 256,
    method: str = "mc",
    seed: int = 1,
    specs: Sequence[str] = (),
    sensitivity: bool = False,
    modes: int = 3,
    threads: int = 0,
    point_timeout: float = 60.0,
    bootstrap: int = 1000,
    progress: str | None = None,
    progress_interval: float = 10.0,
) -> dict[str, Any]: ...
def fit(
    case: _CaseSource,
    parameters: Mapping[str, _Bounds] | Iterable[str],
    data: _PathLike | None = None,
    features: _PathLike | None = None,
    column: str | None = None,
    time_shift: bool = False,
    time_shift_range: str | None = None,
    scale: bool = False,
    scale_range: str | None = None,
    two_stage: bool = False,
    starts: int = 1,
    max_iterations: int = 50,
    threads: int = 0,
    progress: str | None = None,
    progress_interval: float = 10.0,
) -> dict[str, Any]: ...
def optimize(
    case: _CaseSource,
    vary: Mapping[str, _Bounds] | Iterable[str],
    minimize: str | None = None,
    maximize: str | None = None,
    constraints: Sequence[str] = (),
    analysis: str = "simulate",
    modes: int = 3,
    max_evals: int = 100,
    global_evals: int = 0,
    threads: int = 0,
    point_timeout: float = 60.0,
    progress: str | None = None,
    progress_interval: float = 10.0,
) -> dict[str, Any]: ...
def paper(
    out: _PathLike | None = None,
    positions: int = 50,
    modal_positions: int = 100,
    prestress_points: int = 26,
    scan_horizon: str = "500 us",
    examples: _PathLike | None = None,
    threads: int = 0,
    gnuplot: str = "gnuplot",
    progress: str | None = None,
    progress_interval: float = 10.0,
) -> dict[str, Any]: ...
