"""What every robot agent shares: the ``Actor`` bookkeeping, the habit's online learning,
and the conversion of a planner result into a MetaController proposal.

Online learning (habit and hybrid robots). The robot learns inside :meth:`Robot.act`:
``turn.reward`` is the reward received since its previous turn and
``turn.observation["observation"]`` the facts now, so together with the previous turn's
``(facts, action)`` they form the executed transition, and the Q-learner takes one TD
step on it, whoever proposed the action. The first turn of a run has no previous
transition. In episodic mode the last transition ends in a terminal state that the robot
never acts in: call :meth:`Robot.end` with the final turn (``terminated=True``: no
bootstrap; ``False`` on truncation: bootstrap from the last state). In continuing mode
(the paper's) the table is re-drawn and the next ``act`` bootstraps across it, so ``end``
is needed only at the end of the run, if at all.
"""

from __future__ import annotations

import time
from abc import ABC, abstractmethod
from dataclasses import replace
from typing import Any, ClassVar

import numpy as np

from hg_marl.agents.habit import QLearner, QLearnerConfig, sample, softmax
from hg_marl.agents.meta.base import PlanProposal, planner_distribution
from hg_marl.agents.meta.cost import CostModel
from hg_marl.core import WAIT, Agent, World
from hg_marl.core.errors import RobotError, check_bool
from hg_marl.policy import Decision, Turn


class Robot(ABC):
    """Base of the robot agents (implements :class:`hg_marl.policy.Actor`).

    Args:
        cost: how decision time is charged (deterministic model by default).
    """

    name: ClassVar[str]
    """Registry name."""

    def __init__(self, cost: CostModel | None = None) -> None:
        self.cost = cost or CostModel()
        self.last_decision: Decision | None = None
        """Record of the last decision (None before the first)."""
        self.rng = np.random.default_rng(0)
        self.world: World | None = None
        self.agent = Agent.ROBOT
        self.n_actions = 0

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Start a run on ``world`` in seat ``agent``; ``rng`` is now this robot's."""
        self.world, self.agent, self.rng = world, agent, rng
        self.n_actions = world.n_actions(agent)
        self.last_decision = None
        self._reset(world)

    def _reset(self, world: World) -> None:  # noqa: B027 (optional hook)
        """Hook: per-run set-up."""

    @abstractmethod
    def act(self, turn: Turn) -> int:
        """Return the action to execute and set :attr:`last_decision`."""

    def end(self, turn: Turn, terminated: bool = True) -> None:  # noqa: B027 (optional hook)
        """The run or episode is over; learners take their last TD step (see module docstring)."""

    def _record_none(self) -> None:
        """No decision of this robot's own this turn (another expert decided)."""
        self.last_decision = None

    def _record(self, expert: str, action: int, **fields: Any) -> None:
        """Keep this decision's :class:`~hg_marl.policy.Decision` (unnamed fields keep their defaults)."""
        self.last_decision = Decision(expert=expert, action=int(action), **fields)


class LearningRobot(Robot):
    """A robot with a habitual expert that learns online from every executed transition.

    Args:
        q_config: the Q-learner's hyper-parameters (used when ``learner`` is None): a
            :class:`QLearnerConfig`, or a plain dict of the fields that differ from
            :attr:`default_habit`, e.g. ``{"features": "facts"}`` (so sweeps and the CLI
            can pass it as JSON).
        learner: an existing Q-learner to use and keep across resets (to continue
            training or evaluate a saved habit). When None, each :meth:`reset` starts a
            fresh, zero-weight learner, as each of the paper's runs does.
        learn: whether to take TD steps (False: a frozen habit, for evaluation).
        cost: decision cost model.
        share_objects: learn on the state with interchangeable objects in canonical order
            (:mod:`hg_marl.agents.robots.canonical`), so what is learnt about one tape
            holds for its interchangeable twins.
    """

    _prev: tuple[np.ndarray, int] | None
    """The previous turn's (facts, executed action), pending its TD step."""
    default_habit: ClassVar[QLearnerConfig] = QLearnerConfig()
    """The habit's configuration when ``q_config`` is None; a dict ``q_config`` overrides its fields."""

    def __init__(
        self,
        q_config: QLearnerConfig | dict[str, Any] | None = None,
        learner: QLearner | None = None,
        learn: bool = True,
        cost: CostModel | None = None,
        share_objects: bool = False,
    ) -> None:
        super().__init__(cost)
        self.share_objects = check_bool(share_objects, f"{self.name}.share_objects", RobotError)
        self._canon: Any = None
        self._to_original: np.ndarray | None = None
        self._to_canonical: np.ndarray | None = None
        if isinstance(q_config, dict):
            try:
                q_config = replace(self.default_habit, **q_config)
            except TypeError as exc:
                raise ValueError(f"bad q_config {q_config!r}: {exc}") from None
        elif q_config is not None and not isinstance(q_config, QLearnerConfig):
            raise ValueError(f"bad q_config {q_config!r}: expected a JSON object of habit settings")
        self.q_config = q_config or self.default_habit
        self._given_learner = learner
        self.learner = learner
        self.learn = learn
        self._prev: tuple[np.ndarray, int] | None = None
        self.last_td_error = 0.0

    def _reset(self, world: World) -> None:
        if self._given_learner is None:
            self.learner = QLearner(world.n_facts, self.n_actions, self.q_config)
        self._prev = None
        if self.share_objects:
            from hg_marl.agents.robots.canonical import CanonicalView

            self._canon = CanonicalView(world, self.agent)

    def _habit_facts(self, turn: Turn) -> np.ndarray:
        """The facts the habit sees this turn (canonical ones with ``share_objects``).

        Also sets the action maps :meth:`_habit_proposal` and :meth:`_remember` use, so
        call it once per turn, before both.
        """
        facts = turn.observation["observation"]
        if self._canon is None:
            return facts
        facts, self._to_original, self._to_canonical = self._canon.view(turn.state, facts)
        return facts

    def _to_robot_actions(self, values: np.ndarray) -> np.ndarray:
        """Per-action habit values (canonical labelling) in the original labelling."""
        return values if self._to_canonical is None else values[self._to_canonical]

    @property
    def habit(self) -> QLearner:
        """The Q-learner (available after :meth:`reset`)."""
        if self.learner is None:
            raise RuntimeError(f"{type(self).__name__}: call reset() before act()")
        return self.learner

    @property
    def has_pending(self) -> bool:
        """Whether a transition awaits its TD step (False on a run's first turn)."""
        return self._prev is not None

    def _remember(self, facts: np.ndarray, action: int) -> None:
        """Keep this turn's (habit facts, executed action) for the next TD step.

        ``action`` is in the original labelling; it is learnt in the habit's.
        """
        if self._to_canonical is not None:
            action = int(self._to_canonical[action])
        self._prev = (facts, action)

    def _learn_from(self, reward: float, facts: np.ndarray, done: bool = False) -> bool:
        """TD step on the pending (facts, action) -> (reward, facts) transition, if any.

        Returns:
            Whether a transition was pending (whether or not learning is on).
        """
        if self._prev is None:
            return False
        if self.learn:
            prev_facts, prev_action = self._prev
            self.last_td_error = self.habit.update(prev_facts, prev_action, reward, facts, done)
        return True

    def _habit_proposal(self, facts: np.ndarray) -> tuple[np.ndarray, np.ndarray, int, float]:
        """Q-values, Boltzmann distribution, a sampled action and the wall time it took."""
        t0 = time.perf_counter()
        habit = self.habit
        q = self._to_robot_actions(habit.q_values(facts))
        probs = softmax(q, habit.config.beta)
        action = sample(probs, self.rng)
        return q, probs, action, time.perf_counter() - t0

    def end(self, turn: Turn, terminated: bool = True) -> None:
        """Last TD step: no bootstrap when ``terminated``; forget the pending transition."""
        self._learn_from(turn.reward, self._habit_facts(turn), done=terminated)
        self._prev = None


def make_planner(world: World, config: Any = None, human_model: Any = None) -> Any:
    """Build the goal-directed expert.

    Imported here rather than at module top so the robots that never plan (habit,
    random) do not depend on the planner package.
    """
    from hg_marl.agents.planner import Planner, PlannerConfig

    return Planner(world, config=config or PlannerConfig(), human_model=human_model)


def plan_proposal(result: Any, n_actions: int, agent: Agent, cost: CostModel) -> PlanProposal:
    """Turn a ``PlanResult`` into the MetaController's :class:`PlanProposal`."""
    success = bool(result.success)
    action = int(result.robot_action)
    if success:
        dist = np.asarray(result.action_distribution(n_actions, agent), dtype=np.float64)
    else:
        dist = planner_distribution(action, n_actions)
    return PlanProposal(
        success=success,
        action=action,
        distribution=dist,
        cost=cost.planner_cost(int(result.nodes), float(result.wall_time)),
        nodes=int(result.nodes),
        human_action=int(result.human_action) if success else -1,
    )


def stall_move(turn: Turn, rng: np.random.Generator) -> int:
    """A feasible move other than ``wait``, drawn uniformly: the way out of a stall.

    A partner who waits for the robot to leave (or to do anything else) gets a new
    situation; ``wait`` is returned only when nothing else is feasible.
    """
    wait = wait_index(turn.world, turn.agent)
    moves = [int(i) for i in np.flatnonzero(turn.mask) if i != wait]
    return moves[int(rng.integers(len(moves)))] if moves else wait


def habit_stall_move(turn: Turn, q: np.ndarray, rng: np.random.Generator) -> int:
    """The habit's best *feasible* move other than ``wait``: a learning robot's way out of a stall.

    Why not the habit's proposal itself: the proposal is sampled over every action, and in
    a stall (states the habit knows little) it is mostly infeasible, a 0.2 s no-op that
    changes nothing the partner reacts to. Restricting the argmax to the mask keeps what the
    habit has learnt (its preferred feasible move) and guarantees a real move; ties go to a
    seeded draw. ``wait`` only when nothing else is feasible, as for :func:`stall_move`.
    """
    wait = wait_index(turn.world, turn.agent)
    moves = np.asarray([int(i) for i in np.flatnonzero(turn.mask) if i != wait], dtype=np.int64)
    if moves.size == 0:
        return wait
    values = np.asarray(q, dtype=np.float64)[moves]
    best = moves[values >= values.max()]
    return int(best[int(rng.integers(best.size))])


def wait_index(world: World, agent: Agent) -> int:
    """Index of ``wait`` for ``agent``."""
    return world.index(agent, WAIT)
