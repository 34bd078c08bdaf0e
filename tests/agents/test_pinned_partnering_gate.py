"""What the planning robots' partnering tells its monitor and posterior, pinned for the mutation gate.

Worked by hand on ``paper2015`` (places: spots 0-5, bins 6, robot's hand 7, human's hand 8;
the robot at ``table_left`` (1) reaches ``mat_left`` (0) only, the human reaches its mats
4 and 5). From tapes on (0, 2, 4):

- the robot's ``pick(tape1)`` (action 0) succeeds: tapes on (7, 2, 4); the human's
  ``pick(tape3)`` (action 2) then gives (7, 2, 8);
- the robot's ``pick(tape3)`` (action 2) fails (out of its reach): nothing moves, and the
  posterior is told the robot's action failed (-1).

The posterior sees the state the human acted in (after the robot's action) only when the
robot acted before, no task was just solved (a positive reward), the human did act (its
last action is not -1) and the reconstruction gives the state of the turn. The monitor and
posterior are replaced by spies that record what they are told.
"""

from __future__ import annotations

from typing import Any

import pytest

from hg_marl.agents.partner import PartnerMonitor
from hg_marl.agents.planner.models import cooperative
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Decision, Turn

START = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
ROBOT_PICK_TAPE1, ROBOT_PICK_TAPE3 = 0, 2
HUMAN_PICK_TAPE1, HUMAN_PICK_TAPE3 = 0, 2


class _Posterior:
    """Records each observation; plans against the cooperative human."""

    def __init__(self) -> None:
        self.seen: list[tuple[State, int, int]] = []

    def observe(self, world: World, state: State, robot_action: int, human_action: int) -> None:
        self.seen.append((state, robot_action, human_action))

    def model(self) -> Any:
        return cooperative()

    def most_probable(self) -> str:
        return "lazy"


class _Monitor(PartnerMonitor):
    """A real monitor that also records what it is told."""

    def __init__(self) -> None:
        super().__init__()
        self.told: list[tuple[int, int, bool]] = []

    def observe(self, world: World, expected: int, actual: int, solved: bool) -> None:
        self.told.append((expected, actual, solved))
        super().observe(world, expected, actual, solved)


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


def _aware(world: World) -> tuple[Partnering, _Posterior, _Monitor]:
    partnering = Partnering(world, None, None, partner_aware=True)
    posterior, monitor = _Posterior(), _Monitor()
    partnering.posterior = posterior
    partnering.monitor = monitor
    return partnering, posterior, monitor


def _turn(world: World, where: tuple[int, ...], last: tuple[int, int], reward: float = 0.0) -> Turn:
    state = State(where=where, robot_at=1, offer_by=-1, offer_obj=-1)  # a new object, equal to the rules' one
    return Turn(world=world, state=state, agent=Agent.ROBOT, observation={}, reward=reward, last_actions=last)


def test_the_human_is_seen_in_the_state_after_the_robots_action_with_its_own_last_action(world: World) -> None:
    """Robot picks tape1, human picks tape3: the posterior sees (7, 2, 4), robot 0, human 2."""
    partnering, posterior, _ = _aware(world)
    partnering.acted(START, ROBOT_PICK_TAPE1)
    partnering.observe(_turn(world, (7, 2, 8), (ROBOT_PICK_TAPE1, HUMAN_PICK_TAPE3)), None)
    assert posterior.seen == [(State((7, 2, 4), 1, -1, -1), ROBOT_PICK_TAPE1, HUMAN_PICK_TAPE3)]


def test_the_humans_first_action_index_is_an_action_like_any_other(world: World) -> None:
    """Tapes on (4, 2, 0): the robot picks tape3 from mat_left, the human tape1 (action 0) from its mat."""
    partnering, posterior, _ = _aware(world)
    start = State((4, 2, 0), 1, -1, -1)
    partnering.acted(start, ROBOT_PICK_TAPE3)
    partnering.observe(_turn(world, (8, 2, 7), (ROBOT_PICK_TAPE3, HUMAN_PICK_TAPE1)), None)
    assert posterior.seen == [(State((4, 2, 7), 1, -1, -1), ROBOT_PICK_TAPE3, HUMAN_PICK_TAPE1)]


def test_a_failed_robot_action_is_told_as_minus_one_in_the_unchanged_state(world: World) -> None:
    """The robot cannot reach tape3: the human acted in the start state, the robot's action -1."""
    partnering, posterior, _ = _aware(world)
    partnering.acted(START, ROBOT_PICK_TAPE3)
    partnering.observe(_turn(world, (0, 2, 8), (ROBOT_PICK_TAPE3, HUMAN_PICK_TAPE3)), None)
    assert posterior.seen == [(START, -1, HUMAN_PICK_TAPE3)]


@pytest.mark.parametrize(
    ("where", "why"),
    [((7, 3, 8), "a state after the reconstruction's"), ((7, 1, 8), "a state before the reconstruction's")],
)
def test_a_turn_the_reconstruction_does_not_give_is_not_evidence(
    world: World, where: tuple[int, ...], why: str
) -> None:
    """Tape2 elsewhere than the rules put it: the posterior is told nothing."""
    partnering, posterior, _ = _aware(world)
    partnering.acted(START, ROBOT_PICK_TAPE1)
    partnering.observe(_turn(world, where, (ROBOT_PICK_TAPE1, HUMAN_PICK_TAPE3)), None)
    assert posterior.seen == [], why


def test_no_evidence_before_the_robot_acted_or_before_the_human_did(world: World) -> None:
    """A run's first turn has no previous state; a human who has not acted yet (-1) says nothing."""
    partnering, posterior, _ = _aware(world)
    partnering.observe(_turn(world, (0, 2, 4), (-1, -1)), None)
    partnering.acted(START, ROBOT_PICK_TAPE1)
    partnering.observe(_turn(world, (7, 2, 4), (ROBOT_PICK_TAPE1, -1)), None)
    assert posterior.seen == []


@pytest.mark.parametrize(("reward", "solved"), [(0.5, True), (0.0, False), (-1.0, False)])
def test_a_positive_reward_is_a_solved_task_which_is_no_evidence(world: World, reward: float, solved: bool) -> None:
    """The monitor is told the plan's expected action, the human's, and whether a task was solved;
    after a solved task the table was reset, so the posterior is told nothing."""
    partnering, posterior, monitor = _aware(world)
    partnering.acted(START, ROBOT_PICK_TAPE1)
    last = Decision(expert="planner", action=ROBOT_PICK_TAPE1, expected_human_action=HUMAN_PICK_TAPE1)
    partnering.observe(_turn(world, (7, 2, 8), (ROBOT_PICK_TAPE1, HUMAN_PICK_TAPE3), reward), last)
    assert monitor.told == [(HUMAN_PICK_TAPE1, HUMAN_PICK_TAPE3, solved)]
    assert len(posterior.seen) == (0 if solved else 1)


def test_a_blocked_action_changes_the_model_once_and_an_unchanged_model_keeps_the_planner(world: World) -> None:
    """Blocks in the monitor make a new (blocked) model at the next observation; the one after
    implies the same model again, so nothing changes (no new planner)."""
    partnering = Partnering(world, None, None, partner_aware=False)
    take = next(a for a in world.actions(Agent.HUMAN) if a.kind is Kind.TAKE)
    partnering.monitor.blocked = frozenset({take})
    turn = _turn(world, (0, 2, 4), (-1, -1))
    assert partnering.observe(turn, None) is True
    assert partnering.model.blocked == {take}
    planner = partnering.planner
    assert partnering.observe(turn, None) is False
    assert partnering.planner is planner and partnering.estimate == "blocked=1"


def test_the_previous_turn_is_none_first_then_the_robots_state_and_action(world: World) -> None:
    """``previous`` is a value (not a method): None on a run's first turn, then what :meth:`acted` kept."""
    partnering = Partnering(world, None, None, partner_aware=False)
    assert partnering.previous is None
    partnering.acted(START, ROBOT_PICK_TAPE1)
    assert partnering.previous == (START, ROBOT_PICK_TAPE1)
    assert partnering.estimate == ""  # no posterior, no blocks


def test_a_partner_aware_estimate_is_the_posteriors_most_probable_type(world: World) -> None:
    partnering, _, _ = _aware(world)
    assert partnering.estimate == "lazy"
