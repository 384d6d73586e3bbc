"""compare() against `impactbench compare`'s metrics.csv and sensitivity() against `impactbench
sensitivity`'s gains CSV, for the same input."""

import math

import numpy as np
import pytest

import impactbench
from conftest import cli_message, read_csv, run_cli

# Process CPU and wall time differ from run to run; every other column is deterministic.
TIMES = {"engine_cpu_seconds", "record_cpu_seconds", "wall_seconds"}


def test_compare_gives_the_programs_metrics(tmp_path):
    run_cli("compare", "bouncing_ball", "--engines", "moreau,event", "--duration", "1",
            "--out", tmp_path, "--no-plots")
    table, reference = impactbench.compare("bouncing_ball", engines=["moreau", "event"],
                                           duration=1.0, as_frame=False)
    header, rows = read_csv(tmp_path / "metrics.csv")
    assert list(table) == header[:-1]  # all but the settings column
    assert "apex_error" in table and "impact_time_error" in table  # the analytic errors
    assert reference.startswith("event")
    for r, row in enumerate(rows):
        assert table["engine"][r] == row[0]
        for name, text in zip(header[1:-3], row[1:-3]):
            if name in TIMES:
                continue
            value = table[name][r]
            assert (math.isnan(value) and text == "") or value == float(text), name
        assert table["failure"][r] == row[-3]
        assert table["note"][r] == row[-2]


def test_compare_at_the_expert_settings_gives_the_programs_metrics(tmp_path):
    run_cli("compare", "bouncing_ball", "--engines", "bullet", "--settings", "expert",
            "--duration", "0.5", "--out", tmp_path, "--no-plots")
    table, _ = impactbench.compare("bouncing_ball", engines=["bullet"], duration=0.5,
                                   settings="expert", as_frame=False)
    header, rows = read_csv(tmp_path / "metrics.csv")
    assert table["engine"] == ["bullet (expert)"] == [rows[0][0]]
    for name, text in zip(header[1:-3], rows[0][1:-3]):
        if name not in TIMES:
            value = table[name][0]
            assert (math.isnan(value) and text == "") or value == float(text), name


def test_compare_refusals_carry_the_programs_message(tmp_path):
    for args, kw in [(("--engines", "moreau,moreau"), {"engines": ["moreau", "moreau"]}),
                     (("--option", "theta=1"), {"options": {"theta": 1}}),
                     (("--engines", "moreau", "--option", "box2d.velocity_iterations=8"),
                      {"engines": ["moreau"], "options": {"box2d.velocity_iterations": 8}}),
                     (("--settings", "tuned"), {"settings": "tuned"})]:
        code, message = cli_message("compare", "bouncing_ball", *args, "--out", tmp_path / "o")
        with pytest.raises(impactbench.Error) as raised:
            impactbench.compare("bouncing_ball", **kw)
        assert str(raised.value) == message
        assert raised.value.exit_code == code


# A planar bounce; sphere_spin's spatial slip and roll (its quaternion reported as a rotation
# vector) with the friction and restitution gains.
@pytest.mark.parametrize("name, duration, parameter_gains", [("bouncing_ball", 0.8, False),
                                                             ("sphere_spin", 0.5, True)])
def test_sensitivity_gives_the_programs_gains(tmp_path, name, duration, parameter_gains):
    flags = ["--parameter-gains"] if parameter_gains else []
    run_cli("sensitivity", name, "--duration", str(duration), *flags, "--out", tmp_path / "g.csv")
    result = impactbench.sensitivity(name, duration=duration, parameter_gains=parameter_gains)
    header, rows = read_csv(tmp_path / "g.csv")
    assert header == ["kind", "event", "t", "order", "micro_events", "matrix", "row", "col",
                      "value"]
    n = len(result["state_names"])
    checked = 0
    for kind, event, t, order, micro, matrix, row, col, value in rows:
        if kind == "jump_gain":
            e = result["events"][int(event)]
            assert float(t) == e["t"]
            gain = next(g for g in e["gains"] if " ".join(map(str, g["order"])) == order)
            assert micro == " ".join(gain["micro_events"])
            array = gain[matrix]
        else:
            assert float(t) == result["t_end"]
            array = result["end_point_" + matrix]
        assert float(value) == array[int(row), int(col)]  # written with 17 digits: exact
        checked += 1
    expected = sum(g["Gz"].size + g["Gv"].size for e in result["events"] for g in e["gains"])
    assert checked == expected + result["end_point_state"].size + result["end_point_input"].size
    assert result["end_point_state"].shape == (n, n)
    assert len(result["events"]) > 0
    if name == "sphere_spin":  # 6 tangent positions, 6 velocities, μ and e
        assert result["state_names"] == [
            "ball.x", "ball.y", "ball.z", "ball.rx", "ball.ry", "ball.rz", "ball.vx", "ball.vy",
            "ball.vz", "ball.wx", "ball.wy", "ball.wz", "friction", "restitution"]


# An unknown scenario; a spatial one whose run reaches an event without a first-order gain
# (the cube's rest, a Zeno accumulation).
@pytest.mark.parametrize("name", ["no_such", "cube_toss"])
def test_sensitivity_refusal_carries_the_programs_message(tmp_path, name):
    code, message = cli_message("sensitivity", name, "--out", tmp_path / "g.csv")
    with pytest.raises(impactbench.Error) as raised:
        impactbench.sensitivity(name)
    assert str(raised.value) == message
    assert not (tmp_path / "g.csv").exists()
