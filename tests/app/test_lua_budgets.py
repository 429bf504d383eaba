"""The two instruction budgets: per step() (--lua-budget, <system lua_budget>) and per setup
call (--lua-init-budget, <system lua_init_budget>), each set alone, and bad values refused."""
from clitest import argos, need_essaim, run, write

pytestmark = need_essaim

SPIN_IN_INIT = "function init() while true do end end\nfunction step() end\n"
BUSY_INIT = "function init() local n = 0 for i = 1, 3000000 do n = n + i end end\nfunction step() end\n"


def with_system(attributes):
    return argos(robots=1).replace("<experiment ", f"<system {attributes} />\n    <experiment ")


def test_init_budget_stops_init_and_names_its_option(tmp_path):
    write(tmp_path, {"x.argos": argos(robots=1), "c.lua": SPIN_IN_INIT})
    r, s = run(tmp_path, "x.argos", "--lua-init-budget", "1e6")
    assert r.returncode == 0, r.stderr
    assert "c.lua:1: instruction budget exceeded (1000000 instructions per call, --lua-init-budget)" \
        in s["controller_errors"][0]["message"]


def test_a_small_step_budget_leaves_init_its_own(tmp_path):
    # --sandbox counts from the first instruction (10^8 for both kinds of call): 3e6 loop
    # iterations in init() (~10^7 instructions) pass under the setup budget whatever the
    # file's step budget says, and the file's lua_init_budget stops them.
    write(tmp_path, {"x.argos": with_system('lua_budget="1000000"'), "c.lua": BUSY_INIT})
    r, s = run(tmp_path, "x.argos", "--sandbox")
    assert r.returncode == 0 and s["controller_errors"] == [], r.stderr
    write(tmp_path, {"x.argos": with_system('lua_init_budget="1000000"')})
    r, s = run(tmp_path, "x.argos", "--sandbox", out="out2")
    assert "(1000000 instructions per call, --lua-init-budget)" in s["controller_errors"][0]["message"]


def test_bad_init_budgets_are_bad_input(tmp_path):
    write(tmp_path, {"x.argos": with_system('lua_init_budget="-1"'), "c.lua": BUSY_INIT})
    r, _ = run(tmp_path, "x.argos")
    assert r.returncode == 2
    assert "lua_init_budget must be >= 0 (instructions per init(), reset() or top-level call; 0 = unlimited)" \
        in r.stderr, r.stderr
    write(tmp_path, {"x.argos": argos(robots=1)})
    r, _ = run(tmp_path, "x.argos", "--lua-init-budget", "-3", out="out2")
    assert r.returncode == 2 and "--lua-init-budget: '-3' must be a non-negative integer" in r.stderr, r.stderr
