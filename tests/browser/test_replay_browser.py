"""Recorded runs end to end: `essaim run --record`, `essaim replay` and `essaim snapshot` from
the command line, then the replay page in headless Chromium (Playwright): it loads, plays,
draws every robot, selects a robot by a click, draws a robot the loop functions added only
from its arrival, and loads a 30-robot 10000-tick run fast.

The browser tests need Python's `playwright` (scripts/requirements.txt; its driver ships in
the wheel) and Debian's chromium (scripts/setup.sh); `playwright install` is never used.
"""
import json
import os
import shutil
import struct
import subprocess
import time
from pathlib import Path

import pytest

CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]

CONTROLLER = """
local speed
function init() speed = tonumber(robot.params.speed) or 5 end
function step()
  local x = robot.positioning.position.x
  robot.wheels.set_velocity(speed, speed * (x > 0 and 0.7 or 0.9))
end
"""

LOOP = """
function floor_color(x, y)
  if x < 0 and y < 0 then return 40, 40, 200 end
  return 255, 255, 255
end
"""


def experiment(robots: str, ticks: int, script: Path, loop: Path, arena=(6, 4)) -> str:
    return f"""<?xml version="1.0" ?>
<argos-configuration>
  <framework><system threads="0"/>
    <experiment length="{ticks / 10}" ticks_per_second="10" random_seed="3"/></framework>
  <controllers>
    <lua_controller id="c">
      <actuators><differential_steering implementation="default"/></actuators>
      <sensors><differential_steering implementation="default"/><positioning implementation="default"/></sensors>
      <params script="{script}" speed="8"/>
    </lua_controller>
  </controllers>
  <loop_functions script="{loop}"/>
  <arena size="{arena[0]},{arena[1]},1" center="0,0,0.5">
    <floor id="f" source="loop_functions" pixels_per_meter="50"/>
    <box id="crate" size="0.3,0.2,0.2" movable="true" mass="1"><body position="2,1,0" orientation="20,0,0"/></box>
    <cylinder id="post" radius="0.15" height="0.3" movable="false"><body position="-2,1.2,0" orientation="0,0,0"/></cylinder>
    {robots}
  </arena>
  <physics_engines><dynamics2d id="dyn2d"/></physics_engines>
  <media/>
</argos-configuration>
"""


def foot_bot(i: int, x: float, y: float, yaw: float) -> str:
    return (f'<foot-bot id="fb{i}"><body position="{x},{y},0" orientation="{yaw},0,0"/>'
            f'<controller config="c"/></foot-bot>')


def make_run(essaim, tmp: Path, name: str, robots: str, ticks: int, record="--record", arena=(6, 4),
             loop=LOOP) -> Path:
    (tmp / "ctrl.lua").write_text(CONTROLLER)
    (tmp / "loop.lua").write_text(loop)
    argos = tmp / f"{name}.argos"
    argos.write_text(experiment(robots, ticks, tmp / "ctrl.lua", tmp / "loop.lua", arena))
    out = tmp / name
    args = [essaim, "run", str(argos), "--out", str(out), "--quiet"] + ([record] if isinstance(record, str) else record)
    proc = subprocess.run(args, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return out


FIVE = "".join(foot_bot(i, x, y, yaw) for i, (x, y, yaw) in
               enumerate([(-2, -1, 0), (-1, 0.5, 45), (0, -1, 90), (1, 0.8, 180), (2, -1.2, 270)]))


@pytest.fixture(scope="module")
def small_run(essaim, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("replay")
    return make_run(essaim, tmp, "small", FIVE, 200)


# ---- command line ------------------------------------------------------------------------

def test_record_is_listed_and_every_n_is_accepted(essaim, tmp_path, small_run):
    summary = json.loads((small_run / "summary.json").read_text())
    assert "recording.bin" in summary["outputs"]
    assert not list(small_run.glob("*.tmp.*")), "temporary files left behind"
    rec = (small_run / "recording.bin").read_bytes()
    assert rec[:8] == b"ESSAIMRC"
    # --record every=5 and --record=every=5: same file, ~1/5 of the frames.
    a = make_run(essaim, tmp_path, "a", FIVE, 200, record=["--record", "every=5"])
    b = make_run(essaim, tmp_path, "b", FIVE, 200, record="--record=every=5")
    ra, rb = (a / "recording.bin").read_bytes(), (b / "recording.bin").read_bytes()
    assert len(ra) == len(rb)
    assert struct.unpack_from("<I", ra, 20)[0] == struct.unpack_from("<I", rb, 20)[0] == 5  # every
    assert len(ra) < len(rec) / 3
    bad = subprocess.run([essaim, "run", str(tmp_path / "a.argos"), "--record=every=0", "--quiet",
                          "--out", str(tmp_path / "bad")], capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and "--record" in bad.stderr


def test_replay_writes_one_self_contained_page(essaim, small_run):
    proc = subprocess.run([essaim, "replay", str(small_run)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    page = Path(proc.stdout.strip())
    assert page == small_run / "replay.html"
    html = page.read_text()
    assert "@ESSAIM_RECORDING@" not in html
    for needle in ("http://", "https://", "fetch(", "<link", "src="):
        assert needle not in html, f"the page must fetch nothing: found {needle!r}"


def test_snapshot_and_its_errors(essaim, small_run, tmp_path):
    out = tmp_path / "frame.png"
    proc = subprocess.run([essaim, "snapshot", str(small_run), "--tick", "100", "-o", str(out),
                           "--trail", "50", "--size", "300"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    png = out.read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    assert (width, height) == (300, 200)  # the 6 m x 4 m arena
    late = subprocess.run([essaim, "snapshot", str(small_run), "--tick", "5000", "-o", str(out)],
                          capture_output=True, text=True, timeout=60)
    assert late.returncode == 2 and "holds ticks 0 to 200" in late.stderr
    (tmp_path / "empty").mkdir()
    none = subprocess.run([essaim, "replay", str(tmp_path / "empty")], capture_output=True, text=True, timeout=60)
    assert none.returncode == 2 and "--record" in none.stderr


# ---- browser -----------------------------------------------------------------------------

def chromium_path():
    for p in (os.environ.get("ESSAIM_CHROMIUM"), shutil.which("chromium"), "/usr/bin/chromium"):
        if p and os.access(p, os.X_OK):
            return p
    return None


@pytest.fixture(scope="module")
def browser():
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright missing: install scripts/requirements.txt "
                                                                 "into .venv")
    exe = chromium_path()
    if not exe:
        pytest.skip("chromium missing: scripts/setup.sh installs Debian's chromium")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=CHROMIUM_ARGS)
        yield b
        b.close()


def open_page(browser, html: Path):
    page = browser.new_page(viewport={"width": 1000, "height": 760})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("request", lambda r: errors.append("request " + r.url) if not r.url.startswith(("file:", "blob:", "data:"))
            else None)
    start = time.monotonic()
    page.goto(html.as_uri())
    page.wait_for_function("window.essaimReplay && (window.essaimReplay.ready || window.essaimReplay.error)",
                           timeout=30000)
    return page, errors, time.monotonic() - start


def test_replay_plays_draws_and_selects(essaim, browser, small_run, tmp_path):
    subprocess.run([essaim, "replay", str(small_run)], check=True, capture_output=True, timeout=60)
    page, errors, _ = open_page(browser, small_run / "replay.html")
    assert page.evaluate("window.essaimReplay.error || ''") == ""
    assert page.get_attribute("#view", "data-robot-count") == "5"
    assert page.evaluate("essaimReplay.robotCount") == 5
    assert page.text_content("#tick") == "0"

    page.click("#play")
    page.wait_for_function("Number(document.getElementById('tick').textContent) > 0", timeout=10000)
    page.click("#play")  # pause
    assert not page.evaluate("essaimReplay.playing()")
    shown = int(page.text_content("#tick"))
    assert 0 < shown <= 200

    # Click robot fb3 where it is drawn now.
    pos = page.evaluate("essaimReplay.robotCanvasPosition(3)")
    page.click("#view", position={"x": pos["x"], "y": pos["y"]})
    selected = page.text_content("#selected")
    assert selected.startswith("fb3"), selected
    assert "battery 100%" in selected
    # The slider scrubs; the tick shown follows it.
    page.eval_on_selector("#slider", "s => { s.value = '150'; s.dispatchEvent(new Event('input')); }")
    assert page.text_content("#tick") == "150"
    page.screenshot(path=str(tmp_path / "replay.png"))
    assert (tmp_path / "replay.png").stat().st_size > 1000
    assert errors == []


JOINING = LOOP + """
function post_step()
  if experiment.tick == 50 then
    experiment.add_entity("foot-bot", {id = "newcomer", controller = "c", position = {0, 1}, orientation = 90})
  end
end
"""


def test_replay_and_snapshot_show_a_robot_added_during_the_run(essaim, browser, tmp_path):
    run = make_run(essaim, tmp_path, "joined", FIVE, 100, loop=JOINING)
    for tick in ("10", "100"):  # before and after its arrival
        snap = subprocess.run([essaim, "snapshot", str(run), "--tick", tick, "--trail", "100", "-o",
                               str(tmp_path / f"t{tick}.png")], capture_output=True, text=True, timeout=60)
        assert snap.returncode == 0, snap.stderr
    subprocess.run([essaim, "replay", str(run)], check=True, capture_output=True, timeout=60)
    page, errors, _ = open_page(browser, run / "replay.html")
    assert page.evaluate("window.essaimReplay.error || ''") == ""
    assert page.evaluate("essaimReplay.ids") == [f"fb{i}" for i in range(5)] + ["newcomer"]
    assert page.get_attribute("#view", "data-robot-count") == "5"
    assert page.text_content("#info").endswith("5 robots, 5 alive")
    assert page.evaluate("essaimReplay.robot(5).present") is False
    page.evaluate("essaimReplay.setFrame(60)")  # every tick recorded: frame k is tick k
    assert page.get_attribute("#view", "data-robot-count") == "6"
    assert page.text_content("#info").endswith("6 robots, 6 alive")
    pos = page.evaluate("essaimReplay.robotCanvasPosition(5)")
    page.click("#view", position={"x": pos["x"], "y": pos["y"]})
    assert page.text_content("#selected").startswith("newcomer  battery"), page.text_content("#selected")
    page.evaluate("essaimReplay.setFrame(20)")  # selected, but not there yet: said, not drawn
    assert page.text_content("#selected") == "newcomer  not added yet"
    assert page.get_attribute("#view", "data-robot-count") == "5"
    page.evaluate("essaimReplay.setFrame(100)")  # its trail starts where it was added
    assert page.text_content("#selected").startswith("newcomer  battery")
    assert errors == []


def test_replay_of_30_robots_10000_ticks_loads_and_scrubs(essaim, browser, tmp_path):
    bots = "".join(foot_bot(i, -4.5 + 1.5 * (i % 7), -3 + 1.5 * (i // 7), 12 * i) for i in range(30))
    run = make_run(essaim, tmp_path, "big", bots, 10000, arena=(12, 8))
    subprocess.run([essaim, "replay", str(run)], check=True, capture_output=True, timeout=60)
    page, errors, seconds = open_page(browser, run / "replay.html")
    assert page.evaluate("essaimReplay.frameCount") == 10001
    assert page.get_attribute("#view", "data-robot-count") == "30"
    # Scrubbing to the end reads the last frame on demand.
    page.evaluate("essaimReplay.setFrame(10000)")
    assert page.text_content("#tick") == "10000"
    print(f"30 robots x 10000 ticks: {(run / 'recording.bin').stat().st_size} bytes recorded, "
          f"page ready in {seconds:.2f} s (script {page.evaluate('essaimReplay.loadMs'):.0f} ms)")
    # The time is reported above, not bounded (a busy machine is slower, not wrong):
    # open_page's wait is the guard against a page that never gets ready.
    assert errors == []


def test_replay_exports_the_view_as_a_webm_video(essaim, browser, small_run, tmp_path):
    """The video button plays from the tick shown to the end while MediaRecorder records the
    canvas, then downloads a WebM that ffprobe reads: VP8/9, the canvas's size, frames that
    show the arena and the robots."""
    if not shutil.which("ffprobe"):
        pytest.skip("ffprobe missing: scripts/setup.sh installs Debian's ffmpeg")
    subprocess.run([essaim, "replay", str(small_run)], check=True, capture_output=True, timeout=60)
    page, errors, _ = open_page(browser, small_run / "replay.html")
    assert page.evaluate("essaimReplay.canRecordVideo")
    assert page.is_visible("#record")
    page.select_option("#speed", "20")  # 200 ticks at 20 x 10 ticks/s: a one-second video
    with page.expect_download(timeout=30000) as download:
        page.click("#record")
        assert page.evaluate("essaimReplay.recordingVideo()")
    webm = tmp_path / download.value.suggested_filename
    download.value.save_as(webm)
    assert webm.name == "small-replay.webm"
    assert page.text_content("#tick") == "200"  # played to the end, then stopped recording
    assert not page.evaluate("essaimReplay.recordingVideo()")
    assert page.text_content("#record").strip().endswith("video")
    probe = json.loads(subprocess.run(
        ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
         "stream=codec_name,width,height,nb_read_frames", "-of", "json", str(webm)],
        capture_output=True, text=True, check=True, timeout=60).stdout)["streams"][0]
    assert probe["codec_name"] in ("vp8", "vp9")
    size = page.evaluate("[document.getElementById('view').width, document.getElementById('view').height]")
    assert [probe["width"], probe["height"]] == size
    assert int(probe["nb_read_frames"]) >= 5
    # Its last frame: the dark page around a light arena, robots in between (many colours).
    last = tmp_path / "last.png"  # each frame written over the one before: the last stays
    subprocess.run(["ffmpeg", "-v", "error", "-i", str(webm), "-update", "1", str(last)], check=True, timeout=60)
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", str(last), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         capture_output=True, check=True, timeout=60).stdout
    assert len(raw) == size[0] * size[1] * 3
    colours = {raw[i:i + 3] for i in range(0, size[0] * size[1] * 3, 3 * 7)}
    assert len(colours) > 20
    assert errors == []
