"""The planner's human models' answers, pinned for the mutation gate.

Expected values from the models' documented rules, worked by hand on ``paper2015``'s human
actions: picks 0-2, throws 3-5, gives 6-8, takes 9-11 (one per tape), places 12-29, and
``wait`` last (30). A deterministic model answers one choice set with probability 1; a
model idling with probability ``p`` answers ``((p, (wait,)), (1 - p, allowed))``; the
allowed set keeps the candidates whose kind the model performs and which are not blocked,
and is ``(wait,)`` when none is left.
"""

from __future__ import annotations

import pytest

from hg_marl.agents.planner.models import (
    HUMAN_KINDS,
    RestrictedHuman,
    cooperative,
    lazy,
    make_human_model,
    no_handover,
)
from hg_marl.core import Agent, Kind, State, World

WAIT = 30
PICK0, THROW0, GIVE0, TAKE0, PLACE0 = 0, 3, 6, 9, 12
STATE = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)  # the tapes on their spots


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def test_the_human_has_every_kind_but_goto(world: World) -> None:
    """``Kind``'s rule: the human has all kinds but GOTO, ``wait`` included."""
    assert {Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE, Kind.PLACE, Kind.WAIT} == HUMAN_KINDS
    assert {a.kind for a in world.actions(Agent.HUMAN)} == HUMAN_KINDS


@pytest.mark.parametrize("p_idle", [0.0, 0.5, 0.999])
def test_an_idling_probability_in_zero_to_one_is_accepted(p_idle: float) -> None:
    """``[0, 1)``: 0 is a deterministic model, anything below 1 a stochastic one."""
    assert cooperative(p_idle).stochastic is (p_idle > 0)


@pytest.mark.parametrize("p_idle", [-0.1, 1.0, 1.5])
def test_an_idling_probability_outside_zero_to_one_is_refused(p_idle: float) -> None:
    """1 would be a human that never acts, and above 1 no probability at all."""
    with pytest.raises(ValueError, match="p_idle must be in"):
        cooperative(p_idle)


def test_a_deterministic_model_answers_one_set_with_probability_one(world: World) -> None:
    """``p_idle == 0``: ``((1.0, allowed),)``, the cooperative human's allowed set being every candidate."""
    state = STATE
    cands = (PICK0, THROW0, TAKE0, WAIT)
    assert cooperative().choices(world, state, cands) == ((1.0, cands),)
    assert lazy().choices(world, state, cands) == ((1.0, (PICK0, THROW0, WAIT)),)  # lazy never takes


def test_an_idling_model_answers_wait_with_p_and_the_allowed_set_otherwise(world: World) -> None:
    """``p_idle = 0.25``: ``((0.25, (wait,)), (0.75, allowed))``; a no-handover human drops the give."""
    state = STATE
    cands = (PICK0, GIVE0, PLACE0, WAIT)
    assert cooperative(0.25).choices(world, state, cands) == ((0.25, (WAIT,)), (0.75, cands))
    assert no_handover(0.25).choices(world, state, cands) == ((0.25, (WAIT,)), (0.75, (PICK0, PLACE0, WAIT)))


def test_kinds_the_human_does_not_have_are_ignored_and_nothing_allowed_means_wait(world: World) -> None:
    """A model allowing PICK and GOTO (a robot's kind) lets the human pick and wait only; a
    model allowing THROW alone, asked about a pick, can only wait (the last action)."""
    state = STATE
    odd = RestrictedHuman("odd", frozenset({Kind.PICK, Kind.GOTO}))
    assert odd.choices(world, state, (PICK0, THROW0, TAKE0, PLACE0, WAIT)) == ((1.0, (PICK0, WAIT)),)
    throws = RestrictedHuman("throws", frozenset({Kind.THROW}))
    assert throws.choices(world, state, (PICK0,)) == ((1.0, (WAIT,)),)


def test_blocked_actions_add_up_and_are_never_allowed(world: World) -> None:
    """Two blocks made one after the other rule out both ground actions; blocking the take a
    second time (the monitor seeing it refused again) keeps it blocked."""
    acts = world.actions(Agent.HUMAN)
    model = cooperative().with_blocked(frozenset({acts[TAKE0]})).with_blocked(frozenset({acts[PICK0], acts[TAKE0]}))
    assert model.blocked == {acts[TAKE0], acts[PICK0]}
    state = STATE
    assert model.choices(world, state, (PICK0, THROW0, TAKE0, WAIT)) == ((1.0, (THROW0, WAIT)),)


def test_models_are_made_by_name_and_unknown_names_or_parameters_are_refused() -> None:
    """The three registry names, ``p_idle`` passed on; anything else a ValueError naming it."""
    assert make_human_model("lazy", p_idle=0.5) == lazy(0.5)
    assert make_human_model("no_handover").allowed_kinds == HUMAN_KINDS - {Kind.GIVE, Kind.TAKE}
    with pytest.raises(ValueError, match=r"unknown human model 'grumpy' \(known: cooperative, no_handover, lazy\)"):
        make_human_model("grumpy")
    with pytest.raises(ValueError, match="human model 'lazy': "):
        make_human_model("lazy", patience=3.0)
