"""impactbench from Python: scenarios, engines, compare, contact solvers and sensitivities.

Every function calls the library code the ``impactbench`` program calls, so the numbers are
the program's: ``run`` gives the trajectory ``impactbench run`` writes, ``solve_lcp`` and
``solve_friction`` the status, iterations and residual ``impactbench solve`` prints. A failure
the program reports as one line on stderr raises :class:`Error` with that line (a solver that
does not converge is a status, not an exception). Long runs release the GIL and stop on Ctrl-C
(KeyboardInterrupt) within a second. See docs/python.md.
"""

from __future__ import annotations

import dataclasses
import os
from typing import Any, Mapping, Optional, Sequence

import numpy as np

from . import _impactbench
from ._impactbench import Error

__all__ = [
    "Error", "RunResult", "SolveResult", "scenarios", "describe", "run", "compare",
    "solve_lcp", "solve_friction", "read_fclib", "read_lcp", "sensitivity",
]

# The package sits below the prefix (PREFIX/lib/python3/dist-packages/impactbench, in an install
# and in the build tree alike); the scenarios are in PREFIX/share/impactbench.
_impactbench._set_package_directory(os.path.dirname(os.path.realpath(_impactbench.__file__)))


@dataclasses.dataclass
class RunResult:
    """One engine's run of a scenario, as ``impactbench run`` writes and prints it.

    ``t`` (rows,), ``q`` (rows, positions), ``v`` (rows, velocities) and ``energy`` (rows,) hold
    the rows of the trajectory CSV (the same sampling); ``events`` is a structured array with
    the fields of the events CSV (t, contact, kind, from_mode, to_mode, impulse_n, impulse_t);
    ``summary`` is the run summary: settings in force with their sources, duration, samples,
    steps, unconverged_steps (None where the engine has no tolerance: see unconverged_note),
    defect_note (a known defect of the engine that showed in the run, counted, else empty),
    engine_cpu_seconds, record_cpu_seconds, wall_seconds, mean_contacts, events and
    event_kinds, max_penetration, first_energy, last_energy and the engine's own figures
    (engine_summary).
    """

    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    energy: np.ndarray
    position_names: list
    velocity_names: list
    events: np.ndarray
    summary: dict

    @property
    def columns(self) -> list:
        """The column names of the trajectory CSV: t, positions, velocities, energy."""
        return ["t", *self.position_names, *self.velocity_names, "energy"]

    def column(self, name: str) -> np.ndarray:
        """One column of the trajectory by its CSV name (e.g. ``"ball.y"``), a view."""
        if name == "t":
            return self.t
        if name == "energy":
            return self.energy
        if name in self.position_names:
            return self.q[:, self.position_names.index(name)]
        if name in self.velocity_names:
            return self.v[:, self.velocity_names.index(name)]
        raise KeyError(f"no column {name!r} (columns: {', '.join(self.columns)})")


@dataclasses.dataclass
class SolveResult:
    """What ``impactbench solve`` reports of one solve.

    ``solution`` is z (LCP) or r (friction: per contact the normal then tangential
    components), ``velocity`` w = Mz + q or u = Wr + q; ``status`` the solver's status as the
    program prints it ("converged", "max-iterations", ...), ``message`` its detail,
    ``iterations``, ``residual`` (the same measure for every solver), ``faceted_residual``
    (spatial friction through a faceted-cone LCP, else None) and ``seconds`` (wall time).
    """

    solution: np.ndarray
    velocity: np.ndarray
    status: str
    message: str
    iterations: int
    residual: float
    faceted_residual: Optional[float]
    seconds: float
    converged: bool


_EVENT_FIELDS = ("t", "contact", "kind", "from_mode", "to_mode", "impulse_n", "impulse_t")


def _events_array(columns: Mapping[str, Any]) -> np.ndarray:
    def text(name):
        return f"U{max([1, *map(len, columns[name])])}"
    dtype = [("t", "f8"), ("contact", text("contact")), ("kind", text("kind")),
             ("from_mode", text("from_mode")), ("to_mode", text("to_mode")),
             ("impulse_n", "f8"), ("impulse_t", "f8")]
    events = np.empty(len(columns["t"]), dtype=dtype)
    for name in _EVENT_FIELDS:
        events[name] = columns[name]
    return events


def scenarios() -> list:
    """The scenario names, as ``impactbench list`` prints them."""
    return _impactbench.scenarios()


def describe(name: str, set: Optional[Mapping[str, float]] = None) -> dict:
    """What ``impactbench describe NAME [--set k=v]...`` prints, as a dict.

    Keys: name, description, file, dimension, system, engines, duration [s], dt [s],
    tolerance, bodies, planes, inputs; parameters (dicts: name, value, default, unit,
    description); settings ({engine: [{key, value, source}]}: every engine's settings in
    force, with where each comes from); analytic (dicts: name, value (at k = 0 when indexed),
    unit, indexed, description, expression).
    """
    return _impactbench.describe(name, dict(set or {}))


def run(name: str, engine: str, dt: Optional[float] = None, tol: Optional[float] = None,
        solver: Optional[str] = None, duration: Optional[float] = None,
        set: Optional[Mapping[str, float]] = None,
        options: Optional[Mapping[str, Any]] = None,
        sample_dt: Optional[float] = None, settings: str = "default") -> RunResult:
    """Runs scenario ``name`` with ``engine``: ``impactbench run`` without files.

    The arguments are the program's flags: ``dt`` (--dt), ``tol`` (--tol), ``solver``
    (--solver), ``duration`` (--duration), ``set`` ({parameter: value}, --set),
    ``options`` ({"[ENGINE.]key": value}, --option), ``sample_dt`` (--sample-dt; 0 keeps
    every step; unset, a time-stepper's trajectory is thinned to about 1e6 numbers as the
    program's is) and ``settings`` (--settings: "default" or "expert", the values a reference
    engine's own documentation gives for accurate rigid contact). Raises :class:`Error` with the program's message for anything it refuses.
    """
    raw = _impactbench._run(name, engine, dt, tol, solver, duration, dict(set or {}),
                            dict(options or {}), sample_dt, settings)
    return RunResult(t=raw["t"], q=raw["q"], v=raw["v"], energy=raw["energy"],
                     position_names=raw["position_names"],
                     velocity_names=raw["velocity_names"],
                     events=_events_array(raw["events"]), summary=raw["summary"])


def compare(name: str, engines: Optional[Sequence[str]] = None, dt: Optional[float] = None,
            duration: Optional[float] = None, set: Optional[Mapping[str, float]] = None,
            options: Optional[Mapping[str, Any]] = None, out: Optional[str] = None,
            as_frame: Optional[bool] = None, settings: str = "default"):
    """``impactbench compare``: several engines on one scenario, their metrics table.

    Returns ``(table, reference)``: ``table`` has the columns of metrics.csv (engine, every
    metric including the analytic errors such as apex_error and impact_time_error, failure,
    note), as
    a pandas DataFrame when pandas is installed (``as_frame=None``) or asked for, else a dict
    {column: numpy array or list}; NaN where a metric does not apply. ``reference`` names the
    reference trajectory. An engine whose run fails keeps its row, with NaN metrics and its
    reason in ``failure`` (the program exits 4 then); no exception is raised for it.
    ``options`` keys must name their engine ("moreau.max_iterations"); ``settings`` is
    --settings ("default" or "expert"; an engine at its expert set is labelled
    ``ENGINE (expert)``).
    The program's CSV files go to ``out`` when given (no plots), else to a temporary folder
    removed afterwards.
    """
    raw = _impactbench._compare(name, list(engines or []), dt, duration, dict(set or {}),
                                dict(options or {}), out, settings)
    table = raw["columns"]
    if as_frame is None or as_frame:
        try:
            import pandas
            return pandas.DataFrame(table), raw["reference"]
        except ImportError:
            if as_frame:
                raise
    return table, raw["reference"]


def _matrix(matrix):
    """A scipy.sparse matrix as CSR (sorted, duplicates summed, as a copy); else as given."""
    if hasattr(matrix, "tocsr") and hasattr(matrix, "format"):
        csr = matrix.tocsr(copy=True)
        csr.sum_duplicates()
        csr.sort_indices()
        return csr
    return matrix


def _solve_result(raw: dict) -> SolveResult:
    return SolveResult(**raw)


def solve_lcp(M, q, solver: str = "lemke", tol: Optional[float] = None,
              max_iter: Optional[int] = None, options: Optional[Mapping[str, Any]] = None,
              warm_start=None) -> SolveResult:
    """Solves the LCP w = M z + q, 0 <= z ⊥ w >= 0 as ``impactbench solve`` does.

    ``M`` is a square numpy array or scipy.sparse matrix, ``q`` a vector; ``solver`` one of
    lemke, pgs, psor, newton-fb, enum; ``tol`` and ``max_iter`` default to the solver's;
    ``options`` the solver's --option settings ({"relaxation": 1.2} for psor); ``warm_start``
    a starting z. The inputs are checked (real dtype, shape, finite) before the solver runs.
    """
    return _solve_result(_impactbench._solve_lcp(_matrix(M), q, solver, tol, max_iter,
                                                 dict(options or {}), warm_start))


def solve_friction(W, q, mu, solver: str = "nsgs", tol: Optional[float] = None,
                   max_iter: Optional[int] = None, options: Optional[Mapping[str, Any]] = None,
                   warm_start=None) -> SolveResult:
    """Solves the friction-contact problem u = W r + q (FCLIB local form) as ``impactbench
    solve`` does on an FCLIB file.

    ``W`` is square (numpy or scipy.sparse), ``q`` has 2 (planar: n, t) or 3 (spatial: n, t1,
    t2) entries per contact and ``mu`` one coefficient >= 0 per contact, which fixes the
    dimension. ``solver`` is one of prox-jacobi, prox-gs, nsgs, nsn, lemke, pgs; ``options``
    its --option settings (omega, rho_scale, cone_facets). Checked before the solver runs.
    """
    return _solve_result(_impactbench._solve_friction(_matrix(W), q, mu, solver, tol,
                                                      max_iter, dict(options or {}),
                                                      warm_start))


def _csr(parts: dict):
    """A scipy.sparse.csr_matrix over the arrays (no copy) when scipy is installed, else a
    dense array."""
    try:
        import scipy.sparse
        return scipy.sparse.csr_matrix((parts["data"], parts["indices"], parts["indptr"]),
                                       shape=parts["shape"], copy=False)
    except ImportError:
        dense = np.zeros(parts["shape"])
        for row in range(parts["shape"][0]):
            span = slice(parts["indptr"][row], parts["indptr"][row + 1])
            dense[row, parts["indices"][span]] = parts["data"][span]
        return dense


def read_fclib(path: str) -> dict:
    """An FCLIB problem file (HDF5) in local form, read as ``impactbench solve`` reads it
    (global problems reduced: W = Hᵀ M⁻¹ H).

    Keys: W (scipy.sparse.csr_matrix, or a dense array without scipy), q, mu, dimension (2 or
    3), title, description, from_global, reference_r and reference_u (the file's solution, or
    None) and reference_residual (that solution's residual, as the program prints it).
    """
    raw = _impactbench._read_fclib(os.fspath(path))
    raw["W"] = _csr(raw["W"])
    return raw


def read_lcp(path: str) -> dict:
    """A plain-text LCP file (the format of ``impactbench solve``): {"M": ..., "q": ...}, M a
    dense array or (for "sparse" files) a scipy.sparse.csr_matrix."""
    raw = _impactbench._read_lcp(os.fspath(path))
    if isinstance(raw["M"], dict):
        raw["M"] = _csr(raw["M"])
    return raw


def sensitivity(name: str, duration: Optional[float] = None, tol: Optional[float] = None,
                set: Optional[Mapping[str, float]] = None, parameter_gains: bool = False) -> dict:
    """First-order sensitivity of the scenario's event-driven run, as ``impactbench
    sensitivity`` computes it (planar and spatial rigid-body scenarios and the plank-box).

    Keys: state_names (the reported coordinates: q then v; a spatial body's quaternion
    b.qw..b.qz is reported as its world rotation vector b.rx, b.ry, b.rz; then friction and
    restitution with parameter_gains), events (per macro event: index, t, gains: per order of
    its micro events {order, micro_events, Gz (n × n), Gv (n × m)}), t_end, end_point_state
    (n × n) and end_point_input (n × m, a constant input perturbation per channel).

    parameter_gains: the friction coefficient μ and the restitution e join the state with zero
    flow (``--parameter-gains``), so the last two columns of end_point_state give how the end
    state moves with μ and e.
    """
    return _impactbench._sensitivity(name, duration, tol, dict(set or {}), bool(parameter_gains))
