"""Experiment generation for essaim: the changes every run of an experiment shares
(for_all_exp) and those of one run (for_single_exp_run), as SIERRA's engine tutorial asks.

Unlike ARGoS's engine, nothing is removed from the template: essaim keeps the devices, the
loop functions and their `library`, and takes threads from the command line
(`essaim run --threads`), not from <system threads>. What changes in the file:
  - paths to the template's scripts, floor image and libraries, made absolute (the
    generated files live in SIERRA's exp-inputs/, not beside the template);
  - <experiment length ticks_per_second> from --exp-setup (else the template's values,
    recorded for SIERRA's graphs all the same);
  - <distribute><entity quantity> from --n-agents;
  - <experiment random_seed> of each run, from SIERRA's seeds (kept in exp-inputs/ and
    reused with --preserve-seeds, SIERRA's default, so a rerun repeats every run).
"""
from __future__ import annotations

import logging
import pathlib

from sierra.core import types, utils
from sierra.core.experiment import definition
from sierra.core.experiment import spec as expspec
from sierra.core.variables import exp_setup
import sierra.core.plugin as pm

_logger = logging.getLogger(__name__)

LAUNCH_EXT = ".argos"
# Attributes that name a file relative to the .argos file's folder, by element.
PATH_ATTRS = {"params": ("script",), "loop_functions": ("script", "library"),
              "floor": ("path",), "*": ("library",)}


def for_all_exp(spec: expspec.ExperimentSpec, controller: str, cmdopts: types.Cmdopts,
                expdef_template_fpath: pathlib.Path) -> definition.BaseExpDef:
    """The experiment's definition: the template with the batch criteria's changes
    (already in expdef_template_fpath) and those every run shares."""
    writer = definition.WriterConfig([{
        "src_parent": None, "src_tag": ".", "opath_leaf": LAUNCH_EXT,
        "new_children": None, "new_children_parent": None, "rename_to": None}])
    module = pm.pipeline.get_plugin_module(cmdopts["expdef"])
    exp_def = module.ExpDef(input_fpath=expdef_template_fpath, write_config=writer)
    absolute_paths(exp_def, pathlib.Path(cmdopts["expdef_template"]).resolve().parent)
    _n_agents(exp_def, spec, cmdopts)
    _exp_setup(exp_def, spec, cmdopts)
    return exp_def


def for_single_exp_run(exp_def: definition.BaseExpDef, run_num: int,
                       run_output_path: pathlib.Path, launch_stem_path: pathlib.Path,
                       random_seed: int, cmdopts: types.Cmdopts) -> definition.BaseExpDef:
    """One run: its seed. Its output folder is given to `essaim run --out` (plugin.py)."""
    exp_def.attr_change(".//experiment", "random_seed", str(random_seed))
    return exp_def


def absolute_paths(exp_def: definition.BaseExpDef, template_dir: pathlib.Path) -> None:
    """Relative file attributes resolved against the template's folder."""
    for el in exp_def.root.iter():
        for attr in PATH_ATTRS.get(el.tag, ()) + PATH_ATTRS["*"]:
            value = el.attrib.get(attr)
            if not value or pathlib.Path(value).is_absolute():
                continue
            if attr == "library" and not (template_dir / value).exists():
                continue  # a library name for the loader's search path, not a file
            el.attrib[attr] = str((template_dir / value).resolve())


def _n_agents(exp_def: definition.BaseExpDef, spec: expspec.ExperimentSpec,
              cmdopts: types.Cmdopts) -> None:
    if cmdopts.get("n_agents") is None:
        return
    chg = definition.AttrChange(".//arena/distribute/entity", "quantity",
                                str(cmdopts["n_agents"]))
    exp_def.attr_change(chg.path, chg.attr, chg.value)
    definition.AttrChangeSet(chg).pickle(spec.exp_def_fpath)


def _exp_setup(exp_def: definition.BaseExpDef, spec: expspec.ExperimentSpec,
               cmdopts: types.Cmdopts) -> None:
    """<experiment length ticks_per_second>, pickled for SIERRA's graphs (their time axis)."""
    length = exp_def.attr_get(".//experiment", "length") or "0"
    tps = exp_def.attr_get(".//experiment", "ticks_per_second") or "10"
    if cmdopts.get("exp_setup"):
        parsed = exp_setup.parse(cmdopts["exp_setup"], {"n_secs_per_run": int(float(length)),
                                                        "n_ticks_per_sec": int(float(tps))})
        length, tps = parsed["n_secs_per_run"], parsed["n_ticks_per_sec"]
    chgs = definition.AttrChangeSet(
        definition.AttrChange(".//experiment", "length", str(length)),
        definition.AttrChange(".//experiment", "ticks_per_second", str(tps)))
    for chg in chgs:
        if not exp_def.attr_change(chg.path, chg.attr, chg.value, noprint=True):
            exp_def.attr_add(chg.path, chg.attr, chg.value)
    utils.pickle_modifications(None, chgs, spec.exp_def_fpath)


__all__ = ["for_all_exp", "for_single_exp_run", "absolute_paths"]
