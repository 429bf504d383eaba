"""essaim's engine plugin for SIERRA (`--engine=engine.essaim`): docs/sierra.md."""


def sierra_plugin_type() -> str:
    return "pipeline"
