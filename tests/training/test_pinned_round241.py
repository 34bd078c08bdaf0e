"""Values that round 241's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.equivariant import canonical_answers
from hg_marl.agents.models.layouts import canonical_layout_count, canonical_layouts
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import World
from hg_marl.core.scenario import LayoutGroup
from hg_marl.envs.batched import BatchState
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.heldout_curve import HeldOutCurve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig
from tests.agents.test_models import mid_states

# --- training/baselines/heldout_curve.py ---


def test_each_checkpoint_is_played_for_the_configs_eval_seconds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # heldout_curve.py: each partner's checkpoint is played for ``eval_seconds`` simulated
    # seconds (the protocol of ``greedy_rate``), whatever the number of tables (``eval_envs``).
    # The tables and the scoring are stubbed (no network): the stub records the seconds asked.
    asked: list[float] = []

    def rate(net: object, env: object, seconds: float, seed: int) -> float:
        asked.append(seconds)
        return 360.0

    monkeypatch.setattr(heldout_curve, "make_env", lambda config, n: None)
    monkeypatch.setattr(heldout_curve, "greedy_rate", rate)
    config = RecurrentConfig(
        humans=("cooperative",), scenario="paper2015", out=tmp_path, eval_seconds=900.0, eval_envs=3
    ).check()
    curve = HeldOutCurve(config, ("lazy",), every=100, oracle=False)
    curve(100, None)
    assert asked == [900.0, 900.0]  # one train partner, one held-out partner


# --- agents/models/equivariant.py ---


def test_a_batch_is_answered_from_its_own_keys_not_a_prefetch_that_shares_only_its_seen_actions() -> None:
    # equivariant.py: a prefetched batch's canonical keys are kept for that very batch (the same
    # states and seen arrays). Batch A is prefetched; batch B, other states asked with the same
    # ``seen`` array, must be answered at its own states: each answer is the live human's
    # distribution at that state (a separate instance, with probability > 0), as the partner lists it.
    world = World("paper2015")
    states = mid_states(world, 400)
    half = len(states) // 2
    first, second = states[:half], states[half : 2 * half]
    assert first != second
    seen = np.full(half, -1, dtype=np.int64)
    table = canonical_answers(world, stationary_human("cooperative", world), StatePacker(world))
    assert table is not None
    table.prefetch(BatchState.of(first), seen)
    sizes, actions, probs = table(BatchState.of(second), seen, lambda i, n: None)
    fresh = stationary_human("cooperative", world)
    at = 0
    for i, s in enumerate(second):
        expected = [(h, p) for h, p in fresh.distribution(world, s, -1) if p > 0.0]
        got = list(zip(actions[at : at + sizes[i]].tolist(), probs[at : at + sizes[i]].tolist(), strict=True))
        assert got == expected, s
        at += sizes[i]
    assert at == len(actions)


# --- agents/models/layouts.py ---


def test_the_canonical_layout_count_deals_a_later_group_from_what_the_earlier_left() -> None:
    # Three objects in two bin classes, A = {0, 2} and B = {1}; the first group deals 2 of them
    # on 2 of the spots (0, 1, 2), the second the last one on one of (3, 4). Worked by hand:
    # a first deal {A, A} can be placed 3! / 2! = 3 ways, and leaves one B for 2 spots: 3 x 2 = 6;
    # {A, B} can be placed 3! = 6 ways, and leaves one A for 2 spots: 6 x 2 = 12; 18 in all, one
    # robot start. (Counting the second group from all the objects again, 4 + 4 deals after each
    # first deal, would give 3 x 4 + 6 x 4 = 36.)
    base = World("generated:objects=3,seed=0,bins=2,locations=3").scenario
    world = World(dataclasses.replace(base, layout=(LayoutGroup(2, (0, 1, 2)), LayoutGroup(1, (3, 4)))))
    assert world.bins_of == ((0,), (1,), (0,))
    assert world.scenario.robot_start == (0,)
    assert canonical_layout_count(world) == 18
    assert len(canonical_layouts(world)) == 18
