"""SIERRA project for essaim's foraging experiment (arenas/foraging.argos): docs/sierra.md."""


def sierra_plugin_type() -> str:
    return "project"
