"""``random``: a uniform choice among the feasible actions (a floor for every score)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.robots.base import Robot
from hg_marl.policy import Turn


class RandomRobot(Robot):
    """Uniform over the actions the mask marks feasible (``wait`` always is)."""

    name = "random"

    def act(self, turn: Turn) -> int:
        """Draw one feasible action uniformly with the robot's generator."""
        feasible = np.flatnonzero(turn.mask)
        action = int(feasible[self.rng.integers(len(feasible))])
        self._record("random", action)
        return action
