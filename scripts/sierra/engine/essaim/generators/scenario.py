"""Scenario generators a SIERRA project for essaim can use as they are: its
`generators/scenario.py` is `from engine.essaim.generators.scenario import *`.

`--scenario NAME` runs the template as it is; `--scenario NAME.XxYxZ` also gives SIERRA the
arena's size (in metres) for the constant-density criteria, which set their own.
"""
from __future__ import annotations

import pathlib
import re
import typing as tp

from sierra.core import types
from sierra.core.experiment import definition
from sierra.core.experiment import spec as expspec

from engine.essaim.generators import engine

DIMS = re.compile(r"\.(\d+)x(\d+)(?:x(\d+))?$")


def to_dict(scenario: str) -> dict[str, tp.Any]:
    """`foraging` -> {'scenario_tag': 'foraging'}; `foraging.10x10x1` adds arena_x/y/z."""
    found = DIMS.search(scenario or "")
    ret: dict[str, tp.Any] = {"scenario_tag": (scenario or "").split(".")[0]}
    if found:
        ret.update(arena_x=int(found.group(1)), arena_y=int(found.group(2)),
                   arena_z=int(found.group(3) or 1))
    return ret


def to_generator_name(scenario: str) -> str:
    return "for_all_essaim_exp"


def for_all_essaim_exp(spec: expspec.ExperimentSpec, controller: str, cmdopts: types.Cmdopts,
                       expdef_template_fpath: pathlib.Path, **kwargs) -> definition.BaseExpDef:
    return engine.for_all_exp(spec, controller, cmdopts, expdef_template_fpath)


__all__ = ["to_dict", "to_generator_name", "for_all_essaim_exp"]
