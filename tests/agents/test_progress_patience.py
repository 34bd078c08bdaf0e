"""The progress guard's patience: a robot waits for a partner who works only while it keeps still.

Worked by hand from the rule in ``agents/progress.py`` (P = 200 quiet robot turns start a
spell of ``wait``; it ends once the partner has let W = 40 turns pass without moving
anything; W doubles after a spell in which nothing moved, and a spell in which something
moved makes spells start after 8 quiet turns), on scripted states whose objects never move
while the robot walks between two places (so the unchanged-state rule never fires), and
against a partner written here who helps only once the robot has waited 20 s in a row.
"""

from __future__ import annotations

import numpy as np

from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.family_out import _Historied, helpful
from hg_marl.agents.progress import (
    PATIENCE_AFTER,
    PATIENCE_AGAIN,
    PATIENCE_MAX,
    PATIENCE_WAIT,
    ArrayProgressGuard,
    ProgressGuard,
)
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn
from hg_marl.training.runner import RunConfig, run
from tests.agents.test_progress import batch_of


def test_the_patience_values_are_the_documented_ones() -> None:
    assert (PATIENCE_AFTER, PATIENCE_WAIT, PATIENCE_AGAIN, PATIENCE_MAX) == (200, 40, 8, 320)


def _walking(world: World) -> tuple[State, State]:
    """One table seen from two robot places: nothing moves, the robot's place does."""
    state = world.initial_state(np.random.default_rng(0))
    return state, state._replace(robot_at=(state.robot_at + 1) % world.table.n_locations)


def _decided(guard: ProgressGuard, states: list[State]) -> list[bool]:
    return [guard.observe(s) for s in states]


def test_a_spell_starts_after_p_quiet_turns_lasts_w_and_doubles_w_when_nothing_moves() -> None:
    world = World("paper2015")
    a, b = _walking(world)
    guard = ProgressGuard()
    walk = [a if t % 2 == 0 else b for t in range(1000)]
    decided = _decided(guard, walk[:201])
    # turn 1 has no previous state; turn t >= 2 has t - 1 quiet turns: the spell at turn 201
    assert decided == [False] * 200 + [True] and guard.waiting and guard.reason == "patience"
    assert guard.move(world, walk[200]) == world.n_actions(Agent.ROBOT) - 1 and guard.moves == 0
    # the partner moves nothing: turns 202..240 wait too (still 1..39), turn 241 (still 40) ends it
    assert _decided(guard, walk[201:241]) == [True] * 39 + [False]
    assert (guard.waiting, guard.patience, guard.quiet, guard.spells) == (False, 80, 0, 1)
    # the next spell needs P quiet turns again and lasts 80
    assert _decided(guard, walk[241:441]) == [False] * 199 + [True]
    assert _decided(guard, walk[441:521]) == [True] * 79 + [False]
    assert guard.patience == 160 and not guard.answered


def test_a_spell_in_which_the_partner_moved_something_keeps_w_and_shortens_p() -> None:
    world = World("paper2015")
    a, b = _walking(world)
    moved = a._replace(where=(world.hand[Agent.HUMAN], *a.where[1:]))
    guard = ProgressGuard()
    _decided(guard, [a if t % 2 == 0 else b for t in range(201)])
    assert guard.waiting
    # the partner picks an object at the spell's 11th turn (still 0 again), then keeps still:
    # the 40th turn after it ends the spell
    assert _decided(guard, [a] * 9 + [moved] * 41) == [True] * 49 + [False]
    assert (guard.waiting, guard.patience, guard.answered) == (False, PATIENCE_WAIT, True)
    # from now on 8 quiet turns start a spell
    assert _decided(guard, [moved] * 8) == [False] * 7 + [True]  # quiet 1..8 after the spell


def test_the_array_guard_waits_as_the_scalar_one() -> None:
    world = World("paper2015")
    a, b = _walking(world)
    moved = a._replace(where=(world.hand[Agent.HUMAN], *a.where[1:]))
    # table 0 walks and nothing moves; table 1 likewise, but its partner picks at turn 230;
    # table 2 stands at one state (the unchanged-state rule's rotation moves)
    script = [[a if t % 2 else b, (a if t % 2 else b) if t < 230 else moved, a] for t in range(700)]
    scalars = [ProgressGuard() for _ in range(3)]
    array = ArrayProgressGuard(world)
    array.reset_rows(np.arange(3))
    waited = np.zeros(3, dtype=int)
    for row in script:
        out = array.apply(batch_of(row), np.full(3, 0))
        for i, (g, s) in enumerate(zip(scalars, row, strict=True)):
            expected = g.move(world, s) if g.observe(s) else 0
            assert out[i] == expected
            waited[i] += g.waiting
        assert list(array.waiting) == [g.waiting for g in scalars]
        assert list(array.patience) == [g.patience for g in scalars]
    assert list(array.answered) == [False, True, False]
    assert waited[0] >= PATIENCE_WAIT + 2 * PATIENCE_WAIT and waited[1] > 0


class Deferential(_Historied):
    """Keeps still until the robot has waited 20 s in a row, then helps while it keeps waiting.

    Not stationary (it keeps when the robot's run of waits began). Solvable: a robot that
    waits 20 s gets a helpful partner. Without patience every planning robot solved nothing
    against it on ``paper2015`` in 1100 s (the robot never waited more than about 3 s).
    """

    name = "deferential"

    def _reset(self) -> None:
        self.since: float | None = None
        self.previous = 0.0

    def choose(self, turn: Turn) -> int:
        world = turn.world
        if turn.last_actions[0] == world.n_actions(Agent.ROBOT) - 1:
            self.since = self.previous if self.since is None else self.since
        else:
            self.since = None
        self.previous = turn.clock
        if self.since is not None and turn.clock - self.since >= 20.0:
            return helpful(world, turn.state, take=True)
        return wait_index(world)


def test_a_planner_meets_a_partner_who_helps_only_a_robot_that_keeps_still() -> None:
    result = run(make_robot("planner"), Deferential(), RunConfig(scenario="paper2015", duration=1100, seed=0))
    reasons = result.log["reason"].astype(str)
    assert (reasons == "patience").sum() >= PATIENCE_WAIT
    assert result.summary["tasks_solved"] > 0


def test_reset_rows_makes_room_for_every_table_it_names() -> None:
    world = World("paper2015")
    a, _ = _walking(world)
    for n in (1, 2, 4):
        guard = ArrayProgressGuard(world)
        guard.reset_rows(np.arange(n))
        assert len(guard.waiting) == len(guard.patience) == n and set(guard.patience) == {PATIENCE_WAIT}
        assert list(guard.apply(batch_of([a] * n), np.zeros(n, dtype=int))) == [0] * n
    grown = ArrayProgressGuard(world)
    grown.reset_rows(np.arange(3))
    grown.reset_rows(np.arange(5, 7))  # more tables later: room for 0..6, the new ones fresh
    assert len(grown.waiting) == len(grown._where) == 7 and set(grown.patience) == {PATIENCE_WAIT}
