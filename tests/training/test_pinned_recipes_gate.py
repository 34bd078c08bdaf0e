"""Each recipe builds its partner from the recipe's name however the name was made.

The names are built at run time (as a command line or a file gives them), not written
as literals, so the choice depends on the text, not on which string object it is.
Expected partners from the module's definitions: ``fcp`` mixes random actions at the
three checkpoint levels 0, 0.3 and 0.6, ``e3t`` at 0.3, ``coverage`` moves the tables
after each reset, ``members`` is the compiled members themselves.

A mixture partner's answers for a seeded generator are worked by hand from the same
stream: at reset each table draws its level (one integer per table), at each turn one
uniform per table, and a table whose uniform is below its level answers with a uniformly
random feasible action (the largest of one uniform key per action, among the actions the
world's own rules allow), the others with the member's answer.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import Agent, State, World
from hg_marl.core.batch import BatchState
from hg_marl.training.baselines.recipes import CoveragePartner, NoisyPartner, recipe_partner


def _name(text: str) -> str:
    return "".join(list(text))  # a new string object with the same text


@pytest.mark.parametrize(
    ("recipe", "kind", "levels"),
    [("fcp", NoisyPartner, [0.0, 0.3, 0.6]), ("e3t", NoisyPartner, [0.3]), ("coverage", CoveragePartner, None)],
)
def test_a_recipe_named_at_run_time_builds_its_partner(recipe: str, kind: type, levels: list[float] | None) -> None:
    world = World("paper2015")
    partner = recipe_partner(world, ("cooperative", "lazy"), _name(recipe), cache=None)
    assert type(partner) is kind
    if levels is not None:
        assert np.asarray(partner.levels).tolist() == levels
    members = recipe_partner(world, ("cooperative", "lazy"), _name("members"), cache=None)
    assert not isinstance(members, NoisyPartner | CoveragePartner)


def test_the_eps_table_grows_to_the_highest_row_reset() -> None:
    world = World("paper2015")
    partner = recipe_partner(world, ("cooperative",), "fcp", cache=None)
    rng = np.random.default_rng(0)
    partner.reset_rows(np.array([], dtype=np.int64), rng)
    assert len(partner.eps) == 0
    partner.reset_rows(np.array([4, 1]), rng)
    assert len(partner.eps) == 5
    assert set(partner.eps[[1, 4]].tolist()) <= {0.0, 0.3, 0.6}
    partner.reset_rows(np.array([6]), rng)  # grown again: by two rows, to the highest row reset
    assert len(partner.eps) == 7
    partner.reset_rows(np.array([3]), rng)  # a row it has: no growth
    assert len(partner.eps) == 7


def test_every_training_member_is_in_the_partner_and_one_is_itself() -> None:
    world = World("paper2015")
    both = recipe_partner(world, ("cooperative", "lazy"), "members", cache=None)
    assert [m.name for m in both.members] == ["cooperative", "lazy"]
    one = recipe_partner(world, ("lazy",), "members", cache=None)
    assert one.name == "lazy" and not hasattr(one, "members")


class _Bare:
    """An inner partner without a fallback count."""

    name = "bare"


def test_a_partner_without_fallbacks_counts_none() -> None:
    world = World("paper2015")
    assert NoisyPartner(world, _Bare(), (0.3,)).fallbacks == 0
    assert CoveragePartner(world, _Bare()).fallbacks == 0


class _Constant:
    """A member that always answers ``action`` and draws nothing."""

    name = "constant"

    def __init__(self, action: int) -> None:
        self.action = action

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.full(len(batch), self.action, dtype=np.int64)


LEVELS = (0.0, 0.3, 0.6, 1.0)
"""The ``fcp_init`` checkpoint levels as the module docstring gives them."""


def _by_hand(world: World, states: list[State], eps: np.ndarray, answer: int, rng: np.random.Generator) -> list[int]:
    """One turn of the mixture drawn from ``rng`` by hand (module docstring of this file)."""
    noisy = rng.random(len(states)) < eps
    keys = rng.random((int(noisy.sum()), world.n_actions(Agent.HUMAN)))
    out, j = [], 0
    for state, hit in zip(states, noisy, strict=True):
        if hit:
            out.append(max(world.feasible_indices(state, Agent.HUMAN), key=lambda a: keys[j, a]))
            j += 1
        else:
            out.append(answer)
    return out


def test_a_mixture_partner_answers_as_its_generator_stream_drawn_by_hand() -> None:
    world = World("paper2015")
    states = [world.initial_state(np.random.default_rng(s)) for s in range(12)]
    batch = BatchState.of(states)
    wait = world.n_actions(Agent.HUMAN) - 1
    partner = NoisyPartner(world, _Constant(wait), LEVELS)
    partner.reset_rows(np.arange(12), np.random.default_rng(5))
    eps = np.array(LEVELS)[np.random.default_rng(5).integers(4, size=12)]
    assert partner.eps.tolist() == eps.tolist()
    assert {0.0, 1.0} <= set(eps.tolist())  # a member as it is and a random policy both drawn
    rng, hand = np.random.default_rng(11), np.random.default_rng(11)
    randoms = 0
    for _ in range(4):
        expected = _by_hand(world, states, eps, wait, hand)
        got = partner.act(batch, np.zeros(12, dtype=bool), rng).tolist()
        assert got == expected
        assert [got[i] for i in np.flatnonzero(eps == 0.0)] == [wait] * int((eps == 0.0).sum())
        randoms += sum(a != wait for a in got)
    assert randoms > 0  # some tables answered with a random move, not the member's wait
