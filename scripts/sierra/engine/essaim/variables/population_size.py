"""`population_size.Linear<N>.C<k>` / `population_size.Log<N>`: the number of robots of the
template's first <distribute><entity quantity>, exactly as SIERRA's ARGoS engine sets it
(essaim reads that element as ARGoS does), so the same criterion runs on either engine."""
from sierra.plugins.engine.argos.variables.population_size import PopulationSize, factory

__all__ = ["PopulationSize", "factory"]
