"""What an `essaim debug` session leaves, on the shipped foraging experiment (5 robots, 40
ticks): run to its end, it writes what `essaim run` writes (the same summary, metrics and log
lines, the same recording bytes), and its log lines reach the client as output events; a
variable set by hand changes the run and is listed in summary.json as a divergence; break on
error stops at the raising line and the run then ends as `essaim run` ends it; a client that
disconnects, or closes the connection, leaves a run that ends cleanly with its summary."""
import pytest

from debug_support import (FIRST, ROOT, SHORT, WHEELS, add_log_line, comparable, controller, essaim_run, insert_after,
                           line_of, recording, summary)


def same_run(ref, dbg):
    """The outputs of two runs agree: summary (less times and paths), metrics, recording."""
    assert comparable(summary(dbg)) == comparable(summary(ref))
    assert (dbg / "metrics.json").read_text() == (ref / "metrics.json").read_text()
    if (ref / "recording.bin").exists():
        assert (dbg / "recording.bin").read_bytes() == (ref / "recording.bin").read_bytes()


def stop_at_fb2_tick_10(essaim, argos, tmp_path, session):
    """A recorded reference run, then a recorded debug session stopped at fb2's wheels line at
    tick 10: the session, fb2's thread, its frame and the reference of its `actions` local."""
    essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    script = controller(argos)
    dap = session([argos, *SHORT, "--record", "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": 'robot.id == "fb2" and tick == 10'}]})
    fb2 = dap.stopped()["threadId"]
    frame = dap.frames(fb2)[0]["id"]
    actions = dap.variables(dap.scopes(frame)["Locals"])["actions"]["variablesReference"]
    return dap, script, fb2, frame, actions


def test_continue_runs_to_the_end_with_the_outputs_of_essaim_run(essaim, argos, tmp_path, session):
    add_log_line(argos)
    ref, _ = essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    assert ref.returncode == 0, ref.stderr
    dap = session([argos, *SHORT, "--record", "--out", tmp_path / "dbg"])
    dap.start()
    assert dap.finish() == 0
    [exited] = dap.events_named("exited")
    assert exited["body"]["exitCode"] == 0
    same_run(tmp_path / "ref", tmp_path / "dbg")
    assert summary(tmp_path / "dbg")["debug"] == {"divergences": []}
    # log() lines: output events of category stdout, in the order `essaim run` printed them
    logged = "".join(dap.outputs("stdout"))
    assert logged.splitlines() == ref.stdout.splitlines()


def test_a_session_that_stops_and_steps_changes_nothing(essaim, argos, tmp_path, session):
    essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    script = controller(argos)
    dap = session([argos, *SHORT, "--record", "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": "tick == 7"}]})
    for _ in range(5):  # every robot at tick 7, with a step over each time
        thread = dap.stopped()["threadId"]
        dap.request("next", {"threadId": thread})
        dap.stopped()
        dap.evaluate("robot.proximity[1].value + #robot.range_and_bearing", dap.frames(thread)[0]["id"])
        dap.request("continue", {"threadId": thread})
    assert dap.finish() == 0
    same_run(tmp_path / "ref", tmp_path / "dbg")
    assert summary(tmp_path / "dbg")["debug"] == {"divergences": []}


def test_setting_a_variable_changes_the_run_and_is_recorded_as_a_divergence(essaim, argos, tmp_path, session):
    dap, script, fb2, frame, actions = stop_at_fb2_tick_10(essaim, argos, tmp_path, session)
    assert float(dap.variables(actions)["left"]["value"]) != 0
    got = dap.request("setVariable", {"variablesReference": actions, "name": "left", "value": "0"})
    assert got["value"] == "0"
    assert dap.value("actions.left", frame) == "0"
    dap.set_breakpoints(script, [])
    assert dap.run_to_end(fb2) == 0

    [divergence] = summary(tmp_path / "dbg")["debug"]["divergences"]
    assert divergence["tick"] == 10 and divergence["thread"] == "fb2"
    assert "left" in divergence["name"] and divergence["value"] == "0"
    # fb2 drove with its left wheel stopped for one tick: its path differs from then on, the
    # others' up to that tick do not
    ids, ref, _ = recording(tmp_path / "ref" / "recording.bin")
    _, dbg, _ = recording(tmp_path / "dbg" / "recording.bin")
    i = ids.index("fb2")
    assert all(dbg[t] == ref[t] for t in range(0, 10))
    assert dbg[40][i] != ref[40][i]


def test_the_repl_evaluates_statements_and_other_robots_are_readable(argos, tmp_path, session):
    script = controller(argos)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": 'robot.id == "fb1" and tick == 3'}]})
    fb1 = dap.stopped()["threadId"]
    frame = dap.frames(fb1)[0]["id"]
    dap.evaluate("probe_value = 3", frame, context="repl")
    assert dap.value("probe_value * 2", frame) == "6"
    hover = dap.evaluate("actions", frame, context="hover")  # a table: opened by its reference
    assert hover["variablesReference"] > 0 and "left" in dap.variables(hover["variablesReference"])
    assert dap.value("robot.id").strip("\"'") == "fb1"  # no frame: the thread that stopped
    fb3 = dap.threads()["fb3"]
    other = dap.frames(fb3)[0]["id"]
    assert dap.value("robot.id", other).strip("\"'") == "fb3"
    assert dap.value("probe_value", other) == "nil"  # each robot its own Lua state
    dap.set_breakpoints(script, [])
    assert dap.run_to_end(fb1) == 0
    [divergence] = summary(tmp_path / "dbg")["debug"]["divergences"]
    assert divergence["thread"] == "fb1" and divergence["tick"] == 3


def test_break_on_error_stops_at_the_raising_line_then_the_run_ends_as_essaim_run_ends_it(
        essaim, argos, tmp_path, session):
    script = controller(argos)
    line = insert_after(script, FIRST, '  if robot.id == "fb1" and tick == 6 then error("injected failure") end')
    ref, _ = essaim_run(essaim, argos, SHORT, tmp_path / "ref", tmp_path)
    assert [e["robot"] for e in summary(tmp_path / "ref")["controller_errors"]] == ["fb1"]

    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(exceptions=["error"])
    stop = dap.stopped()
    assert stop["reason"] == "exception" and stop["threadId"] == dap.threads()["fb1"]
    assert "injected failure" in stop["text"]
    top = dap.frames(stop["threadId"])[0]
    assert top["line"] == line and top["source"]["path"] == str(script)
    assert dap.value("tick", top["id"]) == "6"
    assert dap.run_to_end(stop["threadId"]) == ref.returncode
    same_run(tmp_path / "ref", tmp_path / "dbg")
    assert any("injected failure" in t for t in dap.outputs("stderr"))


def test_without_the_error_filter_a_controller_error_does_not_stop(essaim, argos, tmp_path, session):
    insert_after(controller(argos), FIRST, '  if robot.id == "fb1" and tick == 6 then error("injected failure") end')
    essaim_run(essaim, argos, SHORT, tmp_path / "ref", tmp_path)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start()
    assert dap.finish() == 0
    assert dap.events_named("stopped") == []
    same_run(tmp_path / "ref", tmp_path / "dbg")


@pytest.mark.parametrize("how", ["close", "disconnect"])
def test_a_client_that_leaves_over_tcp_lets_the_run_end_cleanly(essaim, argos, tmp_path, session, how):
    essaim_run(essaim, argos, SHORT + ["--record"], tmp_path / "ref", tmp_path)
    script = controller(argos)
    dap = session([argos, *SHORT, "--record", "--out", tmp_path / "dbg"], tcp=True)
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": "tick >= 9"}]})
    dap.stopped()
    if how == "disconnect":
        dap.request("disconnect", {"terminateDebuggee": False})
    dap.close_connection()
    assert dap.wait_exit() == 0
    same_run(tmp_path / "ref", tmp_path / "dbg")  # the breakpoints went with the client


def test_a_client_that_closes_stdin_lets_the_run_end_cleanly(essaim, argos, tmp_path, session):
    essaim_run(essaim, argos, SHORT, tmp_path / "ref", tmp_path)
    script = controller(argos)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": "tick >= 9"}]})
    dap.stopped()
    dap.close_connection()
    assert dap.wait_exit() == 0
    same_run(tmp_path / "ref", tmp_path / "dbg")


def test_terminate_while_stopped_ends_the_run_there_with_its_outputs(argos, tmp_path, session):
    script = controller(argos)
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg"])
    dap.start(breakpoints={script: [{"line": line_of(script, WHEELS), "condition": 'robot.id == "fb0" and tick == 12'}]})
    dap.stopped()
    dap.request("terminate")
    assert dap.finish() == 0
    s = summary(tmp_path / "dbg")
    assert s["ticks"] in (11, 12) and s["debug"] == {"divergences": []}
    assert (tmp_path / "dbg" / "metrics.json").exists()  # post_experiment ran


def test_the_experiment_and_options_may_come_from_the_launch_request(essaim, argos, tmp_path, session):
    """launch {"experiment", "args", "cwd"}: relative paths from cwd; it overrides the command line's."""
    essaim_run(essaim, "arenas/foraging.argos", SHORT, tmp_path / "ref", tmp_path)
    dap = session([ROOT / "arenas" / "clustering.argos"])  # overridden by launch's experiment
    dap.start(experiment="arenas/foraging.argos", args=[*SHORT, "--out", "dbg"], cwd=tmp_path)
    assert dap.finish() == 0
    same_run(tmp_path / "ref", tmp_path / "dbg")
    assert summary(tmp_path / "dbg")["experiment"] == "arenas/foraging.argos"


def test_going_back_before_a_divergence_drops_it(essaim, argos, tmp_path, session):
    dap, script, fb2, _, actions = stop_at_fb2_tick_10(essaim, argos, tmp_path, session)
    dap.request("setVariable", {"variablesReference": actions, "name": "left", "value": "0"})
    dap.set_breakpoints(script, [])
    assert dap.resume("runToTick", fb2, tick=15)["reason"] == "goto"
    before = len(dap.outputs("console"))
    # back to fb2's step() at tick 10, then 9: before the change, which is dropped, and said so
    for _ in range(6):
        assert dap.resume("stepBack", fb2)["reason"] == "step"
    assert dap.value("tick", dap.frames(fb2)[0]["id"]) == "8"  # first line of tick 9's step()
    assert any("diverg" in t for t in dap.outputs("console")[before:]), dap.outputs("console")[before:]
    assert dap.run_to_end(fb2) == 0
    assert summary(tmp_path / "dbg")["debug"] == {"divergences": []}
    same_run(tmp_path / "ref", tmp_path / "dbg")
