"""--scenario and --controller, the two options every SIERRA project defines. The scenario
names the batch's folder (`NAME`, or `NAME.XxYxZ` to give the constant-density criteria the
starting arena); the controller is one of config/controllers.yaml."""
from __future__ import annotations

import argparse

from sierra.core import types
from sierra.plugins import PluginCmdline


def build(parents: list[argparse.ArgumentParser], stages: list[int]) -> PluginCmdline:
    cmdline = PluginCmdline(parents, stages)
    cmdline.multistage.add_argument(
        "--scenario", default="foraging",
        help="NAME or NAME.XxYxZ (arena in metres)." + cmdline.stage_usage_doc([1, 2, 3, 4]))
    cmdline.multistage.add_argument(
        "--controller", default="foraging.default",
        help="CATEGORY.NAME of config/controllers.yaml: foraging.default (the template as "
             "it is), foraging.greedy, foraging.explorer." + cmdline.stage_usage_doc([1, 2, 3, 4]))
    return cmdline


def to_cmdopts(args: argparse.Namespace) -> types.Cmdopts:
    return {"scenario": args.scenario, "controller": args.controller}
