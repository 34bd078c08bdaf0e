"""Values that round 232's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.meta.vpi import VPICriterion
from hg_marl.agents.models.answers import AnswerTable
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.models.packing import StatePacker
from hg_marl.core import Agent, State, World
from hg_marl.envs.batched import BatchState
from hg_marl.training import evaluate as ev
from hg_marl.training.study import Actor
from tests.training.test_pinned_evaluate_gate import _runs, _study


def test_a_pair_no_robot_solved_has_no_reference_rate_not_zero(monkeypatch: pytest.MonkeyPatch) -> None:
    # No oracle rate for the adversarial human, and the planner (the only non-oracle robot)
    # solves nothing on both seeds: there is no reference, so scores.csv's oracle_rate cell is
    # empty (NaN), not a rate of 0 tasks/h that no robot was measured at.
    planner = Actor("planner", {}, "planner")
    study = _study([planner], [Actor("adversarial", {}, "adversarial")], seeds=(0, 1))
    monkeypatch.setattr(ev, "oracle_rate", lambda store, human, scenario, budget, progress: None)
    plan = ev.cells(study)
    frame = ev.score_table(study, plan, _runs({("planner", "adversarial"): [0.0, 0.0]}, plan), store=None)
    assert set(frame["reference"]) == {"none (no robot solved a task)"}
    assert frame["oracle_rate"].isna().all() and frame["score"].isna().all()


def test_an_ensure_of_other_keys_does_not_take_an_earlier_prefetchs_answers() -> None:
    # Two workers allowed (none start for 4 questions: the prefetch is answered when collected).
    # Prefetch keys A, then ensure as many other keys B: A's prefetch is collected and dropped,
    # B is asked of the live human. The reference is the live human's own distribution of each
    # B state (the probabilities above 0, in its order), asked directly.
    world = World("paper2015")
    human = make_human("random")
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    packer = StatePacker(world)
    states = [s for s, _ in layout_distribution(world)][:12]
    keys = np.unique(packer.pack(BatchState.of(states), np.full(len(states), -1)))
    a, b = keys[:4], keys[-4:]
    table = AnswerTable(world, human, packer, arrays=False, jobs=2)
    table.prefetch(a)
    table.ensure(b)
    assert table.keys.tolist() == b.tolist() and table.live_calls == 4
    back, seen = packer.unpack(b)
    first, count = table.lookup(b)
    for i in range(len(b)):
        s = back.state(i)
        want = [(h, p) for h, p in human.distribution(world, State(s.where, s.robot_at, -1, -1), int(seen[i])) if p > 0]
        at = slice(int(first[i]), int(first[i] + count[i]))
        got = list(zip(table.entries["actions"][at].tolist(), table.entries["probs"][at].tolist(), strict=True))
        assert got == want
    table.close()


def test_the_too_many_states_refusal_names_the_places() -> None:
    # generated:objects=12,spots=15 has 15 spots, 1 bin and the 2 hands: 18 places (2 robot
    # locations), and its keys need more than 2**62 values (see the packing gate).
    with pytest.raises(ValueError, match=r"\(12 objects, 18 places\); use a smaller scenario"):
        StatePacker(World("generated:objects=12,spots=15"))


def test_vpis_planning_time_may_exceed_one_decision() -> None:
    # tau is a cost multiplier in decisions (positive), not a probability: 2.0 is kept, and
    # the threshold after one reward of 1 is tau * rate = 2.0 * 0.02 = 0.04.
    criterion = VPICriterion(tau=2.0)
    assert criterion.tau == 2.0
    criterion.observe(1.0)
    assert criterion.tau * criterion.reward_rate == pytest.approx(0.04)
