"""Stepping in `essaim debug` on the shipped foraging experiment (5 robots, 40 ticks): step
over, in and out land on the expected lines (past the end of step(): the same robot's next
step()); stepping back returns to the robot's previous step() and shows what was seen there
the first time (a robot whose controller failed: the boundary before that tick);
reverse-continue returns to the previous hit; run to tick, pause and stop on
entry stop at tick boundaries. Going back changes nothing: the recording of such a session is
byte for byte that of `essaim run`."""
import json

from debug_support import ACTIONS, FIRST, SHORT, WHEELS, controller, essaim_run, insert_after, line_of, recording

SENSING_FIRST = "local p = { tick = tick }"   # controllers/foraging/sensing.lua, percepts()'s first line


def where(dap, thread):
    """(file name, line, function name) of the thread's innermost frame."""
    top = dap.frames(thread)[0]
    return (top["source"]["path"].rsplit("/", 1)[-1] if top.get("source") else None), top["line"], top["name"]


def snapshot(dap, thread) -> str:
    """What the robot sees and holds at the stop, as one exact string: its readings (proximity,
    position), its wheel speeds so far, and the controller's tick."""
    frame = dap.frames(thread)[0]["id"]
    return dap.value(
        '(function() local s = string.format("%d %.17g %.17g", tick, robot.positioning.position.x, '
        'robot.positioning.position.y) for i = 1, #robot.proximity do '
        's = s .. string.format(" %.17g", robot.proximity[i].value) end return s end)()', frame).strip('"')


def test_step_over_in_and_out_land_on_the_expected_lines(argos, tmp_path, session):
    script = controller(argos)
    first, actions, wheels = (line_of(script, t) for t in (FIRST, ACTIONS, WHEELS))
    sensing_first = line_of(script.parent / "foraging" / "sensing.lua", SENSING_FIRST)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": actions, "condition": 'robot.id == "fb1" and tick == 4'}]})
    fb1 = dap.stopped()["threadId"]
    assert fb1 == dap.threads()["fb1"] and where(dap, fb1) == ("foraging.lua", actions, "step")

    # over: the calls of the line run whole
    stop = dap.resume("next", fb1)
    assert stop["reason"] == "step" and stop["threadId"] == fb1
    assert where(dap, fb1) == ("foraging.lua", wheels, "step")
    # out of step(): the same robot's next step(), first line (tick 5; the other robots ran)
    stop = dap.resume("stepOut", fb1)
    assert stop["reason"] == "step" and stop["threadId"] == fb1
    assert where(dap, fb1) == ("foraging.lua", first, "step")
    assert dap.value("tick", dap.frames(fb1)[0]["id"]) == "4"
    dap.resume("next", fb1)
    assert where(dap, fb1) == ("foraging.lua", actions, "step")
    # in: sensing.percepts(robot, tick), the first call on the line
    stop = dap.resume("stepIn", fb1)
    assert stop["reason"] == "step"
    path, line, name = where(dap, fb1)
    assert (path, line) == ("sensing.lua", sensing_first) and "percepts" in name
    assert len(dap.frames(fb1)) == 2
    # out: back in step(), after the line that called it (behaviour.step ran whole)
    dap.resume("stepOut", fb1)
    assert where(dap, fb1) == ("foraging.lua", wheels, "step")
    assert dap.value("tick", dap.frames(fb1)[0]["id"]) == "5"
    assert dap.run_to_end(fb1) == 0


def test_step_back_returns_to_the_previous_tick_with_the_values_seen_there(essaim, argos, tmp_path, session):
    script = controller(argos)
    first, wheels = line_of(script, FIRST), line_of(script, WHEELS)
    essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    dap = session([argos, *SHORT, "--record", "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": wheels, "condition": 'robot.id == "fb2" and tick >= 12'}]})
    fb2 = dap.stopped()["threadId"]
    seen = {}
    for tick in (12, 13):
        seen[tick] = snapshot(dap, fb2)
        assert seen[tick].split()[0] == str(tick)
        if tick == 12:
            dap.request("continue", {"threadId": fb2})
            assert dap.stopped()["threadId"] == fb2

    # back from tick 13 to the first line of fb2's step() at tick 12: readings of tick 12
    stop = dap.resume("stepBack", fb2)
    assert stop["reason"] == "step" and stop["threadId"] == fb2
    assert where(dap, fb2) == ("foraging.lua", first, "step")
    again = snapshot(dap, fb2).split()
    assert again[0] == "11"  # the upvalue before `tick = tick + 1`
    assert again[1:] == seen[12].split()[1:]
    # forward again: the breakpoint at tick 12, then 13, exactly as the first time
    for tick in (12, 13):
        dap.request("continue", {"threadId": fb2})
        stop = dap.stopped()
        assert stop["reason"] == "breakpoint" and snapshot(dap, fb2) == seen[tick]

    # from a tick boundary: back to the robot's step() one tick earlier
    dap.set_breakpoints(script, [])
    stop = dap.resume("runToTick", fb2, tick=20)
    assert stop["reason"] == "goto"
    stop = dap.resume("stepBack", fb2)
    assert where(dap, fb2) == ("foraging.lua", first, "step") and snapshot(dap, fb2).split()[0] == "18"
    assert dap.run_to_end(fb2) == 0
    assert (tmp_path / "dbg" / "recording.bin").read_bytes() == (tmp_path / "ref" / "recording.bin").read_bytes()


def test_reverse_continue_returns_to_the_previous_hit_then_to_the_start(argos, tmp_path, session):
    script, wheels = controller(argos), line_of(controller(argos), WHEELS)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": wheels, "condition": 'robot.id == "fb0" and tick % 5 == 0'}]})
    fb0 = dap.stopped()["threadId"]
    seen = {5: snapshot(dap, fb0)}
    for tick in (10, 15):
        dap.request("continue", {"threadId": fb0})
        dap.stopped()
        seen[tick] = snapshot(dap, fb0)
    assert [s.split()[0] for s in seen.values()] == ["5", "10", "15"]
    for tick in (10, 5):
        stop = dap.resume("reverseContinue", fb0)
        assert stop["reason"] == "breakpoint" and stop["threadId"] == fb0
        assert where(dap, fb0) == ("foraging.lua", wheels, "step")
        assert snapshot(dap, fb0) == seen[tick]
    # no hit before tick 5: the start of the run
    stop = dap.resume("reverseContinue", fb0)
    assert stop["reason"] == "entry"
    assert dap.frames(fb0)[0]["name"] == "before tick 1"
    dap.request("continue", {"threadId": fb0})
    assert dap.stopped()["reason"] == "breakpoint" and snapshot(dap, fb0) == seen[5]
    dap.set_breakpoints(script, [])
    assert dap.run_to_end(fb0) == 0


def test_stop_on_entry_and_run_to_tick_stop_at_tick_boundaries(essaim, argos, tmp_path, session):
    essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    ids, frames, unit = recording(tmp_path / "ref" / "recording.bin")
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(stop_on_entry=True)
    stop = dap.stopped()
    assert stop["reason"] == "entry"
    threads = dap.threads()
    for thread in threads.values():
        [frame] = dap.frames(thread)
        assert frame["name"] == "before tick 1" and not frame.get("source")

    stop = dap.resume("runToTick", threads["fb3"], tick=25)
    assert stop["reason"] == "goto" and stop["description"] == "before tick 25"
    [frame] = dap.frames(threads["fb3"])
    assert frame["name"] == "before tick 25"
    scopes = dap.scopes(frame["id"])
    assert set(scopes) == {"Globals", "robot"}
    glob = dap.variables(scopes["Globals"])
    assert "decision_count" in glob and "step" in glob  # the controller's globals ...
    assert not {"string", "math", "table", "coroutine"} & set(glob)  # ... not the standard libraries
    # readings of tick 24, the last sensed: the recording's pose of that tick
    robot = dap.variables(scopes["robot"])
    assert robot["id"]["value"] == '"fb3"' and "positioning" in robot and "proximity" in robot
    x, y, _ = frames[24][ids.index("fb3")]
    assert abs(float(dap.value("robot.positioning.position.x", frame["id"])) - x) <= unit
    assert abs(float(dap.value("robot.positioning.position.y", frame["id"])) - y) <= unit
    # the loop functions' thread has its globals only
    [frame] = dap.frames(1)
    assert frame["name"] == "before tick 25" and set(dap.scopes(frame["id"])) == {"Globals"}

    assert dap.run_to_end(threads["fb3"]) == 0


def test_pause_stops_at_the_next_tick_boundary_and_terminate_ends_the_run_cleanly(argos, tmp_path, session):
    # long enough that the pause arrives while it runs
    dap = session([argos, "--ticks", "1000000", "--seed", "3", "--set", "arena.distribute.entity.quantity=2",
                   "--out", tmp_path / "dbg"])
    dap.start()
    dap.request("pause", {"threadId": 2})
    stop = dap.stopped()
    assert stop["reason"] == "pause" and stop["threadId"] == 2
    [frame] = dap.frames(2)
    assert frame["name"].startswith("before tick ")
    tick = int(frame["name"].split()[-1])
    dap.request("terminate")
    assert dap.finish() == 0
    summary = json.loads((tmp_path / "dbg" / "summary.json").read_text())
    assert summary["ticks"] in (tick - 1, tick)  # ended where it was paused


def test_step_back_of_a_robot_that_did_not_run_stops_at_the_boundary_before_that_tick(argos, tmp_path, session):
    """fb1's controller fails at tick 6 (essaim run then stops that robot): from tick 9, its
    previous step() does not exist; stepBack stops before tick 8 (docs/debug-contract.md)."""
    script = controller(argos)
    insert_after(script, FIRST, '  if robot.id == "fb1" and tick == 6 then error("injected failure") end')
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": 'robot.id == "fb3" and tick == 9'}]})
    dap.stopped()
    fb1 = dap.threads()["fb1"]
    stop = dap.resume("stepBack", fb1)
    assert stop["reason"] == "step"
    assert [f["name"] for f in dap.frames(fb1)] == ["before tick 8"]
    dap.set_breakpoints(script, [])
    assert dap.run_to_end(fb1) == 0
