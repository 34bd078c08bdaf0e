"""``adversarial``: works against the team, by documented tactics only.

Tactics, in order:

1. refuses handovers: never takes what the robot offers, never gives;
2. never throws anything into a bin;
3. holding an object: hides it on a free spot only the human reaches (out of the
   robot's reach from every location); if there is none, keeps it in hand (hoarding);
4. empty-handed: steals an object from a spot both reach, preferring one the robot
   reaches from where it stands now (about to be picked);
5. otherwise waits.

With ``p_idle`` it waits instead, at random. The robot can still clean whatever the
human cannot reach; against this human most layouts can never be completed, which is
the point (the oracle reports the best achievable rate, possibly 0).
"""

from __future__ import annotations

from hg_marl.agents.humans.base import (
    Distribution,
    StationaryHuman,
    check_p_idle,
    deterministic,
    first_feasible,
    human_only_spots,
    index_of,
    wait_index,
    with_idle,
)
from hg_marl.core import Agent, Kind, State, World


class AdversarialHuman(StationaryHuman):
    """Hoards objects and moves them out of the robot's reach.

    Args:
        p_idle: probability of doing nothing at any turn.
    """

    name = "adversarial"

    def __init__(self, p_idle: float = 0.0) -> None:
        super().__init__()
        self.p_idle = check_p_idle(p_idle)

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The tactic that applies first (see the module docstring)."""
        index = self._tactic(world, state)
        if index < 0:
            return deterministic(wait_index(world))
        return with_idle(deterministic(index), world, self.p_idle)

    @staticmethod
    def _tactic(world: World, state: State) -> int:
        held = world.holding(state, Agent.HUMAN)
        if held >= 0:
            return first_feasible(world, state, [index_of(world, Kind.PLACE, held, s) for s in human_only_spots(world)])
        spots = world.scenario.spots
        stealable = [
            o
            for o, p in enumerate(state.where)
            if p < world.n_spots and spots[p].reach.human and spots[p].reach.robot_from
        ]
        stealable.sort(key=lambda o: not world.spot_reachable(state, Agent.ROBOT, state.where[o]))
        return first_feasible(world, state, [index_of(world, Kind.PICK, o) for o in stealable])
