# Type stubs of the package impactbench (tools/python/impactbench/__init__.py documents each).
import os
from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

class Error(RuntimeError, ValueError):
    """The program's one-line failure message; exit_code is its exit status (1 or 2)."""
    exit_code: int

class RunResult:
    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    energy: np.ndarray
    position_names: list[str]
    velocity_names: list[str]
    events: np.ndarray
    summary: dict[str, Any]
    @property
    def columns(self) -> list[str]: ...
    def column(self, name: str) -> np.ndarray: ...

class SolveResult:
    solution: np.ndarray
    velocity: np.ndarray
    status: str
    message: str
    iterations: int
    residual: float
    faceted_residual: Optional[float]
    seconds: float
    converged: bool

def scenarios() -> list[str]: ...
def describe(name: str, set: Optional[Mapping[str, float]] = ...) -> dict[str, Any]: ...
def run(name: str, engine: str, dt: Optional[float] = ..., tol: Optional[float] = ...,
        solver: Optional[str] = ..., duration: Optional[float] = ...,
        set: Optional[Mapping[str, float]] = ..., options: Optional[Mapping[str, Any]] = ...,
        sample_dt: Optional[float] = ...) -> RunResult: ...
def compare(name: str, engines: Optional[Sequence[str]] = ..., dt: Optional[float] = ...,
            duration: Optional[float] = ..., set: Optional[Mapping[str, float]] = ...,
            options: Optional[Mapping[str, Any]] = ..., out: Optional[str] = ...,
            as_frame: Optional[bool] = ...) -> Tuple[Any, str]: ...
def solve_lcp(M: Any, q: Any, solver: str = ..., tol: Optional[float] = ...,
              max_iter: Optional[int] = ..., options: Optional[Mapping[str, Any]] = ...,
              warm_start: Any = ...) -> SolveResult: ...
def solve_friction(W: Any, q: Any, mu: Any, solver: str = ..., tol: Optional[float] = ...,
                   max_iter: Optional[int] = ..., options: Optional[Mapping[str, Any]] = ...,
                   warm_start: Any = ...) -> SolveResult: ...
def read_fclib(path: Union[str, "os.PathLike[str]"]) -> dict[str, Any]: ...
def read_lcp(path: Union[str, "os.PathLike[str]"]) -> dict[str, Any]: ...
def sensitivity(name: str, duration: Optional[float] = ..., tol: Optional[float] = ...,
                set: Optional[Mapping[str, float]] = ...) -> dict[str, Any]: ...
