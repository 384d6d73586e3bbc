"""scenarios() and describe() against `impactbench list` and `impactbench describe`."""

import re

import pytest

import impactbench
from conftest import cli_message, run_cli


def test_scenarios_are_the_programs_list():
    _, out, _ = run_cli("list")
    assert impactbench.scenarios() == out.split()


@pytest.mark.parametrize("name,overrides", [("bouncing_ball", {}),
                                            ("bouncing_ball", {"restitution": 0.5}),
                                            ("plank_box", {})])
def test_describe_holds_what_the_program_prints(name, overrides):
    sets = [a for k, v in overrides.items() for a in ("--set", f"{k}={v!r}")]
    _, out, _ = run_cli("describe", name, *sets)
    d = impactbench.describe(name, set=overrides)
    lines = out.splitlines()
    assert f"name: {d['name']}" in lines
    assert f"engines: {', '.join(d['engines'])}" in lines
    assert f"file: {d['file']}" in lines
    # Every number is printed as shortest round-trip text: reading it back is exact.
    assert float(re.search(r"^duration: (\S+) s$", out, re.M).group(1)) == d["duration"]
    assert float(re.search(r"^dt: (\S+) s$", out, re.M).group(1)) == d["dt"]
    for p in d["parameters"]:
        match = re.search(rf"^  {re.escape(p['name'])}\s+= (\S+) ", out, re.M)
        assert match, p["name"]
        assert float(match.group(1)) == p["value"]
    for k, v in overrides.items():
        assert next(p for p in d["parameters"] if p["name"] == k)["value"] == v
    for engine, settings in d["settings"].items():
        block = out.split(f"settings of {engine}:\n")[1].split(":\n")[0]
        for s in settings:
            assert f"  {s['key']} = {s['value']} ({s['source']})" in block
    for q in d["analytic"]:
        label = q["name"] + ("(k)" if q["indexed"] else "")
        match = re.search(rf"^  {re.escape(label)}\s+= (\S+) ", out, re.M)
        assert match and float(match.group(1)) == q["value"], label


@pytest.mark.parametrize("args,call", [
    (("describe", "no_such_scenario"), lambda: impactbench.describe("no_such_scenario")),
    (("describe", "bouncing_ball", "--set", "no_such=1"),
     lambda: impactbench.describe("bouncing_ball", set={"no_such": 1})),
    (("describe", "bouncing_ball", "--set", "restitution=nan"),
     lambda: impactbench.describe("bouncing_ball", set={"restitution": float("nan")})),
])
def test_refusals_carry_the_programs_message(args, call):
    code, message = cli_message(*args)
    with pytest.raises(impactbench.Error) as raised:
        call()
    assert str(raised.value) == message
    assert raised.value.exit_code == code
    assert isinstance(raised.value, RuntimeError) and isinstance(raised.value, ValueError)
