"""run() against `impactbench run` on the same input: the same rows (bit for bit: the CSV holds
shortest round-trip text), the same events, the same summary, the same refusals."""

import re

import numpy as np
import pytest

import impactbench
from conftest import cli_message, read_csv, run_cli

CASES = [
    ("bouncing_ball", "moreau", {"duration": 0.5}),
    ("bouncing_ball", "event", {"duration": 0.5}),
    ("bouncing_ball", "moreau", {"duration": 0.3, "dt": 2e-3, "sample_dt": 0.01,
                                 "set": {"restitution": 0.5}, "options": {"theta": 0.75}}),
    ("bouncing_ball", "box2d", {"duration": 0.3}),
    ("bouncing_ball", "bullet", {"duration": 0.3, "settings": "expert"}),
]


def cli_args(name, engine, kw):
    args = ["run", name, "--engine", engine]
    for key, flag in (("dt", "--dt"), ("tol", "--tol"), ("duration", "--duration"),
                      ("sample_dt", "--sample-dt"), ("solver", "--solver"),
                      ("settings", "--settings")):
        if key in kw:
            args += [flag, repr(kw[key]) if isinstance(kw[key], float) else kw[key]]
    for k, v in kw.get("set", {}).items():
        args += ["--set", f"{k}={v!r}"]
    for k, v in kw.get("options", {}).items():
        args += ["--option", f"{k}={v!r}"]
    return args


@pytest.mark.parametrize("name,engine,kw", CASES)
def test_run_gives_the_programs_trajectory_events_and_summary(tmp_path, name, engine, kw):
    traj, events = tmp_path / "traj.csv", tmp_path / "events.csv"
    _, out, _ = run_cli(*cli_args(name, engine, kw), "--out", traj, "--events", events)
    result = impactbench.run(name, engine=engine, **kw)

    header, rows = read_csv(traj)
    assert result.columns == header
    table = np.array([[float(x) for x in row] for row in rows])
    expected = np.column_stack([result.t, result.q, result.v, result.energy])
    assert expected.shape == table.shape
    assert np.array_equal(expected, table)  # bit for bit

    header, rows = read_csv(events)
    assert list(result.events.dtype.names) == header
    assert len(result.events) == len(rows)
    for event, row in zip(result.events, rows):
        assert float(row[0]) == event["t"]
        assert row[1:5] == [event["contact"], event["kind"], event["from_mode"], event["to_mode"]]
        assert (float(row[5]), float(row[6])) == (event["impulse_n"], event["impulse_t"])

    s = result.summary
    for setting in s["settings"]:
        assert f"  setting {setting['key']} {setting['value']} ({setting['source']})" in out
    assert f"  samples {s['samples']}\n" in out
    assert s["samples"] == len(result.t)
    assert float(re.search(r"^  steps\s+(\S+)$", out, re.M).group(1)) == s["steps"]
    assert re.search(r"^  events (\d+)", out, re.M).group(1) == str(s["events"])
    assert float(re.search(r"^  max_penetration\s+(\S+) m", out, re.M).group(1)) == \
        s["max_penetration"]
    energies = re.search(r"^  energy (\S+) J at start, (\S+) J at end$", out, re.M)
    assert (float(energies.group(1)), float(energies.group(2))) == \
        (s["first_energy"], s["last_energy"])


def test_arrays_are_views_of_the_runs_buffers():
    result = impactbench.run("bouncing_ball", engine="moreau", duration=0.05)
    for array in (result.t, result.q, result.v, result.energy):
        assert array.flags.c_contiguous
        assert not array.flags.owndata  # owned by the capsule over the run's buffer, not copied
    assert np.shares_memory(result.column("ball.y"), result.q)


@pytest.mark.parametrize("args,kw", [
    (("run", "no_such", "--engine", "moreau"), {"name": "no_such", "engine": "moreau"}),
    (("run", "bouncing_ball", "--engine", "warp"), {"engine": "warp"}),
    (("run", "bouncing_ball", "--engine", "moreau", "--dt", "-1"),
     {"engine": "moreau", "dt": -1.0}),
    (("run", "bouncing_ball", "--engine", "moreau", "--tol", "nan"),
     {"engine": "moreau", "tol": float("nan")}),
    (("run", "bouncing_ball", "--engine", "moreau", "--option", "no_such_key=1"),
     {"engine": "moreau", "options": {"no_such_key": 1}}),
    (("run", "bouncing_ball", "--engine", "moreau", "--set", "no_such=1"),
     {"engine": "moreau", "set": {"no_such": 1}}),
    (("run", "bouncing_ball", "--engine", "event", "--dt", "0.001"),
     {"engine": "event", "dt": 0.001}),
    (("run", "bouncing_ball", "--engine", "moreau", "--sample-dt", "5e-324"),
     {"engine": "moreau", "sample_dt": 5e-324}),
    (("run", "bouncing_ball", "--engine", "bullet", "--settings", "tuned"),
     {"engine": "bullet", "settings": "tuned"}),
])
def test_refusals_carry_the_programs_message(tmp_path, args, kw):
    code, message = cli_message(*args, "--out", tmp_path / "t.csv")
    kw.setdefault("name", "bouncing_ball")
    with pytest.raises(impactbench.Error) as raised:
        impactbench.run(**kw)
    assert str(raised.value) == message
    assert raised.value.exit_code == code
