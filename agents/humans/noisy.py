"""``noisy``: a Boltzmann-rational cooperative human (Overcooked-AI's human model idea).

Each feasible action ``a`` is scored by the time the team would then need to finish,
``c(a) = duration(a) + T(next state)``, with ``T`` the duration of the planner's plan
from the state after ``a`` (the robot to move next). The human picks ``a`` with
probability ``∝ exp(-(c(a) - min c) / temperature)``: temperature 0 is the cooperative
human, a large temperature a uniform draw among feasible actions. Actions after which
no plan exists score ``+inf`` (probability 0) unless nothing has a plan.
"""

from __future__ import annotations

import math

from hg_marl.agents.humans.base import Distribution, StationaryHuman, deterministic
from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.core import Agent, State, World
from hg_marl.core.cycle import cycle_length

_MEMO_LIMIT = 200_000


class NoisyHuman(StationaryHuman):
    """Cooperative, with softmax noise over the predicted time to finish.

    Args:
        temperature: seconds; the softmax temperature (0 = exactly cooperative).
    """

    name = "noisy"
    uses_robot_action = True
    equivariant = True  # scores from the planner's equivariant intents, normalised with fsum (order-free)

    def __init__(self, temperature: float = 1.0) -> None:
        super().__init__()
        if not temperature >= 0.0:
            raise ValueError(f"temperature must be non-negative seconds, got {temperature}")
        self.temperature = float(temperature)
        self._cooperative = CooperativeHuman()
        self._memo: dict[tuple[State, int], Distribution] = {}
        self._world: World | None = None

    def scores(self, world: World, state: State, robot_action: int = -1) -> dict[int, float]:
        """Predicted seconds to finish after each feasible human action.

        The cycle under way lasts ``max(d_robot, d_human)``, with ``d_robot`` the duration
        of ``robot_action`` (0 if unknown), then the plan from the state after the action.
        """
        planner = self._cooperative.planner(world)
        d_robot = world.durations.of(world.actions(Agent.ROBOT)[robot_action].kind) if robot_action >= 0 else 0.0
        out = {}
        for index in world.feasible_indices(state, Agent.HUMAN):
            step = world.step(state, Agent.HUMAN, index)
            rest = planner.intent(step.state, to_move=Agent.ROBOT).duration  # inf when no plan
            out[index] = cycle_length(d_robot, step.duration) + rest
        return out

    def seen_representatives(self, world: World) -> list[int]:
        """Per robot action, one it answers alike: the cooperative human's classes (finer than the
        duration alone, which is all :meth:`scores` reads, and what the temperature-0 answer reads)."""
        return self._cooperative.seen_representatives(world)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """Softmax over ``-scores / temperature`` (the planned action at temperature 0)."""
        if self.temperature == 0.0:
            return self._cooperative.distribution(world, state, robot_action)
        if self._world is not world:
            self._memo, self._world = {}, world
        dist = self._memo.get((state, robot_action))
        if dist is None:
            scores = self.scores(world, state, robot_action)
            best = min(scores.values())
            if math.isinf(best):
                return self._cooperative.distribution(world, state, robot_action)
            weights = {i: math.exp(-(c - best) / self.temperature) for i, c in scores.items() if not math.isinf(c)}
            total = math.fsum(weights.values())
            dist = [(i, w / total) for i, w in sorted(weights.items()) if w > 0.0] or deterministic(
                self._cooperative.planned_action(world, state, robot_action)
            )
            if len(self._memo) > _MEMO_LIMIT:
                self._memo.clear()
            self._memo[(state, robot_action)] = dist
        return dist
