"""Per-run generation a SIERRA project for essaim can use as it is: its
`generators/experiment.py` is `from engine.essaim.generators.experiment import *`."""
from engine.essaim.generators.engine import for_single_exp_run

__all__ = ["for_single_exp_run"]
