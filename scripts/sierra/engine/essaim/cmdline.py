"""Command line of the essaim engine: ARGoS's engine options, so that a SIERRA pipeline
written for `--engine=engine.argos` runs with `--engine=engine.essaim` and nothing else
changed, plus essaim's own (`--essaim`, `--essaim-arg`)."""
from __future__ import annotations

import argparse

from sierra.core import types
from sierra.plugins import PluginCmdline

IGNORED = "Accepted for ARGoS pipelines; essaim ignores it"


class EngineCmdline(PluginCmdline):
    def init_stage1(self) -> None:
        self._init_run_options()
        self._init_argos_options()

    def _init_run_options(self) -> None:
        g = self.stage1
        g.add_argument("--exp-setup", default=None,
                       help="Run length and ticks per second, `exp_setup.T<seconds>.K<ticks per "
                            "second>` as for ARGoS (<experiment length ticks_per_second>); "
                            "default: the template's own." + self.stage_usage_doc([1]))
        g.add_argument("--physics-n-engines", type=int, default=None,
                       help="Threads per run (`essaim run --threads`): SIERRA's cores per run. "
                            "Required with hpc.local; hpc.adhoc, hpc.slurm and hpc.pbs derive it "
                            "from the allocation." + self.stage_usage_doc([1]))
        g.add_argument("--n-agents", type=int, default=None,
                       help="Robots in every experiment (<distribute><entity quantity>), over "
                            "the template's." + self.stage_usage_doc([1]))
        g.add_argument("--essaim", default=None,
                       help="The essaim executable: default $ESSAIM, else `essaim` on PATH, "
                            "else this checkout's build/essaim." + self.stage_usage_doc([1]))
        g.add_argument("--essaim-arg", action="append", default=[],
                       help="An extra argument for every `essaim run` (repeat it): "
                            "`--essaim-arg=--strict`, `--essaim-arg=--record=every=10`."
                            + self.stage_usage_doc([1]))

    def _init_argos_options(self) -> None:
        g = self.stage1
        g.add_argument("--physics-engine-type2D", default="dynamics2d", help=IGNORED)
        g.add_argument("--physics-engine-type3D", default="dynamics3d", help=IGNORED)
        g.add_argument("--physics-iter-per-tick", type=int, default=None, help=IGNORED)
        g.add_argument("--physics-spatial-hash2D", action="store_true", help=IGNORED)
        g.add_argument("--camera-config", default="overhead", help=IGNORED)
        # ARGoS's engine removes these devices unless told; essaim keeps the template's.
        for name in ("rab", "leds", "battery"):
            g.add_argument(f"--with-robot-{name}", action="store_true", default=False,
                           help=IGNORED + ": the template's devices are kept")


def build(parents: list[argparse.ArgumentParser], stages: list[int]) -> PluginCmdline:
    return EngineCmdline(parents=parents, stages=stages)


def to_cmdopts(args: argparse.Namespace) -> types.Cmdopts:
    return {
        "exp_setup": args.exp_setup,
        "physics_n_engines": args.physics_n_engines,
        "physics_n_threads": args.physics_n_engines,
        "n_agents": args.n_agents,
        "essaim": args.essaim,
        "essaim_args": list(args.essaim_arg),
        "physics_spatial_hash2D": args.physics_spatial_hash2D,
        "with_robot_rab": True,
        "with_robot_leds": True,
        "with_robot_battery": True,
    }
