"""The values round 77's missed planted bugs changed (``mutation/planted.py``, FRESH77), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents import content
from hg_marl.agents.partner import PartnerMonitor
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.base import LearningRobot
from hg_marl.agents.robots.canonical import CanonicalView
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.training.baselines import compare
from hg_marl.training.baselines.comparison import CompareConfig


def test_a_human_seat_view_maps_the_humans_own_actions_of_a_swapped_pair() -> None:
    # CanonicalView's agent is "the seat whose actions are permuted". paper2015's three tapes are
    # interchangeable; tapes on places (0, 4, 2) sort to (0, 2, 4), the canonical tape c being
    # tape (0, 2, 1)[c]. The human's 31 actions, by hand from its action list: picks 0-2, throws
    # 3-5, gives 6-8, takes 9-11 (one per tape), place(tape o, spot s) = 12 + 6 o + s (six spots),
    # wait 30. So canonical pick(1) stands for pick(2), place(1, s) for place(2, s), and back.
    world = World("paper2015")
    assert world.n_actions(Agent.HUMAN) == 31
    view = CanonicalView(world, Agent.HUMAN)
    state = State(where=(0, 4, 2), robot_at=1, offer_by=-1, offer_obj=-1)
    _, to_original, to_canonical = view.view(state, world.facts(state))
    assert to_original is not None and to_canonical is not None
    perm = (0, 2, 1)  # a swap: its own inverse
    expected = [3 * (a // 3) + perm[a % 3] for a in range(12)]
    expected += [12 + 6 * perm[o] + s for o in range(3) for s in range(6)]
    expected += [30]
    assert [int(i) for i in to_original] == expected
    assert [int(i) for i in to_canonical] == expected


def _swap01(action: int) -> int:
    """A robot action of paper2015 with tapes 0 and 1 exchanged (hand-written reference).

    Robot actions: picks 0-2, throws 3-5, gives 6-8, takes 9-11 (one per tape), goto 12-16 (the
    first three to a tape's place, so they follow the tape), wait 17.
    """
    swap = (1, 0, 2)
    if action < 12:
        return 3 * (action // 3) + swap[action % 3]
    if action < 15:
        return 12 + swap[action - 12]
    return action


def test_the_habit_robot_with_shared_objects_learns_its_step_on_the_canonical_state() -> None:
    # With share_objects the habit "is asked at the canonical facts ... and the executed action is
    # mapped forward before its TD step" (agents/robots/canonical.py). MIRROR has tapes 0 and 1 on
    # each other's places, so its canonical state is STATE (tapes sorted by place) with tapes 0
    # and 1 exchanged. One terminal TD step of reward 1 from Q = 0 moves Q by alpha = 0.6 (the
    # habit's default rate) at STATE's facts for the exchanged action, and nowhere else there.
    world = World("paper2015")
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    mirror = State(where=(2, 0, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    robot = make_robot("habit", share_objects=True, q_config={"features": "tabular"})
    assert isinstance(robot, LearningRobot)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))

    def turn(at: State, reward: float) -> Turn:
        observation = {"observation": world.facts(at), "action_mask": world.mask(at, Agent.ROBOT)}
        return Turn(world, at, Agent.ROBOT, observation, reward=reward)

    action = robot.act(turn(mirror, 0.0))
    robot.end(turn(state, 1.0), terminated=True)
    expected = np.zeros(world.n_actions(Agent.ROBOT))
    expected[_swap01(action)] = 0.6
    np.testing.assert_allclose(robot.habit.q_values(world.facts(state)), expected)


def test_a_met_expectation_ends_the_run_of_misses_so_the_robot_is_not_stalled() -> None:
    # PartnerMonitor: "when the human still does not do what is expected stall_after times in a
    # row, the robot is stalled". With stall_after=2: a miss, a met expectation, a miss is one miss
    # in a row (not stalled); a second miss after it makes two in a row (stalled).
    world = World("paper2015")
    expected, wait = 0, world.n_actions(Agent.HUMAN) - 1  # the human's pick(tape 0); wait is last
    monitor = PartnerMonitor(block_after=5, stall_after=2)
    monitor.observe(world, expected, wait, solved=False)
    monitor.observe(world, expected, expected, solved=False)
    monitor.observe(world, expected, wait, solved=False)
    assert monitor.misses == 1 and not monitor.stalled
    monitor.observe(world, expected, wait, solved=False)
    assert monitor.misses == 2 and monitor.stalled


def test_the_references_are_computed_again_for_other_evaluation_seeds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The module docstring: the baselines' fractions are "on the same humans and evaluation
    # seeds", and a changed setting never reuses an old result. So the references stored for
    # seeds (5, 6) are served again for (5, 6) (the store's control) but not for seeds (7,):
    # those are computed, on (7,). The stand-in rate is the sum of the seeds (a hand-made value).
    calls: list[tuple[int, ...]] = []

    def fake(config: CompareConfig, human: str) -> dict[str, Any]:
        calls.append(tuple(config.eval_seeds))
        return {"oracle": None, "planner": float(sum(config.eval_seeds)), "hybrid": 1.0}

    monkeypatch.setattr(compare, "_reference_rates", fake)
    # the code is the same for both configurations: a fixed code digest spares the walk of the sources
    monkeypatch.setattr(content, "code_digest", lambda roots: "same code")
    base: dict[str, Any] = {"humans": ("lazy",), "duration": 90.0, "out": tmp_path / "cmp"}
    first = CompareConfig(eval_seeds=(5, 6), **base)
    assert compare.reference_rates(first, "lazy")["planner"] == 11.0
    assert compare.reference_rates(first, "lazy")["planner"] == 11.0
    assert calls == [(5, 6)]
    other = CompareConfig(eval_seeds=(7,), **base)
    assert compare.reference_rates(other, "lazy")["planner"] == 7.0
    assert calls == [(5, 6), (7,)]
