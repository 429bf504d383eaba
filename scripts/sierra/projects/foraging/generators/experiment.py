from engine.essaim.generators.experiment import *  # noqa: F401,F403 (the engine's, as they are)
