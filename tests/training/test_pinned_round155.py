"""Values that round 155's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.robots.base import habit_stall_move
from hg_marl.agents.robots.canonical import CanonicalView
from hg_marl.core import Agent, State, World
from hg_marl.core.spec import bind, parse_spec, signature_defaults
from tests.agents.test_pinned_robot_base_gate import ROBOT_WAIT, N, _state, _turn


def test_a_state_with_two_later_tapes_swapped_is_relabelled() -> None:
    # roboergosum's tapes are green1-3 (objects 0-2) and blue1-3 (objects 3-5), each colour one
    # class of interchangeable tapes; the canonical state sorts each class by place code. By hand:
    # the greens on spots (0, 1, 2) are in order, the blues on (4, 3, 5) sort to (3, 4, 5), the
    # canonical tape c being tape (0, 1, 2, 4, 3, 5)[c]: blue1 and blue2 swap, the first two tapes
    # (and the third) stay. The robot's actions are numbered per tape: picks 0-5, throws 6-11,
    # gives 12-17, takes 18-23, gotos 24-29, then goto(green_bin), goto(blue_bin), goto(human)
    # (30-32) and wait (33): canonical blue1's action stands for blue2's and back.
    world = World("roboergosum")
    view = CanonicalView(world, Agent.ROBOT)
    state = State(where=(0, 1, 2, 4, 3, 5), robot_at=0, offer_by=-1, offer_obj=-1)
    sorted_state = State(where=(0, 1, 2, 3, 4, 5), robot_at=0, offer_by=-1, offer_obj=-1)
    facts, to_original, to_canonical = view.view(state, world.facts(state))
    np.testing.assert_array_equal(facts, world.facts(sorted_state))
    assert to_original is not None and to_canonical is not None
    swap = (0, 1, 2, 4, 3, 5)
    for first in (0, 6, 12, 18, 24):
        assert [int(to_original[first + c]) for c in range(6)] == [first + o for o in swap]
        assert [int(to_canonical[first + o]) for o in range(6)] == [first + c for c in swap]
    assert [int(to_original[a]) for a in range(30, 34)] == [30, 31, 32, 33]


def test_the_stall_move_weighs_each_feasible_move_by_its_own_value() -> None:
    # Feasible: actions 5 and 10 and wait; the infeasible action 0 scores highest (8), then 10 (3),
    # then 5 (1). The stall move is the best feasible move other than wait: 10, whatever the draw.
    mask = np.zeros(N, dtype=np.int8)
    mask[[5, 10, ROBOT_WAIT]] = 1
    q = np.zeros(N)
    q[0], q[5], q[10], q[ROBOT_WAIT] = 8.0, 1.0, 3.0, 9.0
    turn = _turn(_state(), mask=mask)
    assert {habit_stall_move(turn, q, np.random.default_rng(seed)) for seed in range(10)} == {10}


def test_a_parameter_annotated_path_or_none_takes_a_text() -> None:
    # A parameter whose default is None takes a value of the type its annotation names: a
    # ``Path`` names a file, written as a text in a spec, so its placeholder is the empty text
    # and a spec's path comes back as that text.
    def factory(out: Path | None = None, rate: float = 0.5) -> None:
        del out, rate

    defaults = signature_defaults(factory)
    assert defaults == {"out": "", "rate": 0.5}
    assert bind(parse_spec("thing:out=/tmp/x.json"), defaults, what="thing") == {"out": "/tmp/x.json"}
