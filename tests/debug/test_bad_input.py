"""Bad input given to `essaim debug` is reported to the editor, as `essaim run` reports it
on the terminal, and the process exits as `essaim run` does (2: nothing was run): an
experiment that does not load fails the launch request with the file:line message; a
controller with a syntax error is an error output event naming the script and line, then
the exited event with code 2. (Bad breakpoints: test_breakpoints.py.)"""
from debug_support import controller, insert_after


def test_an_experiment_that_does_not_load_fails_the_launch(argos, tmp_path, session):
    text = argos.read_text().replace("<arena size=", '<arena sizze="1" size=')
    argos.write_text(text)
    line = next(n for n, l in enumerate(text.splitlines(), 1) if "sizze" in l)
    dap = session([])
    dap.request("initialize", {"adapterID": "essaim", "pathFormat": "path"})
    failed = dap.request_error("launch", {"experiment": str(argos), "args": ["--strict", "--ticks", "5"]})
    assert failed["message"].startswith(f"{argos}:{line}: <arena>: ") and "sizze" in failed["message"]
    dap.send("disconnect", {})  # what an editor sends after a failed launch
    assert dap.wait_exit() == 2


def test_a_controller_that_does_not_compile_is_an_error_event_and_exit_2(argos, tmp_path, session):
    script = controller(argos)
    insert_after(script, "function step()", "  local broken = = 1")
    dap = session([argos, "--ticks", "5", "--out", tmp_path / "dbg"])
    dap.start()
    assert dap.wait_event("exited")["body"]["exitCode"] == 2
    assert dap.finish() == 2
    errors = "".join(dap.outputs("stderr"))
    assert "foraging.lua:" in errors and "unexpected symbol near '='" in errors, dap.outputs()
