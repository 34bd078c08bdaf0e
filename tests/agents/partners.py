"""Adversarial partners for the no-livelock tests, written on the public ``Actor`` protocol.

None of them is in the human registry: they are what a user might plug in. Each one
leaves the task solvable (a robot that adapts can still clean the table), but each
breaks an assumption the robot's model of the human may rely on.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import helpful, robot_stuck
from hg_marl.core import WAIT, Agent, Kind, World
from hg_marl.policy import Actor, Turn


class _Wrapped:
    """Plays ``inner`` (a registry human), letting :meth:`override` replace its choice."""

    def __init__(self, inner: str = "cooperative") -> None:
        self.inner: Actor = make_human(inner)
        self.world: World | None = None
        self.rng = np.random.default_rng(0)

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.world, self.rng = world, rng
        self.wait = world.index(agent, WAIT)
        self.inner.reset(world, agent, np.random.default_rng(rng.integers(2**32)))

    def act(self, turn: Turn) -> int:
        return self.override(turn, int(self.inner.act(turn)))

    def override(self, turn: Turn, action: int) -> int:
        return action

    def kind(self, turn: Turn, action: int) -> Kind:
        return turn.world.actions(Agent.HUMAN)[action].kind


class RefusesRequests(_Wrapped):
    """Cooperative, but refuses handovers (``give``/``take``) with probability ``p``."""

    def __init__(self, p: float = 0.7) -> None:
        super().__init__("cooperative")
        self.p = p

    def override(self, turn: Turn, action: int) -> int:
        if self.kind(turn, action) in (Kind.GIVE, Kind.TAKE) and self.rng.random() < self.p:
            return self.wait
        return action


class NeverTakes(_Wrapped):
    """Cooperative in everything but taking what the robot offers."""

    def override(self, turn: Turn, action: int) -> int:
        return self.wait if self.kind(turn, action) is Kind.TAKE else action


class IdleWhenAsked(_Wrapped):
    """Never hands over, and stays idle while the robot stands at the handover place.

    It puts its tapes on the shared mat by itself, but only when the robot is elsewhere:
    a robot that waits at the handover place for a give that never comes waits forever.
    """

    def __init__(self) -> None:
        super().__init__("no_handover")

    def override(self, turn: Turn, action: int) -> int:
        if turn.state.robot_at in turn.world.scenario.handover_locations:
            return self.wait
        return action


class RefusesForVisit(_Wrapped):
    """Cooperative, but on some visits of the robot to the handover place refuses to do anything.

    Whether a visit is a refusing one is drawn once when the robot arrives (probability
    ``p``), so the refusal lasts the whole visit: a robot that keeps offering, or keeps
    waiting for a give, gets nothing until it leaves. Away from the handover place it is
    cooperative, so the task stays solvable.
    """

    def __init__(self, p: float = 0.5) -> None:
        super().__init__("cooperative")
        self.p = p
        self.refusing = False
        self.was_there = False

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        super().reset(world, agent, rng)
        self.refusing = self.was_there = False

    def act(self, turn: Turn) -> int:
        there = turn.state.robot_at in turn.world.scenario.handover_locations
        if there and not self.was_there:
            self.refusing = bool(self.rng.random() < self.p)
        self.was_there = there
        action = int(self.inner.act(turn))
        return self.wait if there and self.refusing else action


class UndoesWork(_Wrapped):
    """Puts tapes on the shared mat (never hands over), but now and then picks one back up."""

    def __init__(self, p: float = 0.3) -> None:
        super().__init__("no_handover")
        self.p = p

    def override(self, turn: Turn, action: int) -> int:
        world, state = turn.world, turn.state
        if world.holding(state, Agent.HUMAN) >= 0 or self.rng.random() >= self.p:
            return action
        mask = turn.mask
        acts = world.actions(Agent.HUMAN)
        for index in np.flatnonzero(mask):
            a = acts[index]
            if a.kind is Kind.PICK and world.scenario.spots[state.where[a.obj]].reach.robot_from:
                return int(index)
        return action


class ChangesWithoutNotice:
    """Cooperative, then never-giving, then lazy, ... every ``period`` simulated seconds."""

    def __init__(self, period: float = 120.0) -> None:
        self.period = period
        self.phases: list[Actor] = [make_human("cooperative"), IdleWhenAsked(), make_human("lazy")]

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        for phase in self.phases:
            phase.reset(world, agent, np.random.default_rng(rng.integers(2**32)))

    def act(self, turn: Turn) -> int:
        return int(self.phases[int(turn.clock // self.period) % len(self.phases)].act(turn))


class Busy:
    """Tidies its own area only right after a robot move that is not a wait; otherwise waits.

    A person who works while the robot is busy and stops when it idles. When the robot has
    nothing but ``wait`` feasible it tidies anyway (``robot_stuck``), as ``fo_mirror`` does:
    without that exception it would answer a robot that has cleared everything within its
    reach with waits for ever and leave the task unsolvable itself. Stationary in (state,
    robot action), never takes an offer.
    """

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.robot_wait = world.n_actions(Agent.ROBOT) - 1

    def act(self, turn: Turn) -> int:
        world, state = turn.world, turn.state
        robot = turn.last_actions[0]
        if (robot < 0 or robot == self.robot_wait) and not robot_stuck(world, state):
            return wait_index(world)
        return helpful(world, state, take=False)


PARTNERS = {
    "refuses_requests": RefusesRequests,
    "never_takes": NeverTakes,
    "refuses_for_visit": RefusesForVisit,
    "idle_when_asked": IdleWhenAsked,
    "undoes_work": UndoesWork,
    "changes_without_notice": ChangesWithoutNotice,
}
"""Partner name -> factory (no arguments)."""


class Fixed:
    """A stand-in member or partner type that always does one action (its distribution is known exactly)."""

    uses_robot_action = False

    def __init__(self, action: int) -> None:
        self.action = action

    def distribution(self, world: World, state: object, robot_action: int = -1) -> list[tuple[int, float]]:
        return [(self.action, 1.0)]
