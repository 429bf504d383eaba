"""`essaim -c FILE.argos` and `essaim FILE.argos` run the file like `essaim run FILE.argos`."""
import json

from clitest import CONTROLLER, argos, essaim, need_essaim, write

pytestmark = need_essaim


def test_dash_c_and_a_bare_file_run_it_with_a_hint(tmp_path):
    write(tmp_path, {"x.argos": argos(), "c.lua": CONTROLLER})
    for args, out in ((["-c", "x.argos", "--ticks", "3", "--out", "a"], "a"),
                      (["x.argos", "--ticks", "4", "--out", "b"], "b"),
                      (["--config-file", "x.argos", "--ticks", "5", "-q", "--out", "c"], "c")):
        r = essaim(*args, cwd=tmp_path)
        assert r.returncode == 0, r.stderr
        assert f"runs as 'essaim run x.argos'" in r.stderr.splitlines()[0], r.stderr
        summary = json.loads((tmp_path / out / "summary.json").read_text())
        assert summary["status"] == "ok" and summary["ticks"] == int(args[args.index("--ticks") + 1])


def test_a_bare_unknown_word_is_still_an_unknown_command(tmp_path):
    r = essaim("rnu", cwd=tmp_path)
    assert r.returncode == 2 and "unknown command 'rnu' (did you mean 'run'?)" in r.stderr
