"""The habit's canonical view of a state and its memo of action maps, pinned for the mutation gate.

``paper2015``'s three tapes are interchangeable (one bin accepts them all), and the
canonical state sorts them by place code (``Relabel``'s rule). Worked by hand on the robot's
actions, numbered picks 0-2, throws 3-5, gives 6-8, takes 9-11 (one per tape, in order),
the gotos, then ``wait`` (17):

- tapes on places (0, 2, 4) are already in canonical order: the view hands the facts back
  as they are, with no maps;
- tapes on (2, 4, 0): the canonical tape 0 is the one on place 0 (tape3), 1 is tape1, 2 is
  tape2, so canonical ``pick(c)`` stands for ``pick`` of tape 2, 0, 1 (a 3-cycle, which is
  not its own inverse: the two maps differ), and the facts are those of (0, 2, 4).

The memo keeps one pair of maps per relabelling met and is emptied when it holds
``_PERM_LIMIT`` (4,096) of them, so it never holds more.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.robots.canonical import CanonicalView
from hg_marl.core import Agent, State, World

CANONICAL = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
CYCLED = State(where=(2, 4, 0), robot_at=1, offer_by=-1, offer_obj=-1)
SWAPPED = State(where=(2, 0, 4), robot_at=1, offer_by=-1, offer_obj=-1)
WAIT = 17


def _view() -> tuple[World, CanonicalView]:
    world = World("paper2015")
    return world, CanonicalView(world, Agent.ROBOT)


def test_a_state_already_in_canonical_order_keeps_its_facts_and_has_no_maps() -> None:
    """Tapes on places 0, 2, 4 are sorted already: the very facts passed, no relabelling."""
    world, view = _view()
    facts = world.facts(CANONICAL)
    out, to_original, to_canonical = view.view(CANONICAL, facts)
    assert out is facts
    assert to_original is None and to_canonical is None
    assert view._perms == {}  # nothing to remember


def test_a_cycled_state_is_seen_as_the_sorted_one_with_its_actions_mapped_through_the_cycle() -> None:
    """Tapes on (2, 4, 0): canonical tape c is tape (2, 0, 1)[c], for every per-tape action."""
    world, view = _view()
    facts, to_original, to_canonical = view.view(CYCLED, world.facts(CYCLED))
    np.testing.assert_array_equal(facts, world.facts(CANONICAL))
    assert to_original is not None and to_canonical is not None
    per_tape = (2, 0, 1)
    for first in (0, 3, 6, 9):  # pick, throw, give, take of tapes 0, 1, 2
        assert [int(to_original[first + c]) for c in range(3)] == [first + o for o in per_tape]
        # the inverse: original tape o is canonical tape (1, 2, 0)[o]
        assert [int(to_canonical[first + o]) for o in range(3)] == [first + c for c in (1, 2, 0)]
    assert to_original[WAIT] == WAIT and to_canonical[WAIT] == WAIT
    n = world.n_actions(Agent.ROBOT)
    np.testing.assert_array_equal(to_original[to_canonical], np.arange(n))  # inverses of each other


def test_the_memo_keeps_one_entry_per_relabelling_met() -> None:
    """The same relabelling met twice is one entry; a second relabelling adds one."""
    world, view = _view()
    sizes = []
    for state in (CYCLED, CYCLED, SWAPPED, CANONICAL):
        view.view(state, world.facts(state))
        sizes.append(len(view._perms))
    assert sizes == [1, 1, 2, 2]


@pytest.mark.parametrize(("held", "after"), [(4095, 4096), (4096, 1)])
def test_the_memo_is_emptied_once_it_holds_4096_relabellings(held: int, after: int) -> None:
    """Below the limit a new relabelling is added (4,095 -> 4,096); at it the memo is emptied
    first and holds the new one alone. The filler keys are no permutation, so never met."""
    world, view = _view()
    dummy = (np.zeros(1, dtype=np.intp), np.zeros(1, dtype=np.intp))
    view._perms.update({(-1, i): dummy for i in range(held)})
    _, to_original, _ = view.view(CYCLED, world.facts(CYCLED))
    assert len(view._perms) == after
    assert to_original is not None and to_original[0] == 2  # computed, not a filler
