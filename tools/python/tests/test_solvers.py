"""solve_lcp(), solve_friction(), read_lcp() and read_fclib() against `impactbench solve` on
the same problem file: the same status, iterations and residual (printed as shortest
round-trip text, so compared exactly), the same solution (written with 17 digits)."""

import re

import numpy as np
import pytest

import impactbench
from conftest import DATA, cli_message, read_csv, run_cli

scipy_sparse = pytest.importorskip("scipy.sparse")


def solve_report(out):
    status = re.search(r"^status   (\S+?)(?::|$)", out, re.M).group(1)
    iterations = int(re.search(r"^iterations (\d+)$", out, re.M).group(1))
    residual = float(re.search(r"^residual (\S+)$", out, re.M).group(1))
    return status, iterations, residual


@pytest.mark.parametrize("file,solver", [("murty_4.lcp", "lemke"), ("murty_4.lcp", "pgs"),
                                         ("two_by_two.lcp", "psor"),
                                         ("chain_5_sparse.lcp", "newton-fb"),
                                         ("chain_5_sparse.lcp", "enum")])
def test_solve_lcp_reports_what_the_program_reports(tmp_path, file, solver):
    path = DATA / "lcp" / file
    code, out, _ = run_cli("solve", path, "--solver", solver, "--solution", tmp_path / "z.csv",
                           check=False)
    problem = impactbench.read_lcp(path)
    result = impactbench.solve_lcp(problem["M"], problem["q"], solver=solver)
    assert (result.status, result.iterations, result.residual) == solve_report(out)
    if code == 0:
        _, rows = read_csv(tmp_path / "z.csv")
        assert np.array_equal(result.solution, [float(r[1]) for r in rows])
        assert np.array_equal(result.velocity, [float(r[2]) for r in rows])
    # Dense and sparse storage of the same matrix solve alike.
    M = problem["M"]
    other = M.toarray() if scipy_sparse.issparse(M) else scipy_sparse.csr_matrix(M)
    again = impactbench.solve_lcp(other, problem["q"], solver=solver)
    assert again.status == result.status
    assert np.allclose(again.solution, result.solution, rtol=0, atol=1e-12)


@pytest.mark.parametrize("file,solver,extra", [
    ("Capsules-i125-1213.hdf5", "nsgs", ()),
    ("Capsules-i125-1213.hdf5", "prox-gs", ("--max-iter", "50")),
    ("LMGC_100_PR_PerioBox-i00361-60-03000.hdf5", "nsn", ("--tol", "1e-6")),
    ("Box_Stacks-i0122-82-5.hdf5", "nsgs", ("--option", "rho_scale=1")),
])
def test_solve_friction_reports_what_the_program_reports(file, solver, extra):
    path = DATA / "fclib" / file
    code, out, _ = run_cli("solve", path, "--solver", solver, *extra, check=False)
    problem = impactbench.read_fclib(path)
    assert problem["dimension"] == 3
    kw = {}
    if "--max-iter" in extra:
        kw["max_iter"] = int(extra[1])
    if "--tol" in extra:
        kw["tol"] = float(extra[1])
    if "--option" in extra:
        kw["options"] = {"rho_scale": 1}
    if solver == "nsgs" and "--option" in extra:  # nsgs has no rho_scale: the same refusal
        code, message = cli_message("solve", path, "--solver", solver, *extra)
        with pytest.raises(impactbench.Error) as raised:
            impactbench.solve_friction(problem["W"], problem["q"], problem["mu"], solver, **kw)
        assert str(raised.value) == message
        return
    result = impactbench.solve_friction(problem["W"], problem["q"], problem["mu"], solver, **kw)
    assert (result.status, result.iterations, result.residual) == solve_report(out)
    if problem["reference_r"] is not None:
        printed = re.search(r"^file's reference solution: residual (\S+)", out, re.M).group(1)
        assert float(printed) == problem["reference_residual"]


def test_a_solver_that_does_not_converge_is_a_status():
    problem = impactbench.read_fclib(DATA / "fclib" / "Capsules-i125-1213.hdf5")
    result = impactbench.solve_friction(problem["W"], problem["q"], problem["mu"], "prox-jacobi",
                                        max_iter=2)
    assert result.status == "max-iterations" and not result.converged
    assert result.iterations == 2


def test_planar_friction_single_contact_closed_form():
    # One planar contact, W = I, q = (-1, 2), mu = 0.5: the contact closes (r_n = 1) and slides
    # with r_t = -mu r_n = -0.5 against the tangential velocity u_t = 2 - 0.5 = 1.5 > 0.
    result = impactbench.solve_friction(np.eye(2), [-1.0, 2.0], [0.5], "nsgs", tol=1e-12)
    assert result.converged
    assert np.allclose(result.solution, [1.0, -0.5], rtol=0, atol=1e-12)
    assert np.allclose(result.velocity, [0.0, 1.5], rtol=0, atol=1e-12)


@pytest.mark.parametrize("call,message", [
    (lambda: impactbench.solve_lcp(np.ones((2, 3)), [1, 1]),
     "M: must be a non-empty square matrix, got shape (2, 3)"),
    (lambda: impactbench.solve_lcp(np.eye(2), [1, 1, 1]),
     "q: length 3 does not match the rows of M (2)"),
    (lambda: impactbench.solve_lcp(np.eye(2), [1, np.nan]), "q: entry 1 is not finite (nan)"),
    (lambda: impactbench.solve_lcp(np.eye(2, dtype=complex), [1, 1]),
     "M: dtype complex128 is not a real number type (float or int)"),
    (lambda: impactbench.solve_lcp(np.eye(2), [[1, 1]]),
     "q: must have 1 dimension, got shape (1, 2)"),
    (lambda: impactbench.solve_friction(np.eye(4), np.zeros(4), [0.5]),
     "W: 4 rows are not 2 (planar) or 3 (spatial) per contact for 1 coefficients in mu"),
    (lambda: impactbench.solve_friction(np.eye(3), np.zeros(3), [-0.5]),
     "mu: entry 0 is negative"),
    (lambda: impactbench.solve_friction(np.eye(3)[:, :2], np.zeros(3), [0.5]),
     "W: must be a non-empty square matrix, got shape (3, 2)"),
    (lambda: impactbench.solve_friction(np.full((3, 3), np.inf), np.zeros(3), [0.5]),
     "W: entry 0 is not finite (inf)"),
])
def test_bad_input_is_refused_before_any_solver_runs(call, message):
    with pytest.raises(impactbench.Error) as raised:
        call()
    assert str(raised.value) == message


@pytest.mark.parametrize("args,call", [
    (("--solver", "warp"), lambda p: impactbench.solve_lcp(p["M"], p["q"], solver="warp")),
    (("--solver", "pgs", "--tol", "-1"),
     lambda p: impactbench.solve_lcp(p["M"], p["q"], solver="pgs", tol=-1.0)),
    (("--solver", "psor", "--option", "relaxation=3"),
     lambda p: impactbench.solve_lcp(p["M"], p["q"], solver="psor", options={"relaxation": 3})),
    (("--solver", "lemke", "--option", "omega=1"),
     lambda p: impactbench.solve_lcp(p["M"], p["q"], solver="lemke", options={"omega": 1})),
])
def test_solver_refusals_carry_the_programs_message(args, call):
    path = DATA / "lcp" / "murty_4.lcp"
    code, message = cli_message("solve", path, *args)
    with pytest.raises(impactbench.Error) as raised:
        call(impactbench.read_lcp(path))
    assert str(raised.value) == message
    assert raised.value.exit_code == code


def test_missing_files_carry_the_programs_message(tmp_path):
    missing = tmp_path / "none.hdf5"
    _, message = cli_message("solve", missing, "--solver", "nsgs")
    for read in (impactbench.read_fclib, impactbench.read_lcp):
        with pytest.raises(impactbench.Error) as raised:
            read(missing)
        assert str(raised.value) == message


def test_read_fclib_arrays_are_not_copies():
    problem = impactbench.read_fclib(DATA / "fclib" / "Capsules-i125-1213.hdf5")
    W = problem["W"]
    assert not W.data.flags.owndata and not problem["q"].flags.owndata
    assert W.shape == (problem["q"].size, problem["q"].size) == (3 * problem["mu"].size,) * 2
