"""Values that round 190's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hg_marl.agents.humans.base import sample
from hg_marl.agents.humans.noisy import NoisyHuman
from hg_marl.agents.oracle import oracle_rate
from hg_marl.core import World
from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def test_the_noisy_humans_answers_are_listed_in_index_order_so_a_seeded_draw_is_fixed() -> None:
    # The softmax over paper2015's first table (temperature 3 s) gives two actions a share.
    # ``sample`` draws the k-th listed answer, so the order of the list is what a seeded run
    # plays: in index order (as every other human lists its answers), the draw of a generator
    # seeded s is the one numpy's choice makes over the answers sorted by index, worked apart
    # here from the scores' own softmax.
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    human = NoisyHuman(temperature=3.0)
    finite = {i: c for i, c in human.scores(world, state).items() if math.isfinite(c)}
    best = min(finite.values())
    weights = {i: math.exp(-(c - best) / 3.0) for i, c in finite.items()}
    actions = sorted(weights)
    probs = np.array([weights[i] for i in actions]) / sum(weights.values())
    dist = human.distribution(world, state)
    assert len(dist) > 1
    assert [i for i, _ in dist] == actions
    for seed in range(20):
        expected = actions[int(np.random.default_rng(seed).choice(len(actions), p=probs))]
        assert sample(dist, np.random.default_rng(seed)) == expected


def test_a_solve_from_a_table_is_never_reduced_by_symmetry() -> None:
    # oracle_rate's promise: a solve from ``roots`` is "not cached, not reduced by symmetry". The
    # cooperative human is equivariant and paper2015's three objects are interchangeable, so a
    # whole solve is reduced (symmetry None reads the human's flag); from one table it is not,
    # whatever ``symmetry`` says, and its policy and values are keyed by the table as dealt.
    world = World("paper2015")
    assert oracle_rate(world, "cooperative", cache=False).reduced
    table = world.initial_state(np.random.default_rng(3))
    for symmetry in (None, True):
        part = oracle_rate(world, "cooperative", cache=False, symmetry=symmetry, roots=(table,))
        assert not part.reduced
        assert table in set(part.values)


@pytest.mark.parametrize("field", ["episode_seconds", "eval_seconds"])
def test_recurrent_ppo_refuses_zero_seconds_of_play(field: str) -> None:
    # "expected a positive number of seconds": 0 s of play is refused (no table could end a
    # cycle), the smallest positive value is accepted.
    with pytest.raises(ConfigError, match=f"--{field.replace('_', '-')}: expected a positive number of seconds"):
        RecurrentConfig(**{field: 0.0}).check()
    assert RecurrentConfig(**{field: 1e-9}).check()
