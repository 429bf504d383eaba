"""Paths shared by the module and optimiser tests (a module of its own: tests/conftest.py
is the `conftest` these tests would otherwise import)."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
FORAGING = str(ROOT / "arenas" / "foraging.argos")
SMALL = {"arena.distribute.entity.quantity": 5}  # a fast variant of the report's arena
