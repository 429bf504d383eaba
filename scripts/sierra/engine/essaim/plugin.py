"""essaim as a SIERRA engine (`--engine=engine.essaim`): each experimental run is one
`essaim run` of a generated .argos file, its outputs laid out where SIERRA's stage 3 reads
them. The hooks are those of SIERRA's engine-plugin tutorial; docs/sierra.md has the whole
picture.

Per run, the command line SIERRA hands GNU parallel (or sbatch's job, on SLURM) is
    essaim run RUN.argos --out RUN_output/OUTPUT_LEAF --threads N --quiet [--essaim-arg]...
      && python3 outputs.py RUN_output/OUTPUT_LEAF
so each run's folder holds essaim's summary.json, metrics.json, timeseries.csv and files/
(the loop functions' own files), plus metrics.csv and run.csv (outputs.py), all of them
under the project's `sierra.run.output_leaf` (main.yaml).
"""
from __future__ import annotations

import argparse
import logging
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import typing as tp

import psutil

from sierra.core import batchroot, execenv, types
from sierra.core.experiment import bindings, definition
import sierra.core.variables.batch_criteria as bc

from engine.essaim.generators.engine import LAUNCH_EXT

_logger = logging.getLogger("engine.essaim")
HERE = pathlib.Path(__file__).resolve().parent
CHECKOUT_BUILD = HERE.parents[3] / "build" / "essaim"  # scripts/sierra/engine/essaim


def essaim_executable(cmdopts: types.Cmdopts) -> str:
    """--essaim, else $ESSAIM, else `essaim` on PATH, else this checkout's build/essaim;
    absolute, so that the command file runs the same binary on every node."""
    for candidate in (cmdopts.get("essaim"), os.environ.get("ESSAIM"), shutil.which("essaim"),
                      str(CHECKOUT_BUILD)):
        if candidate and os.access(candidate, os.X_OK) and not os.path.isdir(candidate):
            return str(pathlib.Path(candidate).resolve())
    raise RuntimeError("essaim not found: give --essaim PATH, set ESSAIM, put `essaim` on "
                       f"PATH or build {CHECKOUT_BUILD} (scripts/setup.sh)")


def run_output_dir(launch_stem: pathlib.Path, output_leaf: str) -> pathlib.Path:
    """Where SIERRA looks for a run's outputs: exp-outputs/EXP/STEM_output/LEAF, beside
    the run's input exp-inputs/EXP/STEM (SIERRA's batch layout, batchroot.PathSet)."""
    batch_root = launch_stem.parents[2]
    exp_name = launch_stem.parent.name
    return batch_root / "exp-outputs" / exp_name / f"{launch_stem.name}_output" / output_leaf


def output_leaf(main_config: types.YAMLDict) -> str:
    return str(main_config["sierra"]["run"]["output_leaf"])


class ExpRunShellCmdsGenerator(bindings.IExpRunShellCmdsGenerator):
    def __init__(self, cmdopts: types.Cmdopts, criteria: bc.XVarBatchCriteria, exp_num: int,
                 n_agents: tp.Optional[int]) -> None:
        self.cmdopts = cmdopts
        self.leaf = output_leaf(criteria.main_config)

    def pre_run_cmds(self, host: str, input_fpath: pathlib.Path,
                     run_num: int) -> list[types.ShellCmdSpec]:
        return []

    def exec_run_cmds(self, host: str, input_fpath: pathlib.Path,
                      run_num: int) -> list[types.ShellCmdSpec]:
        out = run_output_dir(pathlib.Path(input_fpath), self.leaf)
        threads = int(self.cmdopts.get("physics_n_engines") or 1)
        run = [essaim_executable(self.cmdopts), "run", f"{input_fpath}{LAUNCH_EXT}",
               "--out", str(out), "--threads", str(threads), "--quiet",
               *self.cmdopts.get("essaim_args", [])]
        convert = [sys.executable, str(HERE / "outputs.py"), str(out)]
        cmd = f"{shlex.join(run)} && {shlex.join(convert)};"
        if self.cmdopts.get("exec_devnull"):
            cmd = f"{{ {shlex.join(run)} && {shlex.join(convert)}; }} > /dev/null 2>&1;"
        return [types.ShellCmdSpec(cmd=cmd, shell=True, wait=True)]

    def post_run_cmds(self, host: str,
                      run_output_root: pathlib.Path) -> list[types.ShellCmdSpec]:
        return []


# The batch's exp-outputs/, from stage 2's pre_exp_diagnostics(), for post_exp_cmds().
_batch_output_root: tp.Optional[pathlib.Path] = None


class ExpShellCmdsGenerator(bindings.IExpShellCmdsGenerator):
    def __init__(self, cmdopts: types.Cmdopts, exp_num: int) -> None:
        self.cmdopts = cmdopts

    def pre_exp_cmds(self) -> list[types.ShellCmdSpec]:
        # GNU parallel passes no variables to what it runs on other hosts: Lua's search
        # paths matter to controllers that `require`; added to what the execution
        # environment asked for (hpc.slurm, hpc.adhoc: LD_LIBRARY_PATH, PYTHONPATH).
        cmd = 'export PARALLEL="${PARALLEL:+$PARALLEL }--env LUA_PATH --env LUA_CPATH"'
        return [types.ShellCmdSpec(cmd=cmd, shell=True, wait=True, env=True)]

    def exec_exp_cmds(self, exec_opts: types.StrDict) -> list[types.ShellCmdSpec]:
        return []

    def post_exp_cmds(self) -> list[types.ShellCmdSpec]:
        """The experiment's runs' CSVs given the same columns (outputs.py --align)."""
        if _batch_output_root is None:
            return []
        cmd = shlex.join([sys.executable, str(HERE / "outputs.py"), "--align",
                          str(_batch_output_root)])
        return [types.ShellCmdSpec(cmd=cmd + ";", shell=True, wait=True)]


class ExpConfigurer(bindings.IExpConfigurer):
    def __init__(self, cmdopts: types.Cmdopts) -> None:
        self.cmdopts = cmdopts

    def for_exp_run(self, exp_input_root: pathlib.Path,
                    run_output_root: pathlib.Path) -> None:
        pass  # `essaim run --out` makes the run's folder

    def for_exp(self, exp_input_root: pathlib.Path) -> None:
        pass

    def parallelism_paradigm(self) -> str:
        return "per-exp"


def execenv_check(cmdopts: types.Cmdopts) -> None:
    """Stage 2: essaim runs here (on SLURM and PBS: in the job, on its first node)."""
    exe = essaim_executable(cmdopts)
    r = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and "essaim" in r.stdout, \
        f"{exe} --version failed: {r.stdout}{r.stderr}"
    _logger.debug("Using %s", r.stdout.strip())


def cmdline_postparse_configure(env: str, args: argparse.Namespace) -> argparse.Namespace:
    """Threads per run and runs at a time per node, from the execution environment, so
    that no core runs two threads: hpc.local from --physics-n-engines (default 1) and the
    machine's cores; hpc.adhoc from the nodefile's cores; hpc.slurm from the job's
    SLURM_CPUS_PER_TASK and SLURM_TASKS_PER_NODE; hpc.pbs from PBS_NUM_PPN or NCPUS and
    --exec-jobs-per-node."""
    if not any(stage in args.pipeline for stage in (1, 2)):
        return args
    configure = {"hpc.local": _local, "hpc.adhoc": _adhoc, "hpc.slurm": _slurm,
                 "hpc.pbs": _pbs}.get(env)
    if configure is None:
        _logger.warning("Execution environment %s untested with essaim", env)
        return args
    configure(args)
    _logger.debug("%s: %s threads per run, %s runs at a time per node", env,
                  args.physics_n_engines, args.exec_jobs_per_node)
    return args


def _local(args: argparse.Namespace) -> None:
    args.physics_n_engines = args.physics_n_engines or 1
    if args.exec_jobs_per_node is None:
        cores = psutil.cpu_count() or 1
        args.exec_jobs_per_node = max(1, min(int(args.n_runs), cores // args.physics_n_engines))


def _adhoc(args: argparse.Namespace) -> None:
    nodes = execenv.parse_nodefile(args.nodefile)
    assert nodes, f"No node in --nodefile {args.nodefile}"
    cores = min(node.n_cores for node in nodes)
    if args.exec_jobs_per_node is None:
        args.exec_jobs_per_node = max(1, min(cores, -(-int(args.n_runs) // len(nodes))))
    args.physics_n_engines = max(1, cores // args.exec_jobs_per_node)


def _slurm(args: argparse.Namespace) -> None:
    if args.exec_jobs_per_node is None:
        found = re.match(r"^\d+", os.environ["SLURM_TASKS_PER_NODE"])
        assert found, f"Unexpected SLURM_TASKS_PER_NODE={os.environ['SLURM_TASKS_PER_NODE']}"
        args.exec_jobs_per_node = int(found.group(0))
    args.physics_n_engines = int(os.environ["SLURM_CPUS_PER_TASK"])


def _pbs(args: argparse.Namespace) -> None:
    if "PBS_NUM_PPN" in os.environ:  # Torque
        cores = int(float(os.environ["PBS_NUM_PPN"]))
    elif "NCPUS" in os.environ:  # OpenPBS, PBS Pro
        cores = int(os.environ["NCPUS"])
    else:
        raise RuntimeError("hpc.pbs: neither PBS_NUM_PPN nor NCPUS is set: not a PBS job?")
    args.exec_jobs_per_node = args.exec_jobs_per_node or cores
    args.physics_n_engines = max(1, cores // args.exec_jobs_per_node)


def population_size_from_pickle(exp_def: definition.ExpDefPickle, main_config: types.YAMLDict,
                                cmdopts: types.Cmdopts) -> int:
    for chg in exp_def.attr_chgs:
        if isinstance(chg, definition.AttrChange) and chg.attr == "quantity" \
                and chg.path.endswith("distribute/entity"):
            return int(chg.value)
    return -1


def population_size_from_def(exp_def: definition.BaseExpDef, main_config: types.YAMLDict,
                             cmdopts: types.Cmdopts) -> int:
    pickled = definition.ExpDefPickle(attr_chgs=exp_def.attr_chgs,
                                      element_adds=exp_def.element_adds)
    found = population_size_from_pickle(pickled, main_config, cmdopts)
    if found > 0:
        return found
    quantity = exp_def.attr_get(".//arena/distribute/entity", "quantity")
    return int(quantity) if quantity is not None else -1


def robot_type_from_def(exp_def: definition.BaseExpDef) -> tp.Optional[str]:
    return "foot-bot" if exp_def.has_element(".//arena/distribute/entity/foot-bot") or \
        exp_def.has_element(".//arena/foot-bot") else None


def arena_dims_from_criteria(criteria: bc.XVarBatchCriteria) -> list:
    from sierra.core import utils
    dims = []
    for exp in criteria.gen_attr_changelist():
        for chg in exp:
            if isinstance(chg, definition.AttrChange) and chg.path == ".//arena" \
                    and chg.attr == "size":
                dims.append(utils.ArenaExtent(utils.Vector3D.from_str(str(chg.value))))
    assert dims, "The batch criteria set no arena size"
    return dims


def pre_exp_diagnostics(cmdopts: types.Cmdopts, pathset: batchroot.PathSet,
                        logger: logging.Logger) -> None:
    global _batch_output_root
    _batch_output_root = pathset.output_root
    logger.info("batch_exp_root='%s', runs/exp=%s, threads/run=%s, runs at a time/node=%s",
                pathset.root, cmdopts["n_runs"], cmdopts["physics_n_engines"],
                cmdopts["exec_jobs_per_node"])


# No expsetup_from_def(): SIERRA would then draw time series against one row per tick, and
# essaim's loop functions sample their timeseries.csv at their own rate
# (`timeseries_every`), so its graphs count rows (samples) instead.
