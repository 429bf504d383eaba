"""`essaim debug --serve`: the live page of a debug session in headless Chromium. Stopped at a
breakpoint it says "paused by the debugger" with the tick and rings the robot whose thread the
client looked at last; the run controls are hidden (the editor drives the run); the run's end
after a continue. Needs what test_live_browser.py needs."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "app"))  # the little DAP client

from test_debug_serve import live_view_url  # noqa: E402
from test_debug_smoke import start  # noqa: E402
from test_live_browser import browser  # noqa: E402,F401  (the fixture)

STATE = "document.getElementById('state').textContent"


def test_the_page_rings_the_selected_robot_and_hides_the_run_controls(tmp_path, browser):  # noqa: F811
    dap = start(tmp_path, "--serve", "0")
    dap.request("setBreakpoints", source={"path": "c.lua"},
                breakpoints=[{"line": 4, "condition": 'robot.id == "fb1" and tick == 5'}])
    dap.request("configurationDone")
    url = live_view_url(dap)
    dap.event("stopped")
    page = browser.new_page(viewport={"width": 1200, "height": 760})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(url)
    page.wait_for_function(f"{STATE} === 'paused by the debugger, tick 5: fb1'", timeout=20000)
    page.wait_for_function("essaimLive.highlighted() === 'fb1'", timeout=10000)
    assert page.is_visible("#debugNote") and not page.is_visible("#play") and not page.is_visible("#reset")
    dap.request("stackTrace", threadId=2)
    page.wait_for_function("essaimLive.highlighted() === 'fb0'", timeout=10000)
    assert page.text_content("#state") == "paused by the debugger, tick 5: fb0"
    dap.request("setBreakpoints", source={"path": "c.lua"}, breakpoints=[])
    dap.request("continue", threadId=3)
    dap.event("exited")
    page.wait_for_function(f"{STATE} === 'the run has ended' && essaimLive.highlighted() === ''", timeout=10000)
    dap.request("disconnect")
    assert dap.p.wait(timeout=60) == 0
    assert errors == []
