"""Function size and complexity in src/ (lizard): no function over 60 lines of code with more
than 3 branches, none over cyclomatic complexity 20. Exit 1 listing the ones over.

    .venv/bin/python tools/check_functions.py [PATH...]      (default: src)
"""
import sys
from pathlib import Path

import lizard

MAX_LINES = 60        # lines of code (lizard's NLOC), counted only past MAX_LINEAR_BRANCHES
MAX_LINEAR_BRANCHES = 3  # a long table or a straight sequence of calls is not hard to read
MAX_COMPLEXITY = 20   # cyclomatic complexity (lizard's CCN)


def too_big(fn) -> bool:
    branches = fn.cyclomatic_complexity - 1
    return fn.cyclomatic_complexity > MAX_COMPLEXITY or (fn.nloc > MAX_LINES and branches > MAX_LINEAR_BRANCHES)


def main(paths):
    root = Path(__file__).resolve().parents[1]
    paths = paths or [str(root / "src")]
    over = []
    for info in lizard.analyze(paths):
        over += [(info.filename, fn) for fn in info.function_list if too_big(fn)]
    for filename, fn in over:
        print(f"{Path(filename).resolve().relative_to(root)}:{fn.start_line}: {fn.name}: "
              f"{fn.nloc} lines, complexity {fn.cyclomatic_complexity}")
    if over:
        print(f"check_functions: {len(over)} function(s) over {MAX_LINES} lines with more than "
              f"{MAX_LINEAR_BRANCHES} branches or over complexity {MAX_COMPLEXITY}", file=sys.stderr)
        return 1
    print("check_functions: every function within the limits")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
