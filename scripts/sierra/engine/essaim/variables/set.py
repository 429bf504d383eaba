"""`set.PATH=V1,V2,...` or `set.PATH=LOW:HIGH:N`: one experiment per value of one XML
attribute, PATH written as for `essaim run --set` (docs/cli.md): dot-separated, each segment
but the last a child's tag or id (`tag[k]`: its k-th child of that tag), the last the
attribute. `set.controllers.foraging.params.EPSILONGREED=0.1,0.3,0.5` gives three
experiments; `LOW:HIGH:N` gives N values evenly spaced from LOW to HIGH.

The path is resolved against the template once, into the ElementTree path SIERRA applies
(`./controllers/lua_controller[1]/params`), so a path that names nothing is an error before
anything is generated."""
from __future__ import annotations

import pathlib
import re
import typing as tp
import xml.etree.ElementTree as ET

from sierra.core import types
from sierra.core.experiment import definition
from sierra.core.graphs import bcbridge
from sierra.core.variables import batch_criteria as bc

SEGMENT = re.compile(r"^([\w.-]+?)(?:\[(\d+)\])?$")


class SetAttribute(bc.UnivarBatchCriteria, bcbridge.IGraphable):
    def __init__(self, cli_arg: str, main_config: types.YAMLDict,
                 batch_input_root: pathlib.Path, xpath: str, attr: str,
                 values: list[str]) -> None:
        bc.UnivarBatchCriteria.__init__(self, cli_arg, main_config, batch_input_root)
        self.xpath, self.attr, self.values = xpath, attr, values

    def gen_attr_changelist(self) -> list[definition.AttrChangeSet]:
        return [definition.AttrChangeSet(definition.AttrChange(self.xpath, self.attr, v))
                for v in self.values]

    def graph_info(self, cmdopts: types.Cmdopts,
                   batch_output_root: tp.Optional[pathlib.Path] = None,
                   legend: tp.Optional[list[str]] = None) -> bcbridge.GraphInfo:
        info = bcbridge.GraphInfo(cmdopts, batch_output_root,
                                  legend if legend else self.gen_exp_names())
        info.xlabel = self.attr
        try:
            info.xticks = [float(v) for v in self.values]
        except ValueError:
            info.xticks = [float(i) for i in range(len(self.values))]
        info.xticklabels = list(self.values)
        return info


def parse_values(text: str) -> list[str]:
    """`0.1,0.3` -> ['0.1', '0.3']; `0:1:5` -> five values from 0 to 1."""
    if text.count(":") == 2:
        low, high, n = text.split(":")
        count = int(n)
        assert count >= 2, f"set: LOW:HIGH:N needs N >= 2, have {text}"
        step = (float(high) - float(low)) / (count - 1)
        return [f"{float(low) + i * step:.10g}" for i in range(count)]
    values = [v for v in text.split(",") if v]
    assert values, f"set: no value in '{text}'"
    return values


def resolve(root: ET.Element, path: str) -> tuple[str, str]:
    """essaim's --set PATH -> (ElementTree path, attribute), checked against the template."""
    *segments, attr = path.split(".")
    assert segments and attr, f"set: '{path}' is not PATH.ATTRIBUTE"
    el, xpath = root, "."
    for seg in segments:
        found = SEGMENT.match(seg)
        assert found, f"set: bad segment '{seg}' in '{path}'"
        el, step = _child(el, found.group(1), found.group(2), path)
        xpath += "/" + step
    return xpath, attr


def _child(el: ET.Element, name: str, index: tp.Optional[str], path: str):
    same_tag = [c for c in el if c.tag == name]
    if index is not None:
        k = int(index)
        assert k < len(same_tag), f"set: no <{name}>[{k}] in '{path}'"
        return same_tag[k], f"{name}[{k + 1}]"
    if same_tag:
        return same_tag[0], f"{name}[1]"
    for c in el:
        if c.get("id") == name:
            return c, f"*[@id='{name}']"
    raise AssertionError(f"set: no element '{name}' in '{path}' (tags: "
                         f"{sorted({c.tag for c in el})}, ids: "
                         f"{sorted(c.get('id') for c in el if c.get('id'))})")


def factory(cli_arg: str, main_config: types.YAMLDict, cmdopts: types.Cmdopts,
            batch_input_root: pathlib.Path, **kwargs) -> SetAttribute:
    spec = cli_arg.split(".", maxsplit=1)[1] if "." in cli_arg else ""
    path, sep, values = spec.partition("=")
    assert sep, f"set: expected set.PATH=VALUES, have '{cli_arg}'"
    root = ET.parse(cmdopts["expdef_template"]).getroot()
    xpath, attr = resolve(root, path)
    el = root.find(xpath)
    assert el is not None and attr in el.attrib, \
        f"set: the template has no attribute '{attr}' at '{path}' (SIERRA changes, never adds)"
    return SetAttribute(cli_arg, main_config, batch_input_root, xpath, attr,
                        parse_values(values))


__all__ = ["SetAttribute", "factory", "resolve", "parse_values"]
