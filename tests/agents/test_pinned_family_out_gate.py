"""Family-out partners, stated by hand: ``fo_picky`` takes only even objects, and
``fo_bursts`` needs working spells of positive length.

The picky partner's states are built directly on paper2015: the robot at the handover
place holding out object ``o``, the other objects where the first layout puts them, the
human's hands empty. By its rule (objects 0, 2, ... are the ones it considers its own) it
takes object 0 and object 2, and never object 1.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.family_out import Bursts, Picky
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import HumanError


def _offer(world: World, o: int) -> State:
    start = world.initial_state(np.random.default_rng(0))
    where = tuple(world.table.hand[Agent.ROBOT] if k == o else p for k, p in enumerate(start.where))
    at = next(i for i, ok in enumerate(world.table.give_ok) if ok)
    return State(where, at, int(Agent.ROBOT), o)


@pytest.mark.parametrize(("o", "takes"), [(0, True), (1, False), (2, True)])
def test_picky_takes_only_the_even_objects_offered(o: int, takes: bool) -> None:
    world = World("paper2015")
    state = _offer(world, o)
    take = world.table.action_index(Agent.HUMAN, Kind.TAKE, o)
    assert world.table.feasible(state, Agent.HUMAN, take)
    assert (Picky().rule(world, state, -1) == take) is takes


@pytest.mark.parametrize("params", ["work=0", "work=-0.5", "rest=-1"])
def test_bursts_refuses_a_spell_that_is_not_a_positive_work_and_a_non_negative_rest(params: str) -> None:
    with pytest.raises(HumanError, match="work must be > 0 and rest >= 0 seconds"):
        make_human(f"fo_bursts:{params}")


@pytest.mark.parametrize(("work", "rest"), [(0.0, 60.0), (float("nan"), 60.0), (90.0, float("inf")), (-1.0, 0.0)])
def test_bursts_built_in_python_refuses_the_same(work: float, rest: float) -> None:
    """Python callers skip the spec parser's finiteness check: the constructor's own holds."""
    with pytest.raises(ValueError, match="work must be > 0 and rest >= 0 seconds"):
        Bursts(work=work, rest=rest)


def test_bursts_accepts_no_rest_at_all() -> None:
    human = make_human("fo_bursts:work=0.5,rest=0")
    assert (human.work, human.rest) == (0.5, 0.0)
