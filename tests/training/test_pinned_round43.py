"""Round 43 of the fresh planted bugs: the values its missed bugs changed, pinned.

The expected values are stated independently of the code under test: an answer table
asks the live partner once per key it lacks (counted by set arithmetic on the keys
asked); the Python joint model's exact rate of the policy optimal against a partner is
the oracle's optimum against it (the oracle reaches it by value iteration, the joint
model by a linear solve); canonical layouts are worked by hand from the scenario's deal
and checked against the full enumeration folded through the relabelling.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.headroom import JointModel
from hg_marl.agents.models.answers import AnswerTable, KeyBatch, stationary_human
from hg_marl.agents.models.keyed import unique
from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.agents.models.packing import StatePacker
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.planner.space import Relabel
from hg_marl.core import World
from hg_marl.envs.batched import BatchedRules, BatchState


def test_a_partly_answered_batch_asks_the_live_partner_only_for_the_keys_it_lacks() -> None:
    """A live partner (``lazy``: no array form, not equivariant) asked two keys, then those two
    and the rest of a batch shared with other tables (a :class:`KeyBatch`): the second ensure
    asks only the keys the table lacks, so the live calls are the distinct keys asked in all
    (set arithmetic), and the table holds each key once."""
    world = World("paper2015")
    human = stationary_human("lazy", world)
    packer = StatePacker(world)
    table = AnswerTable(world, human, packer)
    assert table.answers_live and table.canonical is None
    states = [s for s, _ in layout_distribution(world)]
    keys = unique(packer.pack(BatchState.of(states)))
    assert len(keys) >= 4
    rules = BatchedRules(world)
    table.ensure(keys[:2], KeyBatch(packer, rules, keys[:2]))
    assert table.live_calls == 2
    table.ensure(keys, KeyBatch(packer, rules, keys))
    assert table.live_calls == len(keys)  # 2 before, len(keys) - 2 now
    assert len(table.keys) == len(keys)
    assert np.array_equal(table.keys, keys)


@pytest.mark.parametrize(("scenario", "spec"), [("paper2015", "lazy"), ("forced_coordination", "random")])
def test_the_python_joint_models_optimal_policy_rates_at_the_oracles_optimum(scenario: str, spec: str) -> None:
    """The Python joint model of one partner: the policy optimal against it, evaluated against
    it (``JointModel.rate``, the exact linear solve on the policy's chain), is the oracle's
    optimal rate against the same partner (value iteration on the same semi-MDP): two routes
    to one number."""
    world = World(scenario)
    model = JointModel(world, [stationary_human(spec, world)])
    rate = model.rate(model.optimal_policy(0), 0)
    expected = oracle_rate(world, spec, cache=None, symmetry=False).rate_per_hour
    assert expected > 0.0
    assert rate == pytest.approx(expected, rel=1e-6)


_REVERSED = """
name = "paper2015_reversed_deal"
robot_locations = ["bin_side", "table_left", "table_right", "human_side"]
handover_locations = ["human_side"]
robot_start = ["bin_side"]
[[objects]]
name = "tape1"
[[objects]]
name = "tape2"
[[objects]]
name = "tape3"
[[bins]]
name = "trashbin"
robot_reach = ["bin_side"]
human_reach = false
[[spots]]
name = "mat_left"
robot_reach = ["table_left"]
[[spots]]
name = "mat_centre"
robot_reach = ["table_left", "table_right"]
[[spots]]
name = "mat_right"
robot_reach = ["table_right"]
[[spots]]
name = "mat_shared"
robot_reach = ["human_side"]
human_reach = true
[[spots]]
name = "human_mat_1"
human_reach = true
[[spots]]
name = "human_mat_2"
human_reach = true
[[layout]]
count = 1
spots = ["human_mat_1", "human_mat_2"]
[[layout]]
count = 2
spots = ["mat_left", "mat_centre", "mat_right"]
"""


def test_canonical_layouts_sort_each_class_when_a_later_group_deals_lower_spots(tmp_path: Path) -> None:
    """paper2015's table with its two layout groups dealt in the other order (the human's mats,
    spots 4 and 5, first; then two of the robot's mats 0, 1, 2). The three tapes are one class,
    so a canonical table lists their spots in ascending order: by hand, one human mat (1/2
    each) and two of the three robot mats (1/3 each) give the six tables (a, b, h), a < b in
    {0, 1, 2}, h in {4, 5}, each with probability 1/6, the robot at its start (0). The same
    follows from the full enumeration folded through the relabelling."""
    path = tmp_path / "reversed.toml"
    path.write_text(_REVERSED)
    world = World(str(path))
    got = canonical_layouts(world)
    by_hand = {((a, b, h), 0): 1 / 6 for a in range(3) for b in range(a + 1, 3) for h in (4, 5)}
    assert {(s.where, s.robot_at): p for s, p in got} == pytest.approx(by_hand)
    relabel = Relabel(world)
    folded: dict[object, float] = defaultdict(float)
    for state, p in layout_distribution(world):
        folded[relabel.canonical(state)[0]] += p
    assert dict(got) == pytest.approx(dict(folded))
