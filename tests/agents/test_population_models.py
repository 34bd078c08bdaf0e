"""Every member of the small bundled populations: the model on arrays is the Python enumeration.

The exact references' promise is one builder for every partner; the populations' members
(``preference`` partners with their own weights) are the partners the belief robot and the
headroom build models for. The Python enumeration (``tests/agents/reference_oracle.py``,
one state at a time, written independently of the builder) takes well under a second per
member on these tables; on ``roboergosum`` it takes minutes per member, so
``test_models.py`` checks a sample of three there (in the slow stage).
"""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.oracle import oracle_rate
from hg_marl.core import World
from tests.agents.reference_oracle import reference_oracle
from tests.agents.test_models import array_model, assert_same

MEMBERS = [
    (path, i)
    for path, count in (("populations/paper2015.toml", 20), ("populations/hard_layouts.toml", 9))
    for i in range(count)
]


def test_the_small_populations_have_the_members_listed_here() -> None:
    # 20 and 9 [[members]] tables in the files: a member added or removed changes the cases
    assert [
        len(load_population(path).members()) for path in ("populations/paper2015.toml", "populations/hard_layouts.toml")
    ] == [20, 9]


@pytest.mark.parametrize(("path", "member"), MEMBERS)
def test_every_members_model_on_arrays_is_the_python_enumeration(path: str, member: int) -> None:
    population = load_population(path)
    spec = population.members()[member].spec
    world = World(population.scenario)
    ref = reference_oracle(world, spec)
    assert_same(array_model(world, spec)[0], ref)
    result = oracle_rate(world, spec, cache=None)
    assert result.rate_per_hour == pytest.approx(ref.rate_per_hour, rel=1e-9, abs=1e-9)
    assert (result.n_states, result.n_transitions) == (ref.n_states, ref.n_transitions)
