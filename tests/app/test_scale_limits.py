"""The default limits admit what the README's scale table runs: 100 000 foot-bots with their
20 000 obstacles pass `essaim check` with no <system max_entities>; a file that asks for more
than the machine's memory is refused before anything is allocated, and max_entities still
sets an exact count."""
import math
import os
import re

import pytest

from clitest import ROOT, essaim, need_essaim

pytestmark = need_essaim
SANITIZED = os.environ.get("ESSAIM_SANITIZED") == "1"


def scaled(robots):
    """--set values that grow bench/avoidance_1000.argos to `robots` at the same density
    (what `essaim bench scale` does)."""
    s = math.sqrt(robots / 1000)
    side, wall, half = f"{32 * s:g}", f"{16 * s:g}", f"{15 * s:g}"
    o = [f"arena.size={side},{side},1",
         f"arena.wall_north.size={side},0.1,0.5", f"arena.wall_south.size={side},0.1,0.5",
         f"arena.wall_east.size=0.1,{side},0.5", f"arena.wall_west.size=0.1,{side},0.5",
         f"arena.wall_north.body.position=0,{wall},0", f"arena.wall_south.body.position=0,-{wall},0",
         f"arena.wall_east.body.position={wall},0,0", f"arena.wall_west.body.position=-{wall},0,0"]
    for d in range(3):
        at = f"arena.distribute[{d}]."
        o += [f"{at}position.min=-{half},-{half},0", f"{at}position.max={half},{half},0",
              f"{at}entity.quantity={robots if d == 2 else robots // 10}"]
    return [a for v in o for a in ("--set", v)]


@pytest.mark.skipif(SANITIZED, reason="100 000 Lua states under ASan take minutes and many GiB")
def test_100000_robots_pass_check_with_the_default_limits():
    r = essaim("check", ROOT / "bench/avoidance_1000.argos", "--ticks", "1", *scaled(100000), timeout=280)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "over the limit" not in r.stderr and "would need" not in r.stderr


def test_more_than_the_memory_allows_is_refused_and_max_entities_is_exact():
    r = essaim("check", ROOT / "bench/avoidance_1000.argos", "--ticks", "1", *scaled(10 ** 7),
               "--set", "framework.system.max_entity_size=4000")
    assert r.returncode == 2
    assert re.search(r"<entity>: 12000004 entities \(10000000 foot-bots\) would need about 618\.0 GiB, over half "
                     r"of the [0-9.]+ GiB this process may use", r.stderr), r.stderr
    assert '<system max_entities="N"/> allows N entities whatever the machine' in r.stderr
    r = essaim("check", ROOT / "bench/avoidance_1000.argos", "--ticks", "1",
               "--set", "framework.system.max_entities=1000")
    assert r.returncode == 2
    assert "1204 entities are over the limit of 1000 per experiment (<system max_entities>)" in r.stderr, r.stderr
