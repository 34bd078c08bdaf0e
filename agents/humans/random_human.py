"""``random``: uniform over the feasible actions (the registry name is ``random``).

Seat-agnostic: it plays whichever agent it is reset for, so the views also use it as a
random robot.
"""

from __future__ import annotations

from hg_marl.agents.humans.base import Distribution, StationaryHuman
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn


class RandomHuman(StationaryHuman):
    """Picks uniformly at random.

    Args:
        feasible_only: draw among the feasible actions (the mask); False draws among all
            actions, failed ones included (a uniform-noise baseline).
    """

    name = "random"
    equivariant = True  # uniform over a set that relabelling maps onto itself

    def __init__(self, feasible_only: bool = True) -> None:
        super().__init__()
        self.feasible_only = bool(feasible_only)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """Uniform over the human's feasible (or all) actions."""
        return self.distribution_for(world, state, Agent.HUMAN)

    def distribution_for(self, world: World, state: State, agent: Agent) -> Distribution:
        """Uniform over ``agent``'s feasible (or all) actions."""
        options = world.feasible_indices(state, agent) if self.feasible_only else list(range(world.n_actions(agent)))
        p = 1.0 / len(options)
        return [(i, p) for i in options]

    def act(self, turn: Turn) -> int:
        """A uniform draw for the seat being played."""
        dist = self.distribution_for(turn.world, turn.state, turn.agent)
        return dist[int(self.rng.integers(len(dist)))][0]
