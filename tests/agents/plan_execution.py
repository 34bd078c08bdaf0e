"""Following a plan and noticing when the human does not (a reference the tests use).

- :func:`next_robot_action`: the robot's next step of a plan from the current state: its
  first step whose links hold (its preconditions hold in the state, so a take finds the
  object offered), else ``wait``.
- :func:`expected_human_action`: the human action the plan expects in the current state.
- :class:`PlanMonitor`: plans at the robot's turns, watches the human's replies and
  replans when the human goes off-plan. As HATP does, a missing human action becomes a
  *blocking fact*: the replanned model rules that action out (e.g. "the human did not
  take tape1"), so the robot does not wait forever for it. Blocking facts are dropped
  when an object reaches a bin (the situation has changed) or the task completes.
"""

from __future__ import annotations

import logging

from hg_marl.agents.planner.models import HumanModel, RestrictedHuman, cooperative
from hg_marl.agents.planner.plan import NO_ACTION, Plan, PlanResult
from hg_marl.agents.planner.planner import Planner
from hg_marl.core import Action, Agent, State, World

logger = logging.getLogger(__name__)


def _cycle_at(plan: Plan, state: State) -> int:
    """Index of the cycle whose robot turn starts in ``state``, or -1."""
    for k, s in enumerate(plan.states[:-1]):
        if s == state and plan.cycles[k][0] != NO_ACTION:
            return k
    return -1


def next_robot_action(world: World, plan: Plan, state: State) -> int:
    """The robot's planned action in ``state`` (a cycle boundary).

    If ``state`` is one the plan passes through, the robot's step there; otherwise its
    first not-yet-done step whose preconditions hold now; ``wait`` if none does (its next
    step needs the human first).
    """
    wait = world.n_actions(Agent.ROBOT) - 1
    k = _cycle_at(plan, state)
    if k >= 0:
        action = plan.cycles[k][0]
        return action if world.mask(state, Agent.ROBOT)[action] else wait
    mask = world.mask(state, Agent.ROBOT)
    for step in plan.streams[Agent.ROBOT]:
        if step.action != wait and mask[step.action]:
            return step.action
    return wait


def expected_human_action(world: World, plan: Plan, state: State) -> int:
    """The human action the plan expects when the human is to move in ``state``, or -1."""
    for k, (ar, ah) in enumerate(plan.cycles):
        mid = plan.states[k] if ar == NO_ACTION else world.step(plan.states[k], Agent.ROBOT, ar).state
        if mid == state:
            return ah
    return -1


class PlanMonitor:
    """Plans for the robot, checks the human's replies and replans on deviation.

    Args:
        planner: the planner to use while the human follows the plan; its human model is
            the base model to which blocking facts are added.

    Usage per cycle: ``result = monitor.robot_turn(state)``, execute
    ``result.robot_action``; after the human acted from ``mid_state``,
    ``monitor.human_acted(mid_state, human_action, next_state)``.
    """

    def __init__(self, planner: Planner) -> None:
        self.base = planner
        self.world = planner.world
        model: HumanModel = planner.human_model
        self._model = model if isinstance(model, RestrictedHuman) else cooperative()
        self._planners: dict[frozenset[Action], Planner] = {frozenset(): planner}
        self.blocked: frozenset[Action] = frozenset()
        """Human actions currently ruled out (blocking facts)."""
        self.result: PlanResult | None = None
        """The plan being followed."""
        self.deviations = 0
        """How many off-plan human actions were noticed (each makes the next turn replan)."""

    @property
    def planner(self) -> Planner:
        """The planner for the current blocking facts."""
        planner = self._planners.get(self.blocked)
        if planner is None:
            model = self._model.with_blocked(self.blocked)
            planner = Planner(self.world, self.base.config, model)
            self._planners[self.blocked] = planner
        return planner

    def robot_turn(self, state: State) -> PlanResult:
        """The plan to follow from ``state``.

        On the plan this is the cached suffix of the current plan (a look-up); after a
        deviation the state is new to the planner, which searches again, now under the
        blocking facts.
        """
        self.result = self.planner.plan(state, Agent.ROBOT)
        return self.result

    def human_acted(self, state: State, action: int, next_state: State) -> bool:
        """Record the human's ``action`` taken in ``state``; True if it was the expected one.

        On deviation, the expected action becomes a blocking fact when the human did
        nothing instead (the plan was waiting for it); either way the next
        :meth:`robot_turn` replans from the new state.
        """
        world = self.world
        if any(
            world.is_in_bin(p) and not world.is_in_bin(q) for p, q in zip(next_state.where, state.where, strict=True)
        ):
            self.blocked = frozenset()  # an object reached a bin: the situation changed
        if world.is_clean(next_state):
            self.blocked = frozenset()
        plan = self.result.plan if self.result is not None else None
        if plan is None:
            return True
        expected = expected_human_action(world, plan, state)
        if expected < 0 or expected == action:
            return True
        self.deviations += 1
        wait = world.n_actions(Agent.HUMAN) - 1
        if action == wait and expected != wait:
            self.blocked = self.blocked | {world.actions(Agent.HUMAN)[expected]}
        logger.debug(
            "human did %s, plan expected %s; blocked: %s",
            world.action_names[1][action],
            world.action_names[1][expected],
            sorted(map(str, self.blocked)),
        )
        return False
