"""Breakpoints of `essaim debug` on the shipped foraging experiment (5 robots, 40 ticks):
a conditional breakpoint stops the right robot at the right tick, and what the session shows
there (locals, upvalues, robot.proximity, robot.positioning) is what a log() line in the same
place prints under `essaim run` and what the recording holds; breakpoints in a `require`d
module, function breakpoints with hit counts, logpoints; and the bad input: a file no robot
runs, a condition that does not compile, a condition that raises, a hit condition that is
not one."""
import pytest

from debug_support import (ACTIONS, FIRST, ROBOTS, SHORT, WHEELS, add_log_line, controller, essaim_run,
                           line_of, logged, recording)

# the names of a table's entries, "[1]" or "1" as an adapter may show them
def entries(variables: dict) -> dict:
    return {name.strip("[]"): v for name, v in variables.items()}


def number(variable: dict) -> float:
    return float(variable["value"])


def test_a_conditional_breakpoint_stops_that_robot_at_that_tick_with_the_values_log_and_the_recording_give(
        essaim, argos, tmp_path, session):
    add_log_line(argos)
    ref, _ = essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    assert ref.returncode == 0, ref.stderr
    expected = logged(ref.stdout)[("fb3", 17)]
    ids, frames, unit = recording(tmp_path / "ref" / "recording.bin")
    script, line = controller(argos), line_of(controller(argos), WHEELS)

    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    started = dap.start(breakpoints={script: [{"line": line, "condition": 'robot.id == "fb3" and tick == 17'}]})
    caps = started["capabilities"]
    for cap in ("supportsConfigurationDoneRequest", "supportsConditionalBreakpoints", "supportsLogPoints",
                "supportsHitConditionalBreakpoints", "supportsFunctionBreakpoints", "supportsStepBack",
                "supportsSetVariable", "supportsEvaluateForHovers", "supportsTerminateRequest"):
        assert caps.get(cap) is True, cap
    assert {"filter": "error", "label": "Controller errors", "default": False} in caps["exceptionBreakpointFilters"]
    [bp] = started["breakpoints"][script]
    assert bp["verified"] and bp["line"] == line

    stop = dap.stopped()
    assert stop["reason"] == "breakpoint" and stop["allThreadsStopped"] is True
    threads = dap.threads()
    assert threads == {"loop functions": 1, **{robot: i + 2 for i, robot in enumerate(ids)}}
    assert stop["threadId"] == threads["fb3"] == ids.index("fb3") + 2

    top = dap.frames(stop["threadId"])[0]
    assert top["name"] == "step" and top["line"] == line
    assert top["source"]["path"] == str(script)
    scopes = dap.scopes(top["id"])
    assert {"Locals", "Upvalues", "Globals", "robot"} <= set(scopes)

    # Locals and upvalues: actions (the wheel speeds just computed) and the controller's tick.
    actions = dap.variables(dap.variables(scopes["Locals"])["actions"]["variablesReference"])
    assert number(actions["left"]) == pytest.approx(expected["left"], rel=1e-12, abs=1e-12)
    assert number(actions["right"]) == pytest.approx(expected["right"], rel=1e-12, abs=1e-12)
    assert dap.variables(scopes["Upvalues"])["tick"]["value"] == "17"
    exact = dap.value('string.format("%.17g %.17g", actions.left, actions.right)', top["id"]).strip("\"'")
    assert [float(x) for x in exact.split()] == [expected["left"], expected["right"]]

    # robot.proximity as the controller sees it: 24 {value, angle}, as log() printed them.
    robot = dap.variables(scopes["robot"])
    proximity = entries(dap.variables(robot["proximity"]["variablesReference"]))
    assert len(proximity) == 24
    for i, (value, angle) in enumerate(expected["proximity"], 1):
        reading = dap.variables(proximity[str(i)]["variablesReference"])
        assert number(reading["value"]) == pytest.approx(value, rel=1e-12, abs=1e-12), i
        assert number(reading["angle"]) == pytest.approx(angle, rel=1e-12, abs=1e-12), i

    # robot.positioning: the pose the recording has for that robot at that tick (± its unit).
    x, y, _ = frames[17][ids.index("fb3")]
    assert abs(float(dap.value("robot.positioning.position.x", top["id"])) - x) <= unit
    assert abs(float(dap.value("robot.positioning.position.y", top["id"])) - y) <= unit

    assert dap.run_to_end(stop["threadId"]) == 0
    assert len(dap.events_named("stopped")) == 1  # the condition held once


def test_a_breakpoint_in_a_required_module_shows_both_frames(argos, tmp_path, session):
    module = argos.parent.parent / "controllers" / "foraging" / "sensing.lua"
    line = line_of(module, "local p = { tick = tick }")
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    started = dap.start(breakpoints={module: [{"line": line, "condition": 'robot.id == "fb4" and tick == 5'}]})
    assert started["breakpoints"][module][0]["verified"]
    stop = dap.stopped()
    assert stop["reason"] == "breakpoint" and stop["threadId"] == dap.threads()["fb4"]
    inner, outer = dap.frames(stop["threadId"])[:2]
    assert "percepts" in inner["name"] and inner["line"] == line and inner["source"]["path"] == str(module)
    assert outer["name"] == "step" and outer["line"] == line_of(controller(argos), ACTIONS)
    # the frame's locals: the parameters robot and tick
    scopes = dap.scopes(inner["id"])
    assert dap.variables(scopes["Locals"])["tick"]["value"] == "5"
    assert dap.value("robot.id", inner["id"]).strip("\"'") == "fb4"
    assert dap.run_to_end(stop["threadId"]) == 0


def test_a_breakpoint_moves_to_the_next_line_with_code_and_a_relative_path_starts_at_the_experiment(
        argos, tmp_path, session):
    script = controller(argos)
    blank = line_of(script, "function step()") - 1  # the empty line above step()
    assert script.read_text().splitlines()[blank - 1].strip() == ""
    relative = "../controllers/foraging.lua"  # from arenas/, the experiment's folder
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    [bp] = dap.start(breakpoints={relative: [{"line": blank, "condition": 'robot.id == "fb0"'}]})["breakpoints"][relative]
    assert bp["verified"] and bp["line"] > blank
    stop = dap.stopped()
    top = dap.frames(stop["threadId"])[0]
    assert top["line"] == bp["line"] and top["source"]["path"] == str(script)
    dap.request("terminate")
    assert dap.finish() == 0


def test_function_breakpoints_on_step_and_init_with_a_condition_and_a_hit_count(argos, tmp_path, session):
    script = controller(argos)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    started = dap.start(function_breakpoints=[
        {"name": "init", "condition": 'robot.id == "fb1"'},
        {"name": "step", "condition": 'robot.id == "fb2"', "hitCondition": "3"}])
    assert all(b["verified"] for b in started["function_breakpoints"])

    stop = dap.stopped()  # init() of fb1, at its first line
    assert stop["reason"] == "function breakpoint" and stop["threadId"] == dap.threads()["fb1"]
    top = dap.frames(stop["threadId"])[0]
    assert top["name"] == "init" and top["line"] == line_of(script, "cfg = config.load(robot.params)")

    # step() of fb2: the third hit (tick 3) and every one after (">= 3", as DAP means it)
    for tick in (3, 4):
        dap.request("continue", {"threadId": stop["threadId"]})
        stop = dap.stopped()
        assert stop["reason"] == "function breakpoint" and stop["threadId"] == dap.threads()["fb2"]
        top = dap.frames(stop["threadId"])[0]
        assert top["name"] == "step" and top["line"] == line_of(script, FIRST)
        assert dap.value("tick", top["id"]) == str(tick - 1)  # the upvalue, before `tick = tick + 1`
    dap.request("setFunctionBreakpoints", {"breakpoints": []})
    assert dap.run_to_end(stop["threadId"]) == 0


def test_hit_conditions_count_hits_of_the_condition(argos, tmp_path, session):
    script, line = controller(argos), line_of(controller(argos), ACTIONS)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line, "condition": 'robot.id == "fb0"', "hitCondition": "%10"}]})
    seen = []
    for _ in range(4):
        stop = dap.stopped()
        seen.append(int(dap.value("tick", dap.frames(stop["threadId"])[0]["id"])))
        dap.request("continue", {"threadId": stop["threadId"]})
    assert seen == [10, 20, 30, 40]
    assert dap.finish() == 0


def test_logpoints_print_each_hit_and_never_stop(essaim, argos, tmp_path, session):
    add_log_line(argos)
    ref, _ = essaim_run(essaim, argos, SHORT, tmp_path / "ref", tmp_path)
    expected = logged(ref.stdout)
    script, line = controller(argos), line_of(controller(argos), WHEELS)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line, "condition": 'robot.id == "fb1"',
                                     "logMessage": "left={actions.left} right={actions.right} id={robot.id}"}]})
    assert dap.finish() == 0
    assert dap.events_named("stopped") == []
    lines = [t for t in dap.outputs("console") if t.startswith("fb1 tick ")]
    assert len(lines) == 40
    for tick, text in enumerate(lines, 1):
        assert text.endswith("\n")
        head, _, message = text.rstrip("\n").partition(": ")
        assert head == f"fb1 tick {tick}"
        words = dict(w.split("=", 1) for w in message.split())
        assert words["id"] == "fb1"
        assert float(words["left"]) == pytest.approx(expected[("fb1", tick)]["left"], rel=1e-12, abs=1e-12)
        assert float(words["right"]) == pytest.approx(expected[("fb1", tick)]["right"], rel=1e-12, abs=1e-12)


def test_bad_breakpoints_are_reported_and_do_not_stop_the_run(argos, tmp_path, session):
    script = controller(argos)
    # A Lua file away from the experiment and its scripts (one beside or below them might be
    # `require`d later: docs/debug-contract.md counts those as run).
    other = tmp_path / "elsewhere" / "other.lua"
    other.parent.mkdir()
    other.write_text("local x = 1\nlocal y = 2\nreturn x + y\n")
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    started = dap.start(breakpoints={
        other: [3],
        script: [{"line": line_of(script, ACTIONS), "condition": "robot.id =="},  # does not compile
                 {"line": line_of(script, WHEELS), "condition": 'robot.nothing.x > 1 or robot.id == "fb0"'},
                 {"line": line_of(script, FIRST), "hitCondition": "sometimes"}]})
    [unrun] = started["breakpoints"][other]
    assert unrun["verified"] is False
    assert "other.lua" in unrun["message"] and "no controller or loop function" in unrun["message"]
    syntax, raising, hits = started["breakpoints"][script]
    assert syntax["verified"] is False and syntax["message"].startswith("condition: ")
    assert raising["verified"] is True
    assert hits["verified"] is False and hits["message"].startswith("hitCondition")

    assert dap.finish() == 0
    assert dap.events_named("stopped") == []
    errors = [t for t in dap.outputs("console") if "condition error: " in t]
    # every robot, every tick: "fb0 tick 1: condition error: <Lua's message>"
    assert len(errors) == ROBOTS * 40, errors[:3]
    assert errors[0].startswith("fb0 tick 1: condition error: ") and "nothing" in errors[0]
    assert (tmp_path / "dbg" / "summary.json").exists()


def test_a_breakpoint_in_the_loop_functions_stops_their_thread_where_tick_is_the_current_tick(
        argos, tmp_path, session):
    loop = argos.parent / "foraging_loop.lua"
    line = line_of(loop, "local tick = experiment.tick")  # pre_step(): no `tick` in scope yet
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    [bp] = dap.start(breakpoints={loop: [{"line": line, "condition": "tick == 7"}]})["breakpoints"][loop]
    assert bp["verified"] and bp["line"] == line
    stop = dap.stopped()
    assert stop["reason"] == "breakpoint" and stop["threadId"] == 1
    top = dap.frames(1)[0]
    assert top["line"] == line and top["source"]["path"] == str(loop)
    assert dap.value("experiment.tick", top["id"]) == "7"
    assert "robot" not in dap.scopes(top["id"])  # the loop functions have no robot table
    dap.request("next", {"threadId": 1})
    dap.stopped()
    assert dap.variables(dap.scopes(dap.frames(1)[0]["id"])["Locals"])["tick"]["value"] == "7"
    dap.set_breakpoints(loop, [])
    assert dap.run_to_end(1) == 0
