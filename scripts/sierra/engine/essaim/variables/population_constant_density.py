"""`population_constant_density.<density>.I<inc>.C<k>`: robots per m² held at density/100
while the arena grows by `inc` metres a side, k times, from `--scenario NAME.XxYxZ` (the
syntax of SIERRA's ARGoS engine).

essaim's arenas are centred where the template centres them (arenas/ at the origin), so
for each size this sets, about the template's <arena center>: <arena size>; the four walls
`wall_north`, `wall_south`, `wall_east`, `wall_west` (boxes, as ARGoS projects and
tools/make_foraging_arena.py name them) moved to the new edges and stretched; the first
<distribute><position> (uniform) spread over the arena inside the walls; and the robot count
(<distribute><entity quantity>, at least 1). Obstacles, lights and loop-function zones stay
where the template puts them."""
from __future__ import annotations

import pathlib
import typing as tp
import xml.etree.ElementTree as ET

from sierra.core import types, utils
from sierra.core.experiment import definition
from sierra.core.graphs import bcbridge
from sierra.core.variables import batch_criteria as bc
from sierra.core.vector import Vector3D
from sierra.plugins.engine.argos.variables import constant_density as cd

WALL = 0.1  # m: wall thickness
MARGIN = 0.3  # m between a wall and where robots may start


class PopulationConstantDensity(bc.UnivarBatchCriteria, bcbridge.IGraphable,
                                bc.IQueryableBatchCriteria):
    def __init__(self, cli_arg: str, main_config: types.YAMLDict,
                 batch_input_root: pathlib.Path, density: float,
                 extents: list[utils.ArenaExtent], center: tuple[float, float],
                 scenario_tag: str) -> None:
        bc.UnivarBatchCriteria.__init__(self, cli_arg, main_config, batch_input_root)
        self.scenario_tag = scenario_tag
        self.density = density  # robots per m²
        self.extents = extents
        self.center = center

    def n_agents(self, exp_num: int) -> int:
        return max(1, int(self.extents[exp_num].area() * self.density))

    def computable_exp_scenario_name(self) -> bool:
        return True

    def exp_scenario_name(self, exp_num: int) -> str:
        e = self.extents[exp_num]
        return f"{self.scenario_tag}.{int(e.xsize())}x{int(e.ysize())}x{int(e.zsize())}"

    def arena_dims(self, cmdopts: types.Cmdopts) -> list[utils.ArenaExtent]:
        return self.extents

    def gen_attr_changelist(self) -> list[definition.AttrChangeSet]:
        return [self._changes(i) for i in range(len(self.extents))]

    def _changes(self, i: int) -> definition.AttrChangeSet:
        e, (cx, cy) = self.extents[i], self.center
        x, y, z = e.xsize(), e.ysize(), e.zsize()
        hx, hy = x / 2, y / 2
        chg = definition.AttrChange
        walls = {"wall_north": ((x - WALL, WALL), (cx, cy + hy - WALL / 2)),
                 "wall_south": ((x - WALL, WALL), (cx, cy - hy + WALL / 2)),
                 "wall_east": ((WALL, y - WALL), (cx + hx - WALL / 2, cy)),
                 "wall_west": ((WALL, y - WALL), (cx - hx + WALL / 2, cy))}
        ret = definition.AttrChangeSet(
            chg(".//arena", "size", f"{x:g},{y:g},{z:g}"),
            chg(".//arena/distribute/entity", "quantity", str(self.n_agents(i))),
            chg(".//arena/distribute/position", "min",
                f"{cx - hx + MARGIN:g},{cy - hy + MARGIN:g},0"),
            chg(".//arena/distribute/position", "max",
                f"{cx + hx - MARGIN:g},{cy + hy - MARGIN:g},0"))
        for wall, ((sx, sy), (px, py)) in walls.items():
            ret.add(chg(f".//arena/box[@id='{wall}']", "size", f"{sx:g},{sy:g},0.5"))
            ret.add(chg(f".//arena/box[@id='{wall}']/body", "position", f"{px:g},{py:g},0"))
        return ret

    def graph_info(self, cmdopts: types.Cmdopts,
                   batch_output_root: tp.Optional[pathlib.Path] = None,
                   legend: tp.Optional[list[str]] = None) -> bcbridge.GraphInfo:
        info = bcbridge.GraphInfo(cmdopts, batch_output_root,
                                  legend if legend else self.gen_exp_names())
        sizes = [self.n_agents(i) for i in range(len(self.extents))]
        info.xlabel = "Population Size"
        info.xticks = [float(s) for s in sizes]
        info.xticklabels = [str(s) for s in sizes]
        return info


def template_center(cmdopts: types.Cmdopts) -> tuple[float, float]:
    arena = ET.parse(cmdopts["expdef_template"]).getroot().find(".//arena")
    x, y = (float(v) for v in (arena.get("center") or "0,0,0").split(",")[:2])
    return x, y


def factory(cli_arg: str, main_config: types.YAMLDict, cmdopts: types.Cmdopts,
            batch_input_root: pathlib.Path, **kwargs) -> PopulationConstantDensity:
    attr = cd.parse(cli_arg)
    kw = utils.gen_scenario_spec(cmdopts, **kwargs)
    assert "arena_x" in kw, ("population_constant_density needs the starting arena in "
                             "--scenario NAME.XxYxZ (metres)")
    start, inc = (kw["arena_x"], kw["arena_y"]), attr["arena_size_inc"]
    extents = [utils.ArenaExtent(Vector3D(start[0] + k * inc, start[1] + k * inc,
                                          kw.get("arena_z", 1)))
               for k in range(attr["cardinality"])]
    return PopulationConstantDensity(cli_arg, main_config, batch_input_root,
                                     attr["target_density"] / 100.0, extents,
                                     template_center(cmdopts), kw["scenario_tag"])


__all__ = ["PopulationConstantDensity", "factory"]
