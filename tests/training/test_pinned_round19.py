"""The values round 19's missed planted bugs changed, pinned after the round.

Round 19 planted 14 bugs in the newest modules (the belief robot and its members, the
model builder and its answers, the headroom, the compiled partners and robot, the
oracle, the progress guard) after a fresh mutation sample of the same modules had been
pinned (``tests/agents/test_pinned_fresh_sample.py``); 8 were caught. Each expected value
below is worked by hand or from the rule the module states:

- a probe's reason states its extra expected seconds under the members with a say,
  their weights normalised (two members at 0.5, one off its model: 14 - 10 = 4 s);
- the members' solved count starts again on another scenario;
- an empty held-out list has no headroom (NaN), where no list means every column;
- a compiled table whose closure is given as instances is not kept on disk (an instance
  has no content key), one whose closure is given as specs is;
- an answer table filled without canonical keys refuses to serve a reduced model;
- a policy that falls into a trap with probability 0.5 completes no task (rate 0), and
  the same chain with the trap leading back completes one every 3 s (1,200 per hour).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.compiled import compile_human
from hg_marl.agents.headroom import headroom
from hg_marl.agents.humans import make_human
from hg_marl.agents.member_models import MemberModels
from hg_marl.agents.models import AnswerTable, StatePacker, build_model
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.builder import Dynamics
from hg_marl.agents.models.chains import policy_rate
from hg_marl.agents.models.layouts import canonical_layouts, layout_distribution
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import Agent, World
from hg_marl.policy import Turn
from tests.population_files import train_members as _members


def test_a_probes_reason_states_its_seconds_under_the_members_with_a_say(tmp_path: Path) -> None:
    world = World("paper2015")
    robot = BeliefRobot(
        population=_members(tmp_path, a="cooperative", b="lazy"), splits="train", unknown=0.0, probe=20.0
    )
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    # member a: action 0 takes 10 s, action 1 14 s; member b has no say (off its model)
    robot.q_values = lambda w, s, m: {0: 10.0, 1: 14.0} if m == 0 else {}
    robot.information = lambda w, s, a, weights: 1.0 if a == 1 else 0.0
    state = world.initial_state(np.random.default_rng(0))
    assert robot.act(Turn(world, state, Agent.ROBOT, {})) == 1
    assert robot.last_decision is not None
    assert str(robot.last_decision.reason) == "probe: 1.00 nats about the partner for 4.0 s"


def test_the_members_solved_count_starts_again_on_another_scenario() -> None:
    members = MemberModels(("no_handover",))
    members.reset(World("paper2015"))
    members.result(0)
    assert members.solved == 1
    members.reset(World("paper2015"))  # the same table: kept
    assert members.solved == 1
    members.reset(World("forced_coordination"))
    assert members.solved == 0


def test_an_empty_held_out_list_has_no_headroom_and_none_means_every_column() -> None:
    columns = [("lazy", "lazy"), ("no_handover", "no_handover")]
    empty = headroom("paper2015", columns, held_out=[])
    assert empty.held_out == () and math.isnan(empty.headroom)
    every = headroom("paper2015", columns)
    assert every.held_out == ("lazy", "no_handover") and not math.isnan(every.headroom)


def test_a_closure_of_instances_is_not_kept_on_disk_and_one_of_specs_is(tmp_path: Path) -> None:
    world = World("paper2015")
    compile_human(world, "cooperative", cache=tmp_path / "instances", closure=[make_human("lazy")])
    assert not any(p.is_file() for p in (tmp_path / "instances").rglob("*"))
    compile_human(world, "cooperative", cache=tmp_path / "specs", closure=["lazy"])
    assert any(p.is_file() for p in (tmp_path / "specs").rglob("*"))


def test_a_table_filled_without_canonical_keys_refuses_to_serve_a_reduced_model() -> None:
    world = World("paper2015")
    live = stationary_human("cooperative", world)
    table = AnswerTable(world, live, StatePacker(world))
    build_model(world, table, layout_distribution(world), canonical=False)
    assert len(table.keys) > 0 and table.relabelled is False
    with pytest.raises(ValueError, match="canonical keys"):
        build_model(world, table, canonical_layouts(world), canonical=True)


def _chain_rate(trap_returns: bool) -> float:
    """States 0 (start), 1 (completes), 2 (trap); 0 goes to 1 or 2 at 0.5 each, 1 s per cycle."""
    one = np.array([1.0])
    chain = Dynamics(np.zeros(1, dtype=np.int64), np.zeros(0, dtype=np.int64), one[:0], one[:0],
                     np.array([0]), one, np.array([0.0]))  # fmt: skip
    t_start = np.array([0, 2, 2, 3])  # state 1 completes: no transition of its own
    nxt = np.array([1, 2, 0 if trap_returns else 2])
    return policy_rate(chain, np.array([False, True, False]), (t_start, nxt, np.array([0.5, 0.5, 1.0]), np.ones(3)))


def test_a_policy_that_may_fall_into_a_trap_completes_nothing() -> None:
    assert _chain_rate(trap_returns=False) == 0.0
    # V0 = 1 + 0.5 * 0 + 0.5 * V2, V2 = 1 + V0: V0 = 3 s, 3,600 / 3 per hour
    assert _chain_rate(trap_returns=True) == pytest.approx(1200.0, rel=1e-12)
