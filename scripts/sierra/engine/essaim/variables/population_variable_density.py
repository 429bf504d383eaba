"""`population_variable_density.<min>.<max>.C<k>`: robots per m² from min to max in the
arena of `--scenario NAME.XxYxZ`, as SIERRA's ARGoS engine (<distribute><entity quantity>)."""
from sierra.plugins.engine.argos.variables.population_variable_density import (
    PopulationVariableDensity, factory)

__all__ = ["PopulationVariableDensity", "factory"]
