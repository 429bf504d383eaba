"""`essaim video` (docs/video.md): a short recorded run drawn into .mp4, .webm and .gif and read
back with Debian's ffprobe and ffmpeg: the frame count is the ticks shown over --every, the
size and duration are the options', a decoded frame matches `essaim snapshot` at its tick,
--follow keeps the robot at the centre, the labels are drawn; a recording larger than the
memory limit streams; every mistake is named with exit 2, a missing ffmpeg names its package.

Needs ffmpeg (scripts/setup.sh installs it); without it only the missing-ffmpeg test runs.
"""
import json
import os
import shutil
import struct
import subprocess
from pathlib import Path

import pytest

HAVE_FFMPEG = shutil.which("ffmpeg") is not None and shutil.which("ffprobe") is not None
needs_ffmpeg = pytest.mark.skipif(not HAVE_FFMPEG, reason="ffmpeg missing: scripts/setup.sh installs Debian's ffmpeg")

# fb0 glows red and drives in a wide circle; fb1 and fb2 are green and stand still.
CONTROLLER = """
function init()
  if robot.id == "fb0" then robot.leds.set_all_colors("red") else robot.leds.set_all_colors("green") end
end
function step()
  if robot.id == "fb0" then robot.wheels.set_velocity(12, 9) end
end
"""

ARGOS = """<?xml version="1.0" ?>
<argos-configuration>
  <framework><system threads="0"/><experiment length="10" ticks_per_second="10" random_seed="3"/></framework>
  <controllers>
    <lua_controller id="c">
      <actuators><differential_steering implementation="default"/><leds implementation="default" medium="leds"/></actuators>
      <sensors/>
      <params script="ctrl.lua"/>
    </lua_controller>
  </controllers>
  <arena size="4,4,1" center="0,0,0.5">
    <box id="wall" size="0.2,1.5,0.2" movable="false"><body position="1.5,0,0" orientation="0,0,0"/></box>
    <foot-bot id="fb0"><body position="-0.5,-0.8,0" orientation="0,0,0"/><controller config="c"/></foot-bot>
    <foot-bot id="fb1"><body position="-1.2,1.2,0" orientation="0,0,0"/><controller config="c"/></foot-bot>
    <foot-bot id="fb2"><body position="1.0,1.4,0" orientation="0,0,0"/><controller config="c"/></foot-bot>
  </arena>
  <physics_engines><dynamics2d id="dyn2d"/></physics_engines>
  <media><led id="leds"/></media>
</argos-configuration>
"""


@pytest.fixture(scope="module")
def run(essaim, tmp_path_factory):
    """100 ticks recorded every tick (and every 5 ticks, for --every's check)."""
    tmp = tmp_path_factory.mktemp("video")
    (tmp / "ctrl.lua").write_text(CONTROLLER)
    (tmp / "v.argos").write_text(ARGOS)
    for name, record in (("run", "--record"), ("run5", "--record=every=5")):
        proc = subprocess.run([essaim, "run", "v.argos", "--out", name, "--quiet", record], cwd=tmp,
                              capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stderr
    return tmp / "run"


def video(essaim, *args, env=None):
    return subprocess.run([essaim, "video", *map(str, args)], capture_output=True, text=True, timeout=120, env=env)


def probe(path: Path) -> dict:
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=codec_name,width,height,nb_read_frames:format=duration", "-of", "json", str(path)],
                         capture_output=True, text=True, check=True, timeout=60).stdout
    data = json.loads(out)
    s = data["streams"][0]
    return {"codec": s["codec_name"], "size": (s["width"], s["height"]), "frames": int(s["nb_read_frames"]),
            "duration": float(data["format"].get("duration", "nan"))}


def decode(path: Path, index: int = 0) -> tuple[int, int, bytes]:
    """Frame `index` of a video (or a PNG) as RGB bytes, with its size."""
    info = probe(path)
    w, h = info["size"]
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-vf", f"select=eq(n\\,{index})", "-frames:v", "1",
                          "-f", "rawvideo", "-pix_fmt", "rgb24", "-"], capture_output=True, check=True,
                         timeout=60).stdout
    assert len(raw) == w * h * 3
    return w, h, raw


def frames_rgb(path: Path) -> tuple[int, int, list[bytes]]:
    info = probe(path)
    w, h = info["size"]
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         capture_output=True, check=True, timeout=60).stdout
    n = w * h * 3
    return w, h, [raw[i:i + n] for i in range(0, len(raw), n)]


def red_pixels(w: int, rgb: bytes, box=None) -> list[tuple[int, int]]:
    """(x, y) of the pixels that are fb0's red (y down, as in the image)."""
    x0, y0, x1, y1 = box or (0, 0, w, len(rgb) // (3 * w))
    return [(x, y) for y in range(y0, y1) for x in range(x0, x1)
            if rgb[3 * (y * w + x)] > 170 and rgb[3 * (y * w + x) + 1] < 90 and rgb[3 * (y * w + x) + 2] < 90]


@needs_ffmpeg
@pytest.mark.parametrize("ext, codec", [("mp4", "h264"), ("webm", "vp9"), ("gif", "gif")])
def test_each_format_has_the_frames_size_and_duration_asked(essaim, run, tmp_path, ext, codec):
    out = tmp_path / f"v.{ext}"
    proc = video(essaim, run, "-o", out, "--every", 10, "--fps", 10, "--size", 200)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == str(out)
    assert "11 frames, 200x200" in proc.stderr
    info = probe(out)
    assert info["codec"] == codec
    assert info["size"] == (200, 200)
    assert info["frames"] == 11  # ticks 0, 10, ..., 100
    assert info["duration"] == pytest.approx(1.1, abs=0.11)
    assert not list(tmp_path.glob("*.tmp.*")), "temporary file left behind"


@needs_ffmpeg
def test_from_to_every_and_default_output(essaim, run, tmp_path):
    proc = video(essaim, run, "--from", 20, "--to", 75, "--every", 5, "--size", 64, "--fps", 30)
    assert proc.returncode == 0, proc.stderr
    out = run / "video.mp4"
    assert proc.stdout.strip() == str(out)
    info = probe(out)
    assert info["frames"] == 12  # 20, 25, ..., 75
    assert info["size"] == (64, 64)
    assert info["duration"] == pytest.approx(12 / 30, abs=0.05)
    out.unlink()
    # A recording made every 5 ticks: its frames by default, and multiples of 5 only.
    five = run.parent / "run5"
    proc = video(essaim, five, "-o", tmp_path / "five.mp4", "--size", 64)
    assert proc.returncode == 0, proc.stderr
    assert probe(tmp_path / "five.mp4")["frames"] == 21
    bad = video(essaim, five, "-o", tmp_path / "x.mp4", "--every", 3)
    assert bad.returncode == 2
    assert "--every 3" in bad.stderr and "multiple of 5" in bad.stderr


@needs_ffmpeg
def test_a_frame_matches_the_snapshot_at_its_tick(essaim, run, tmp_path):
    proc = video(essaim, run, "-o", tmp_path / "v.mp4", "--every", 10, "--size", 240, "--trail", 30, "--no-labels")
    assert proc.returncode == 0, proc.stderr
    w, h, frame = decode(tmp_path / "v.mp4", 6)  # tick 60
    snaps = {}
    for tick in (60, 90):
        png = tmp_path / f"s{tick}.png"
        s = subprocess.run([essaim, "snapshot", str(run), "--tick", str(tick), "--size", "240", "--trail", "30",
                            "--no-labels", "-o", str(png)], capture_output=True, text=True, timeout=60)
        assert s.returncode == 0, s.stderr
        snaps[tick] = decode(png)[2]

    def differing(a, b):  # pixels off by more than H.264's rounding of edges and colours
        return sum(1 for i in range(0, len(a), 3) if max(abs(a[i + c] - b[i + c]) for c in range(3)) > 64)

    same, other = differing(frame, snaps[60]), differing(frame, snaps[90])
    print(same, other)
    assert same < 0.002 * w * h, f"frame 6 differs from the snapshot of tick 60 in {same} pixels"
    assert other > 5 * max(same, 20), (same, other)
    assert len(red_pixels(w, frame)) > 50  # fb0 is drawn


@needs_ffmpeg
def test_follow_keeps_the_robot_at_the_centre(essaim, run, tmp_path):
    proc = video(essaim, run, "-o", tmp_path / "f.mp4", "--from", 20, "--every", 20, "--size", 200, "--follow", "fb0",
                 "--no-labels")  # from tick 20: the LEDs set in init() light at the first step
    assert proc.returncode == 0, proc.stderr
    w, h, frames = frames_rgb(tmp_path / "f.mp4")
    assert len(frames) == 5
    # 3 m across 200 px: the robot's radius (0.085 m) is about 5.7 px.
    for k, rgb in enumerate(frames):
        red = red_pixels(w, rgb)
        assert len(red) > 40, f"frame {k}: fb0 not drawn"
        cx, cy = sum(x for x, _ in red) / len(red), sum(y for _, y in red) / len(red)
        assert abs(cx - w / 2) < 2 and abs(cy - h / 2) < 2, f"frame {k}: fb0 at {cx:.1f}, {cy:.1f}"
    # Without --follow the same robot moves across the image.
    proc = video(essaim, run, "-o", tmp_path / "a.mp4", "--from", 20, "--every", 20, "--size", 200, "--no-labels")
    assert proc.returncode == 0, proc.stderr
    w, h, frames = frames_rgb(tmp_path / "a.mp4")
    centres = []
    for rgb in (frames[0], frames[-1]):
        red = red_pixels(w, rgb)
        centres.append((sum(x for x, _ in red) / len(red), sum(y for _, y in red) / len(red)))
    assert abs(centres[0][0] - centres[1][0]) + abs(centres[0][1] - centres[1][1]) > 10, centres
    # --view sets the width of the followed view: 1.5 m doubles the robot's size.
    proc = video(essaim, run, "-o", tmp_path / "z.mp4", "--from", 50, "--every", 50, "--size", 200, "--follow", "fb0",
                 "--view", 1.5, "--no-labels")
    assert proc.returncode == 0, proc.stderr
    w, h, frames = frames_rgb(tmp_path / "z.mp4")
    assert len(red_pixels(w, frames[0])) > 3 * 40


def dark_pixels(w: int, rgb: bytes, box) -> int:
    x0, y0, x1, y1 = box
    return sum(1 for y in range(y0, y1) for x in range(x0, x1) if max(rgb[3 * (y * w + x):3 * (y * w + x) + 3]) < 60)


@needs_ffmpeg
def test_tick_and_scale_bar_are_drawn_in_the_corners(essaim, run, tmp_path):
    for name, extra in (("labels", []), ("plain", ["--no-labels"])):
        proc = video(essaim, run, "-o", tmp_path / f"{name}.mp4", "--every", 50, "--size", 400, *extra)
        assert proc.returncode == 0, proc.stderr
    w, h, labelled = decode(tmp_path / "labels.mp4", 1)
    _, _, plain = decode(tmp_path / "plain.mp4", 1)
    top_left, bottom_left = (0, 0, 130, 25), (0, h - 25, 130, h)
    assert dark_pixels(w, labelled, top_left) > 30 and dark_pixels(w, plain, top_left) == 0
    assert dark_pixels(w, labelled, bottom_left) > 30 and dark_pixels(w, plain, bottom_left) == 0


@pytest.mark.parametrize("args, words", [
    (["-o", "x.avi"], ["-o x.avi", ".mp4, .webm or .gif"]),
    (["--fps", "0"], ["--fps", "1 to 240"]),
    (["--size", "8"], ["--size", "16 to 8192"]),
    (["--every", "0"], ["--every"]),
    (["--from", "500"], ["--from 500", "ticks 0 to 100"]),
    (["--from", "50", "--to", "20"], ["--to 20", "before --from 50"]),
    (["--from", "41", "--to", "49", "--every", "10"], ["no tick from 41 to 49"]),
    (["--follow", "fb9"], ["--follow", "no robot 'fb9'", "did you mean 'fb0'"]),
    (["--view", "-1"], ["--view", "width in metres"]),
    (["--tikc", "3"], ["--tikc"]),
])
def test_mistakes_are_named_with_exit_2(essaim, run, tmp_path, args, words):
    args = [a if a != "x.avi" else str(tmp_path / "x.avi") for a in args]
    words = [w.replace("-o x.avi", f"-o {tmp_path / 'x.avi'}") for w in words]
    proc = video(essaim, run, *args)
    assert proc.returncode == 2, proc.stderr
    for w in words:
        assert w in proc.stderr, proc.stderr
    assert not (run / "video.mp4").exists()


def test_no_recording_and_missing_ffmpeg(essaim, run, tmp_path):
    (tmp_path / "empty").mkdir()
    proc = video(essaim, tmp_path / "empty")
    assert proc.returncode == 2 and "--record" in proc.stderr
    # A PATH without ffmpeg: the message names Debian's package; nothing is written.
    env = dict(os.environ, PATH=str(tmp_path / "empty"))
    proc = video(essaim, run, "-o", tmp_path / "v.mp4", env=env)
    assert proc.returncode == 2, proc.stderr
    assert "ffmpeg" in proc.stderr and "apt-get install ffmpeg" in proc.stderr
    assert not list(tmp_path.glob("v.mp4*"))


@needs_ffmpeg
def test_a_recording_larger_than_the_memory_limit_streams(essaim, run, tmp_path):
    """A 16 GB recording (sparse: its first frames a hole of tick-0 frames, then the run's
    101 frames) under the tests' 4 GB address-space cap (conftest.py): the video reads it
    frame by frame, where reading it whole could not even be tried."""
    rec = (run / "recording.bin").read_bytes()
    header, frame = struct.unpack_from("<II", rec, 12)
    frames = rec[header:]
    hole = (16 << 30) // frame
    big = tmp_path / "big.bin"
    with open(big, "wb") as f:
        f.write(rec[:header])
        f.seek(header + hole * frame)
        f.write(frames)
    assert big.stat().st_size > 16 << 30
    proc = video(essaim, big, "-o", tmp_path / "big.mp4", "--from", 0, "--every", 10, "--size", 64, "--trail", 20)
    assert proc.returncode == 0, proc.stderr
    assert probe(tmp_path / "big.mp4")["frames"] == 11


@needs_ffmpeg
def test_output_through_a_symlink_never_over_a_folder(essaim, run, tmp_path):
    real = tmp_path / "real.mp4"
    real.write_bytes(b"an older video")
    link = tmp_path / "link.mp4"
    link.symlink_to(real)
    proc = video(essaim, run, "-o", link, "--every", 50, "--size", 64)
    assert proc.returncode == 0, proc.stderr
    assert link.is_symlink() and probe(real)["frames"] == 3  # ticks 0, 50, 100
    (tmp_path / "folder.mp4").mkdir()
    proc = video(essaim, run, "-o", tmp_path / "folder.mp4")
    assert proc.returncode == 2 and "not a regular file" in proc.stderr, proc.stderr


@needs_ffmpeg
def test_a_robot_id_that_is_not_utf8_is_drawn_with_a_stand_in(essaim, run, tmp_path):
    """Ids are bytes in the file: a damaged one is drawn with '?' where Cairo would refuse it."""
    rec = bytearray((run / "recording.bin").read_bytes())
    at = rec.index(b"fb1", 104)
    rec[at + 1] = 0xFF
    (tmp_path / "recording.bin").write_bytes(rec)
    proc = video(essaim, tmp_path, "-o", tmp_path / "ids.mp4", "--every", 50, "--size", 128, "--ids")
    assert proc.returncode == 0, proc.stderr
    assert probe(tmp_path / "ids.mp4")["frames"] == 3
