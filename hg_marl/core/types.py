"""Named constants shared by the whole task core: agents, action kinds, actions, state.

Nothing here knows a scenario; indices refer to a scenario's ordered lists of objects,
spots, bins and robot locations. The state is a ``NamedTuple`` on purpose: it is
immutable, hashable in C (the planner's transposition table and the oracle's value
table key on it millions of times) and cheap to copy.
"""

from __future__ import annotations

from enum import IntEnum
from typing import NamedTuple


class Agent(IntEnum):
    """The two agents, in AEC turn order."""

    ROBOT = 0
    HUMAN = 1

    @property
    def label(self) -> str:
        """The PettingZoo agent name (``"robot"`` or ``"human"``)."""
        return AGENT_NAMES[self]

    @property
    def other(self) -> Agent:
        """The partner of this agent."""
        return Agent.HUMAN if self is Agent.ROBOT else Agent.ROBOT


AGENT_NAMES: tuple[str, str] = ("robot", "human")


class Kind(IntEnum):
    """Action kinds. The robot has all but PLACE; the human has all but GOTO."""

    PICK = 0
    THROW = 1
    GIVE = 2
    TAKE = 3
    PLACE = 4
    GOTO = 5
    WAIT = 6


class Action(NamedTuple):
    """One ground action.

    Attributes:
        kind: what the action does.
        obj: the object index for PICK/THROW/GIVE/TAKE/PLACE, else -1.
        target: PLACE: the spot index. GOTO: a target code (objects ``0..N-1``, bins
            ``N..N+B-1``, the human ``N+B``). Else -1.
    """

    kind: Kind
    obj: int = -1
    target: int = -1


WAIT = Action(Kind.WAIT)


class State(NamedTuple):
    """The symbolic world state (the clock lives in the environment, not here).

    Attributes:
        where: per object, its place code: a spot index ``0..M-1``, a bin ``M+b``, the
            robot's hand ``M+B``, the human's hand ``M+B+1`` (see ``World.place_*``).
        robot_at: index of the robot's current location.
        offer_by: the agent currently offering an object (a pending handover), or -1.
        offer_obj: the object offered, or -1.
    """

    where: tuple[int, ...]
    robot_at: int
    offer_by: int = -1
    offer_obj: int = -1


class Event(NamedTuple):
    """Something that happened during a transition, for ``infos`` and logs.

    ``str(event)`` reads as a sentence, e.g. ``"robot threw tape1 into trashbin"``.
    """

    kind: str
    agent: str
    obj: str = ""
    place: str = ""

    def __str__(self) -> str:
        words = [self.agent, self.kind]
        if self.obj:
            words.append(self.obj)
        if self.place:
            words.append(self.place)
        return " ".join(words)


class Outcome(NamedTuple):
    """Result of one agent's action on a state.

    Attributes:
        state: the next state.
        ok: False when the action's preconditions did not hold (no effect).
        duration: simulated seconds the action took (a failed one: the precondition check).
        reward: 1.0 when this action completed the task (robot waits on a clean table).
        events: what happened, in order.
    """

    state: State
    ok: bool
    duration: float
    reward: float
    events: tuple[Event, ...]
