"""Family-out partners, stated by hand: ``fo_picky`` takes only even objects, and
``fo_bursts`` needs working spells of positive length.

The picky partner's states are built directly on paper2015: the robot at the handover
place holding out object ``o``, the other objects where the first layout puts them, the
human's hands empty. By its rule (objects 0, 2, ... are the ones it considers its own) it
takes object 0 and object 2, and never object 1.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.base import shared_spots, wait_index
from hg_marl.agents.humans.family_out import Bursts, Forgetful, Picky, helpful
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


def test_picky_picks_an_even_object_it_can_bin_from_a_shared_spot() -> None:
    """asymmetric_advantages: the human reaches the bin for every object. Objects 0, 1 and
    3 are in the bin; object 2 (even, so picky's own) lies on a spot both agents reach:
    picky picks it up to throw it. An odd object there it would leave to the robot."""
    world = World("asymmetric_advantages")
    shared = shared_spots(world)
    assert shared and all(world.table.throw_to[Agent.HUMAN][0][o] >= 0 for o in range(world.n_objects))
    in_bin = world.n_spots  # the first bin's place code
    for o, expected_kind in ((2, Kind.PICK), (1, None)):
        where = tuple(shared[0] if k == o else in_bin for k in range(world.n_objects))
        state = State(where, 0, -1, -1)
        index = Picky().rule(world, state, -1)
        if expected_kind is None:
            assert index == wait_index(world)
        else:
            assert index == world.table.action_index(Agent.HUMAN, expected_kind, o)


@pytest.mark.parametrize(
    ("clock", "forgets"), [(100.0, True), (120.0, True), (129.9, True), (130.0, False), (200.0, False)]
)
def test_forgetful_holds_an_object_for_hold_seconds(clock: float, forgets: bool) -> None:
    """hold = 30 s; the human is first seen holding object 0 at 100 s: it does nothing
    until 130 s (100 + 30), then helps again (throws or hands over what it holds)."""
    world = World("asymmetric_advantages")
    start = world.initial_state(np.random.default_rng(0))
    where = tuple(world.table.hand[Agent.HUMAN] if k == 0 else p for k, p in enumerate(start.where))
    state = State(where, start.robot_at, -1, -1)
    human = Forgetful(hold=30.0)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    assert human.choose(SimpleNamespace(clock=100.0, world=world, state=state)) == wait_index(world)
    action = human.choose(SimpleNamespace(clock=clock, world=world, state=state))
    helping = helpful(world, state)
    assert helping != wait_index(world)
    assert action == (wait_index(world) if forgets else helping)


@pytest.mark.parametrize(
    ("warmup", "clock", "watches"), [(120.0, 119.9, True), (120.0, 120.0, False), (0.0, 0.0, False)]
)
def test_slow_start_watches_for_warmup_seconds_and_helps_from_then_on(
    warmup: float, clock: float, watches: bool
) -> None:
    """Watching for the first ``warmup`` seconds: [0, warmup); at clock == warmup it helps
    (with warmup 0 from its very first turn)."""
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    human = make_human("fo_slow_start", warmup=warmup)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    helping = helpful(world, state)
    assert helping != wait_index(world)
    action = human.choose(SimpleNamespace(clock=clock, world=world, state=state))
    assert action == (wait_index(world) if watches else helping)
