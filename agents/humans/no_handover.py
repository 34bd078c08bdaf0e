"""``no_handover``: "afraid of the robot", never gives nor takes, but otherwise helps.

It throws what it can and moves what the robot cannot reach onto a shared spot (e.g.
``mat_shared`` in ``paper2015``), i.e. the planner's ``no_handover`` human model played
with fixed rules (see :func:`base.tidy_action`), cheap enough for the oracle.
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


class NoHandoverHuman(StationaryHuman):
    """Helps without ever handing over.

    Args:
        p_idle: probability of doing nothing at any turn (0: always helps).
    """

    name = "no_handover"

    def __init__(self, p_idle: float = 0.0) -> None:
        super().__init__()
        self.p_idle = check_p_idle(p_idle)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The tidying rule without handovers (``wait`` if there is nothing to do)."""
        index = tidy_action(world, state, give=False)
        if index < 0:
            return deterministic(wait_index(world))
        return with_idle(deterministic(index), world, self.p_idle)
