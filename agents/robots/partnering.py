"""The planning robots' side of the partner model: observe the human, pick the planner.

Both planning robots (``planner`` and ``hybrid``) hold one :class:`Partnering`. At each
robot turn it reconstructs what the human just did (the state the human acted in is the
robot's previous state after the robot's own action, which the rules make
deterministic), feeds the :class:`~hg_marl.agents.partner.PartnerMonitor` and, when
``partner_aware``, the :class:`~hg_marl.agents.partner.PartnerPosterior`, and hands back
a planner for the current model of the human (one planner per model, so each keeps its
plan cache).
"""

from __future__ import annotations

import functools
from typing import Any

from hg_marl.agents.partner import PartnerMonitor, PartnerPosterior
from hg_marl.agents.planner.models import RestrictedHuman, cooperative
from hg_marl.core import Agent, State, World
from hg_marl.policy import Decision, Turn

MAX_PLANNERS = 8
"""Planners kept (one per human model met in a run)."""


def planner_in(planners: dict[Any, Any], model: Any, make: Any) -> Any:
    """The planner ``planners`` keeps for ``model``, made with ``make(model)`` when it has none
    (the oldest is dropped beyond :data:`MAX_PLANNERS`)."""
    planner = planners.get(model)
    if planner is None:
        if len(planners) >= MAX_PLANNERS:
            planners.pop(next(iter(planners)))
        planner = planners[model] = make(model)
    return planner


class Partnering:
    """Partner monitor (+ posterior) and the planner for the model they imply.

    Args:
        world: the task.
        planner_config: the planners' ``PlannerConfig`` (None: defaults).
        human_model: the fixed base model (None: cooperative); ignored when ``partner_aware``.
        partner_aware: plan against the posterior's most probable partner type.
    """

    def __init__(self, world: World, planner_config: Any, human_model: Any, partner_aware: bool) -> None:
        from hg_marl.agents.robots.base import make_planner

        self.world = world
        self._make = functools.partial(make_planner, world, planner_config)  # picklable, unlike a lambda
        self.base: Any = human_model if human_model is not None else cooperative()
        self.fixed: Any = self.base
        """The base model it was built with (a fixed-model planner's), kept when ``base`` is replaced."""
        self.monitor = PartnerMonitor()
        self.posterior = PartnerPosterior() if partner_aware else None
        self._planners: dict[Any, Any] = {}
        self.model: Any = None
        self.planner: Any = self._planner_for(self._current_model())
        self._prev: tuple[State, int] | None = None

    def _current_model(self) -> Any:
        base = self.posterior.model() if self.posterior is not None else self.base
        return self.monitor.model(base) if isinstance(base, RestrictedHuman) else base

    def _planner_for(self, model: Any) -> Any:
        self.model = model
        return planner_in(self._planners, model, self._make)

    def observe(self, turn: Turn, last: Decision | None) -> bool:
        """Learn from the human's action since the robot's previous turn.

        Returns:
            Whether the model of the human changed (:attr:`planner` is then a new one).
        """
        human_action = turn.last_actions[1]
        solved = turn.reward > 0
        if last is not None or solved:  # a task solved forgets the blocks, whoever decided the move before it
            expected = last.expected_human_action if last is not None else -1
            self.monitor.observe(self.world, expected, human_action, solved)
        if self.posterior is not None and self._prev is not None and not solved and human_action >= 0:
            state, robot_action = self._prev
            step = self.world.step(state, Agent.ROBOT, robot_action)
            after = self.world.step(step.state, Agent.HUMAN, human_action)
            if after.state == turn.state:  # the reconstruction holds (it always should)
                self.posterior.observe(self.world, step.state, robot_action if step.ok else -1, human_action)
        model = self._current_model()
        if model == self.model:
            return False
        self.planner = self._planner_for(model)
        return True

    def planned(self, success: bool) -> None:
        """Tell the monitor whether the planner found a plan with the current model."""
        if not success:
            self.monitor.planner_failed()
            model = self._current_model()
            if model != self.model:
                self.planner = self._planner_for(model)

    def acted(self, state: State, action: int) -> None:
        """Remember the robot's state and action, to reconstruct the human's next move."""
        self._prev = (state, action)

    @property
    def previous(self) -> tuple[State, int] | None:
        """The robot's state and action at its previous turn (None on a run's first turn)."""
        return self._prev

    @property
    def estimate(self) -> str:
        """The current belief about the partner, for the decision record."""
        if self.posterior is not None:
            return self.posterior.most_probable()
        return f"blocked={len(self.monitor.blocked)}" if self.monitor.blocked else ""
