"""A number taken from a file a run wrote, as `essaim test` reads one (docs/testing.md,
"Files the run wrote"): files/PATH[COLUMN].STAT, e.g. files/zone_counts.txt[inside].mean.

The file is a table below the run folder's files/: comma-separated when its first row holds a
comma, else whitespace-separated; COLUMN a name of its header row (a first row that is not all
numbers, a leading '#' dropped) or a position from 1; later lines starting with '#' are
comments; rows whose cell is not a number are passed over. STAT: last, first, mean, sum, min,
max, rows. Used by sweep.py's `file_columns`."""
from __future__ import annotations

import math
import re
from pathlib import Path

STATS = ("last", "first", "mean", "sum", "min", "max", "rows")
FORM = re.compile(r"^files/(?P<path>[^\[\]]+)\[(?P<column>[^\[\]]+)\]\.(?P<stat>\w+)$")


def parse(value: str) -> tuple[str, str, str]:
    """(path below files/, column, stat); ValueError saying what is wrong."""
    m = FORM.match(value)
    if not m or ".." in Path(m["path"]).parts:
        raise ValueError(f"{value!r} is not files/PATH[COLUMN].STAT, e.g. files/zone_counts.txt[count].last")
    if m["stat"] not in STATS:
        raise ValueError(f"{value!r}: after the column comes .{', .'.join(STATS)}")
    return m["path"], m["column"], m["stat"]


def _number(cell: str) -> float | None:
    try:
        v = float(cell)
    except ValueError:
        return None
    return v


def _cells(line: str, commas: bool) -> list[str]:
    return [c.strip() for c in line.split(",")] if commas else line.split()


def column_numbers(text: str, column: str) -> list[float]:
    """The numbers of `column`, in order; ValueError when the column is not there."""
    lines = [line.strip() for line in text.splitlines()]
    lines = [line for line in lines if line]
    if not lines:
        raise ValueError("the file is empty")
    head = lines[0]
    commas = "," in head
    head = head[1:].strip() if head.startswith("#") else head
    first = _cells(head, commas)
    header = not all(_number(c) is not None for c in first)
    if column.isdigit() and int(column) >= 1:
        index = int(column) - 1
    elif header and column in first:
        index = first.index(column)
    else:
        raise ValueError(f"no column {column!r}" + (f" (columns: {', '.join(first)})" if header else ""))
    numbers = []
    for line in lines[1 if header else 0:]:
        if line.startswith("#"):
            continue
        cells = _cells(line, commas)
        v = _number(cells[index]) if index < len(cells) else None
        if v is not None:
            numbers.append(v)
    return numbers


def value(run_dir: Path, spec: str) -> float | None:
    """The number `spec` names in the run folder `run_dir`; None when the file, the column or
    a number in it is missing."""
    path, column, stat = parse(spec)
    try:
        numbers = column_numbers((Path(run_dir) / "files" / path).read_text(errors="replace"), column)
    except (OSError, ValueError):
        return None
    if not numbers:
        return None
    if stat == "rows":
        return float(len(numbers))
    result = {"last": lambda: numbers[-1], "first": lambda: numbers[0], "min": lambda: min(numbers),
              "max": lambda: max(numbers), "sum": lambda: math.fsum(numbers),
              "mean": lambda: math.fsum(numbers) / len(numbers)}[stat]()
    return result
