"""Values that round 169's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.models.chains import certain_states
from hg_marl.agents.models.python_model import certain_states as reference_certain_states
from tests.agents.test_pinned_planted_chains import _chain


def test_the_completing_pair_is_usable_whatever_its_own_transitions_reach() -> None:
    # Two states. Pair 0 is state 0's completing wait; its (hand-made) transition goes to
    # state 1, a trap whose only pair (pair 1) loops on itself. The completing pair is
    # followed by the re-draw, not by its own transitions, so it is always usable. Worked by
    # hand: round 1, every pair may be used; completion is reached from state 0 only (state 1's
    # loop never meets it), so alive = {0}. Round 2: pair 0 completes, so it stays usable
    # although its transition leaves alive; pair 1 leaves alive (to state 1), so it is not;
    # completion is reached from state 0 again, alive = {0} is the fixpoint. Were the
    # completing pair unusable once it leaves alive, nothing would be certain.
    pair_state = np.array([0, 1])
    terminal = np.array([True, False])
    chain = _chain([[(1, 1.0)], [(1, 1.0)]])
    alive, ok = certain_states(2, pair_state, terminal, chain)
    assert alive.tolist() == [True, False]
    assert ok.tolist() == [True, False]
    # the simpler reference, the Python model's fixpoint, agrees
    ref_alive, ref_ok = reference_certain_states(2, pair_state, terminal, np.array([0, 1]), chain.t_next)
    assert ref_alive.tolist() == alive.tolist()
    assert ref_ok.tolist() == ok.tolist()
