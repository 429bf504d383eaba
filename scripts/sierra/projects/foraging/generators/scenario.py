from engine.essaim.generators.scenario import *  # noqa: F401,F403 (the engine's, as they are)
