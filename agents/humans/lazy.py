"""``lazy``: handles only objects in its own area, never takes, and often does nothing.

It matches the planner's ``lazy`` human model (every kind but ``take``, idling with
``p_idle``) with fixed rules instead of a plan, so it is cheap enough for the oracle to
fold into models of hundreds of thousands of states: see :func:`base.tidy_action`.
"""

from __future__ import annotations

from hg_marl.agents.humans.base import (
    Distribution,
    StationaryHuman,
    check_p_idle,
    deterministic,
    tidy_action,
    wait_index,
    with_idle,
)
from hg_marl.core import State, World


class LazyHuman(StationaryHuman):
    """Tidies its own area (throws, hands over or moves objects within the robot's reach).

    Args:
        p_idle: probability of doing nothing at any turn.
    """

    name = "lazy"

    def __init__(self, p_idle: float = 0.3) -> None:
        super().__init__()
        self.p_idle = check_p_idle(p_idle)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """``wait`` with ``p_idle``, else the tidying rule (``wait`` if there is nothing to do)."""
        index = tidy_action(world, state, give=True)
        if index < 0:
            return deterministic(wait_index(world))
        return with_idle(deterministic(index), world, self.p_idle)
