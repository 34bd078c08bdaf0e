"""Values that round 115's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal, planner_distribution
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import State, World
from hg_marl.core.batch import BatchState
from hg_marl.core.relabel import Relabel
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.heldout_curve import HeldOutCurve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig

# --- agents/models/packing.py ---


def test_canonical_on_arrays_names_the_original_objects_of_every_class() -> None:
    # roboergosum's interchangeable classes are objects (0, 1, 2) and (3, 4, 5). Worked by
    # hand for where = (5, 3, 4, 2, 0, 1): the first class sorted by place is object 1 (place
    # 3), 2 (4), 0 (5), so canonical objects 0..2 stand for (1, 2, 0); the second class is
    # object 4 (place 0), 5 (1), 3 (2), so canonical objects 3..5 stand for (4, 5, 3), not for
    # the places within the class (1, 2, 0). The canonical where is (3, 4, 5, 0, 1, 2).
    world = World("roboergosum")
    packer = StatePacker(world)
    b = BatchState.of([State((5, 3, 4, 2, 0, 1), 0, -1, -1)])
    orig = packer.canonical(b)
    assert orig.tolist() == [[1, 2, 0, 4, 5, 3]]
    assert b.state(0).where == (3, 4, 5, 0, 1, 2)
    # and on random states, orig is Relabel.canonical's second value (the per-state reference)
    relabel = Relabel(world)
    rng = np.random.default_rng(115)
    states = [
        State(tuple(int(x) for x in rng.integers(0, world.table.n_places, world.n_objects)), 0, -1, -1)
        for _ in range(50)
    ]
    got = packer.canonical(BatchState.of(states))
    assert [tuple(row) for row in got.tolist()] == [relabel.canonical(s)[1] for s in states]


# --- agents/meta/entropy.py ---


def _normalised_entropy(p: list[float]) -> float:
    """H(p) / log2 |A|, written out (the reference: the criterion's own helper is not called)."""
    return -sum(x * math.log2(x) for x in p) / math.log2(len(p))


def test_by_default_entropies_a_few_ten_thousandths_apart_are_no_tie() -> None:
    # The default tie_tolerance is 1e-9: the planner's distribution over 3 actions is
    # (0.98, 0.01, 0.01), normalised entropy ~0.101858; a habit of (0.9801, 0.00995, 0.00995)
    # has ~0.101440, about 4.2e-4 lower: sharper, so the habit wins every decision (no coin).
    habit_p = [0.9801, 0.00995, 0.00995]
    gap = _normalised_entropy([0.98, 0.01, 0.01]) - _normalised_entropy(habit_p)
    assert 1e-4 < gap < 1e-3
    assert planner_distribution(0, 3).tolist() == pytest.approx([0.98, 0.01, 0.01])
    criterion = EntropyCriterion()
    criterion.reset(np.random.default_rng(3))
    plan = PlanProposal.make(0, 3, 0.0)
    chosen = set()
    for i in range(40):  # a fresh state each time: each filter holds the distribution itself
        view = HabitView(bytes([i]), np.array(habit_p), 0, np.zeros(3), np.ones(3), 0.0, 0.0)
        chosen.add(criterion.choose(view, plan))
    assert chosen == {Expert.HABIT}


# --- training/baselines/heldout_curve.py ---


def test_checkpoints_are_scored_on_tables_seeded_twenty_thousand_past_the_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # heldout_curve.py: evaluation tables are seeded apart from training (the run's seed) and
    # from the final score (seed + 10_000), at EVAL_SEED = 20_000 past the seed: a run of seed 3
    # plays each partner's checkpoint from seed 20_003. The tables and the scoring are stubbed
    # (no network): the stub records the seed it is asked to play from.
    seeds: list[int] = []

    def rate(net: object, env: object, seconds: float, seed: int) -> float:
        seeds.append(seed)
        return 360.0

    monkeypatch.setattr(heldout_curve, "make_env", lambda config, n: None)
    monkeypatch.setattr(heldout_curve, "greedy_rate", rate)
    config = RecurrentConfig(humans=("cooperative",), scenario="paper2015", out=tmp_path, seed=3).check()
    curve = HeldOutCurve(config, ("lazy",), every=100, oracle=False)
    curve(100, None)
    assert seeds == [20_003, 20_003]
