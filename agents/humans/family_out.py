"""Family-out partners: ordinary human habits that no population member expresses.

Why. The adaptive robots (``belief``, ``partner_aware``) are built and tuned on partner
populations of ``preference`` humans: each member scores the task's events with one
weight vector and acts on the best one-step score. People do things no such vector says:
they freeze while something is offered to them, answer a gesture only after the robot has
paused, copy what the robot does, work in bursts, clear only some objects, forget what
they hold, shy away when the robot comes close, or watch before joining in. These eight
partners are written as code to score the robots **outside** the family they were built
for. They form the ``family_out`` set (:data:`FAMILY_OUT`), which no recipe, population
file or tuning decision may use (``tests/agents/test_family_out.py`` checks the bundled
population files, studies of the training recipes and hyper-parameter files name none).

Each partner answers as a function of what it sees: the state, the robot's action of the
cycle, the simulated clock and the history of its own and the robot's moves, which it
keeps explicitly from its turns (never a hidden call count). Random choices (``p_idle``)
go through the generator handed over in ``reset``. Stationary ones (a function of the
state, and of the robot's action under way for ``fo_mirror``) have ``distribution``, so the
oracle can solve the exact best response against them; the others are scored against the
best robot.

Shared building block: :func:`helpful` (take what the robot offers, else tidy one's own
area handing over when the robot waits at the handover place, else wait).
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.humans.base import (
    Distribution,
    StationaryHuman,
    check_p_idle,
    deterministic,
    first_feasible,
    human_only_spots,
    index_of,
    sample,
    shared_spots,
    tidy_action,
    wait_index,
    with_idle,
)
from hg_marl.core import Agent, Kind, State, World
from hg_marl.policy import Turn

FAMILY_OUT = (
    "fo_freeze_on_offer",
    "fo_after_waits",
    "fo_mirror",
    "fo_bursts",
    "fo_picky",
    "fo_forgetful",
    "fo_shy",
    "fo_slow_start",
)
"""The family-out set: registry names of the partners no recipe trains or tunes on."""


def take_offer(world: World, state: State) -> int:
    """The ``take`` of the object the robot offers, if feasible, else -1."""
    if state.offer_by != int(Agent.ROBOT) or state.offer_obj < 0:
        return -1
    return first_feasible(world, state, [index_of(world, Kind.TAKE, state.offer_obj)])


def helpful(world: World, state: State, *, take: bool = True, objects: frozenset[int] | None = None) -> int:
    """Take an offer (when ``take``), else the tidying rule, else ``wait``.

    ``objects``: the objects this partner handles at all (None: every object); an offer
    or a tidying move about another object is left alone.
    """
    if take:
        index = take_offer(world, state)
        if index >= 0 and (objects is None or state.offer_obj in objects):
            return index
    index = tidy_action(world, state, give=True)
    if index >= 0 and objects is not None:
        obj = world.actions(Agent.HUMAN)[index].obj
        if obj not in objects:
            index = -1
    return index if index >= 0 else wait_index(world)


def robot_stuck(world: World, state: State) -> bool:
    """Whether the robot has no feasible move but ``wait`` (nothing left within its reach).

    A partner whose habit answers something the robot does (``fo_mirror``: its idling;
    ``fo_shy``: its standing at a handover place) makes an exception when the robot does
    it for lack of anything else: otherwise both would wait forever and the partner, not
    the robot, would leave the task unsolvable.
    """
    robot_wait = world.n_actions(Agent.ROBOT) - 1
    return all(i == robot_wait for i in world.feasible_indices(state, Agent.ROBOT))


class _Stationary(StationaryHuman):
    """A stationary family-out partner: one deterministic rule, idling with ``p_idle``."""

    def __init__(self, p_idle: float = 0.0) -> None:
        super().__init__()
        self.p_idle = check_p_idle(p_idle)

    def rule(self, world: World, state: State, robot_action: int) -> int:
        raise NotImplementedError

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The rule's action, mixed with ``wait`` at ``p_idle``."""
        index = self.rule(world, state, robot_action)
        if index == wait_index(world):
            return deterministic(index)
        return with_idle(deterministic(index), world, self.p_idle)


class FreezeOnOffer(_Stationary):
    """``fo_freeze_on_offer``: stops everything while the robot offers something, and never takes.

    A person who does not want to be handed things and waits, arms folded, until the robot
    gives up the offer; with no offer pending it tidies its own area (handing over when the
    robot waits empty-handed at the handover place). Stationary (the offer is in the state).
    A robot that keeps offering gets nothing done by either of them.
    """

    name = "fo_freeze_on_offer"

    def rule(self, world: World, state: State, robot_action: int) -> int:
        if state.offer_by == int(Agent.ROBOT):
            return wait_index(world)
        return helpful(world, state, take=False)


class Mirror(_Stationary):
    """``fo_mirror``: works only while the robot works, echoing the kind of the robot's action.

    Robot waits or fails: it waits. Robot offers: it takes. Otherwise it does its own
    tidying move (the robot's kind where the tidying rule offers one: a pick for a pick, a
    throw for a throw), so it keeps pace with an active robot and stops with an idle one.
    It copies the robot's *willingness*, not its helplessness: a robot that waits because
    it has no other feasible move (everything left is out of its reach) is not idling, and
    the partner carries on tidying. Without that exception the pair deadlocks whenever the
    robot runs out of reachable work (both wait forever), and the task would be left
    unsolvable by the partner, not by the robot.
    Stationary in (state, robot action) (``uses_robot_action``): an imitator.
    """

    name = "fo_mirror"
    uses_robot_action = True

    def rule(self, world: World, state: State, robot_action: int) -> int:
        wait = wait_index(world)
        if robot_action < 0:
            return wait
        kind = world.actions(Agent.ROBOT)[robot_action].kind
        if kind is Kind.WAIT:
            return helpful(world, state, take=False) if robot_stuck(world, state) else wait
        if kind is Kind.GIVE:
            index = take_offer(world, state)
            return index if index >= 0 else wait
        held = world.holding(state, Agent.HUMAN)
        if kind is Kind.THROW and held >= 0:
            index = first_feasible(world, state, [index_of(world, Kind.THROW, held)])
            if index >= 0:
                return index
        return helpful(world, state, take=False)


class Picky(_Stationary):
    """``fo_picky``: throws, takes and hands over only every other object (even index).

    A person who clears only the things they consider theirs (objects ``0, 2, 4...``): the
    others it never throws, takes nor hands over; it only moves one that lies where the
    robot cannot reach onto a free shared spot (so the task stays solvable, by the robot).
    Stationary; not equivariant (the rule names objects by index).
    """

    name = "fo_picky"

    def rule(self, world: World, state: State, robot_action: int) -> int:
        wait = wait_index(world)
        held = world.holding(state, Agent.HUMAN)
        shared = shared_spots(world)
        if held >= 0:
            if held % 2 == 0:
                index = tidy_action(world, state, give=True)
            else:
                index = first_feasible(world, state, [index_of(world, Kind.PLACE, held, s) for s in shared])
            return index if index >= 0 else wait
        if state.offer_obj >= 0 and state.offer_obj % 2 == 0:
            index = take_offer(world, state)
            if index >= 0:
                return index
        free_shared = any(s not in state.where for s in shared)
        only_human = human_only_spots(world)
        for o, place in enumerate(state.where):
            if place >= world.n_spots or not world.spot_reachable(state, Agent.HUMAN, place):
                continue
            if o % 2 == 0:
                bin_ok = world.table.throw_to[Agent.HUMAN][state.robot_at][o] >= 0
                useful = bin_ok or (place in only_human and free_shared)
            else:
                useful = place in only_human and free_shared
            if useful:
                index = first_feasible(world, state, [index_of(world, Kind.PICK, o)])
                if index >= 0:
                    return index
        return wait


class Shy(_Stationary):
    """``fo_shy``: freezes whenever the robot stands at a handover place; works when it is away.

    A person uneasy with the robot close by: never takes nor hands over, tidies its own area
    (moving what the robot cannot reach onto a shared spot) only while the robot is at a
    location where no handover is possible, or while the robot stands there with nothing
    else it can do (:func:`robot_stuck`). Stationary (the robot's location is in the state).
    """

    name = "fo_shy"

    def rule(self, world: World, state: State, robot_action: int) -> int:
        if state.robot_at in world.scenario.handover_locations and not robot_stuck(world, state):
            return wait_index(world)
        index = tidy_action(world, state, give=False)
        return index if index >= 0 else wait_index(world)


class _Historied:
    """A non-stationary family-out partner: it keeps what it saw at its own turns.

    Subclasses implement :meth:`choose` from the turn and their explicit history; the
    history is cleared in :meth:`reset`, so the same seed gives the same run.
    """

    name = "historied"

    def __init__(self, p_idle: float = 0.0) -> None:
        self.p_idle = check_p_idle(p_idle)
        self.world: World | None = None
        self.agent = Agent.HUMAN
        self.rng = np.random.default_rng(0)
        self.last_decision: dict[str, object] = {}

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Start a run: own ``rng``, forget the history."""
        self.world, self.agent, self.rng = world, agent, rng
        self._reset()

    def _reset(self) -> None:
        pass

    def choose(self, turn: Turn) -> int:
        raise NotImplementedError

    def act(self, turn: Turn) -> int:
        """The rule's action, replaced by ``wait`` with probability ``p_idle`` (seeded draw)."""
        index = self.choose(turn)
        wait = wait_index(turn.world)
        if index != wait and self.p_idle > 0:
            index = sample([(index, 1.0 - self.p_idle), (wait, self.p_idle)], self.rng)
        self.last_decision = {"human": self.name, "action": turn.world.action_names[turn.agent][index]}
        return index


class AfterWaits(_Historied):
    """``fo_after_waits``: takes an offer only once the robot has waited twice in a row just before.

    A person who needs the robot to pause before accepting something from it (it reads a
    pause as "this is for you"); otherwise tidies its own area. Not stationary: the answer
    depends on the robot's last two actions (the history of ``turn.last_actions`` it keeps).
    """

    name = "fo_after_waits"

    def _reset(self) -> None:
        self.robot_moves: list[int] = []

    def choose(self, turn: Turn) -> int:
        world, state = turn.world, turn.state
        self.robot_moves = [*self.robot_moves[-2:], turn.last_actions[0]]
        wait_r = world.n_actions(Agent.ROBOT) - 1
        # The robot's move of this cycle is the last one; the two before it must be waits.
        paused = len(self.robot_moves) >= 3 and self.robot_moves[-3] == self.robot_moves[-2] == wait_r
        return helpful(world, state, take=paused)


class Bursts(_Historied):
    """``fo_bursts``: works ``work`` simulated seconds, then rests ``rest`` seconds, and again.

    Working, it is helpful (takes offers, tidies its own area); resting, it waits whatever
    happens. Not stationary: the phase is read from the simulated clock it sees.

    Args:
        work: seconds of each working spell.
        rest: seconds of each rest.
    """

    name = "fo_bursts"

    def __init__(self, work: float = 90.0, rest: float = 60.0, p_idle: float = 0.0) -> None:
        super().__init__(p_idle)
        if not (np.isfinite(work) and np.isfinite(rest) and work > 0 and rest >= 0):
            raise ValueError(f"work must be > 0 and rest >= 0 seconds, got {work}, {rest}")
        self.work, self.rest = float(work), float(rest)

    def choose(self, turn: Turn) -> int:
        resting = turn.clock % (self.work + self.rest) >= self.work
        return wait_index(turn.world) if resting else helpful(turn.world, turn.state)


class Forgetful(_Historied):
    """``fo_forgetful``: picks up an object and forgets it in its hand for ``hold`` seconds.

    Otherwise helpful; while holding an object picked less than ``hold`` simulated seconds
    ago it does nothing with it (nor anything else). Not stationary: it remembers when it
    picked what it holds (a clock it saw).

    Args:
        hold: seconds an object stays forgotten in the hand.
    """

    name = "fo_forgetful"

    def __init__(self, hold: float = 30.0, p_idle: float = 0.0) -> None:
        super().__init__(p_idle)
        if not (np.isfinite(hold) and hold >= 0):
            raise ValueError(f"hold must be finite seconds >= 0, got {hold}")
        self.hold = float(hold)

    def _reset(self) -> None:
        self.held: tuple[int, float] | None = None

    def choose(self, turn: Turn) -> int:
        world, state = turn.world, turn.state
        held = world.holding(state, Agent.HUMAN)
        if held < 0:
            self.held = None
        elif self.held is None or self.held[0] != held:
            self.held = (held, turn.clock)  # picked (or taken) since its last turn
        if self.held is not None and turn.clock - self.held[1] < self.hold:
            return wait_index(world)
        return helpful(world, state)


class SlowStart(_Historied):
    """``fo_slow_start``: watches for the first ``warmup`` simulated seconds, then helps.

    A newcomer who first looks at how the robot works. Not stationary (reads the clock).

    Args:
        warmup: seconds of watching (waiting) at the start of a run.
    """

    name = "fo_slow_start"

    def __init__(self, warmup: float = 120.0, p_idle: float = 0.0) -> None:
        super().__init__(p_idle)
        if not (np.isfinite(warmup) and warmup >= 0):
            raise ValueError(f"warmup must be finite seconds >= 0, got {warmup}")
        self.warmup = float(warmup)

    def choose(self, turn: Turn) -> int:
        return wait_index(turn.world) if turn.clock < self.warmup else helpful(turn.world, turn.state)
