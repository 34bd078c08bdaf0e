"""Values that round 202's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pandas as pd
import pytest

from hg_marl.agents.planner.models import cooperative
from hg_marl.core import Agent, World
from hg_marl.training.aggregate import br_prox
from tests.agents.test_pinned_planner_models_gate import PICK0, STATE, TAKE0, THROW0, WAIT


def test_blocks_made_one_after_the_other_on_different_actions_both_stay() -> None:
    # paper2015's human actions: pick 0, throw 3, take 9, wait 30 (the gate file's constants). The
    # monitor blocks the take first, then, in another turn, the pick: the model then rules out both
    # (the blocks add up, HATP's blocking facts are never forgotten by a new one), so of the
    # candidates (pick 0, throw 3, take 9, wait 30) the deterministic model allows the throw and the
    # wait only, with probability 1. The second block shares no action with the first, so a model
    # that kept only the newest block would still allow the take.
    world = World("paper2015")
    acts = world.actions(Agent.HUMAN)
    model = cooperative().with_blocked(frozenset({acts[TAKE0]})).with_blocked(frozenset({acts[PICK0]}))
    assert model.blocked == {acts[TAKE0], acts[PICK0]}
    assert model.choices(world, STATE, (PICK0, THROW0, TAKE0, WAIT)) == ((1.0, (THROW0, WAIT)),)


def test_br_prox_puts_partners_outside_the_groups_in_the_all_split() -> None:
    # A held-out study's groups name partner "a" a train partner; partner "b" (a plain ``humans``
    # entry) is in no group. BR-Prox is split by group, and a partner without one goes to "all" (the
    # split of a study without groups). "a" has 0.5, 0.7, 0.9 over seeds 0-2 and "b" 0.2, 0.4, 0.6:
    # three runs each, whose IQM trims int(0.25 * 3) = 0 scores each side, so it is the mean, 0.7
    # and 0.4; with reps 0 no interval.
    frame = pd.DataFrame(
        {
            "robot": ["r"] * 6,
            "human": ["a"] * 3 + ["b"] * 3,
            "scenario": ["paper2015"] * 6,
            "seed": [0, 1, 2] * 2,
            "score": [0.5, 0.7, 0.9, 0.2, 0.4, 0.6],
            "br_prox": [0.5, 0.7, 0.9, 0.2, 0.4, 0.6],
        }
    )
    entries = br_prox(frame, {"a": "train"}, reps=0)
    assert [(e["robot"], e["scenario"], e["split"], e["runs"], e["ci"]) for e in entries] == [
        ("r", "paper2015", "train", 3, None),
        ("r", "paper2015", "all", 3, None),
    ]
    assert [e["iqm"] for e in entries] == pytest.approx([0.7, 0.4])
