"""Values that round 214's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.models.chains import certain_states
from hg_marl.agents.models.layouts import canonical_layouts
from hg_marl.agents.models.live import LiveAnswers
from hg_marl.core import State, World
from tests.agents.test_pinned_model_answers_gate import RecordingBudget
from tests.agents.test_pinned_planted_chains import _chain

PAPER = World("paper2015")


def test_a_pair_with_no_transitions_never_leaves_the_certain_states_so_it_stays_usable() -> None:
    # pair 0 completes at state 0; pair 1 (state 1) has no transition at all. Only state 0 is
    # certain (nothing leads from state 1 to a completion), and "the pairs it may use" are those
    # that never leave the certain states: pair 0 (terminal) and pair 1, which goes nowhere.
    pair_state = np.array([0, 1])
    terminal = np.array([True, False])
    alive, ok = certain_states(2, pair_state, terminal, _chain([[(0, 1.0)], []]))
    assert alive.tolist() == [True, False]
    assert ok.tolist() == [True, True]


def test_the_canonical_layouts_budget_is_told_the_canonical_deal_count() -> None:
    # paper2015: three interchangeable objects, two dealt to spots {0, 1, 2} and one to {4, 5},
    # one robot start: C(3, 2) x C(2, 1) x 1 = 6 canonical deals (36 ordered deals), so the one
    # reading (at deal 0, memory read too) is "0 of 6 layouts"
    budget = RecordingBudget()
    states = canonical_layouts(PAPER, budget)
    assert len(states) == 6
    assert budget.readings == [("layouts", 0, 6, "layouts", True)]


class _SilentFirst:
    """Answers nothing (only a zero probability) where the robot stands at 0, else one action."""

    def distribution(self, world: object, state: State, seen: int) -> list[tuple[int, float]]:
        return [(5, 0.0)] if state.robot_at == 0 else [(3, 1.0)]


def test_a_question_with_no_answer_keeps_its_zero_entries() -> None:
    # three questions: robot at 1, at 0 (no answer with probability > 0), at 1 again; the entry
    # counts are per question, in order: 1, 0, 1
    rows = [((0, 1, 2), 1, -1, -1, -1), ((0, 1, 2), 0, -1, -1, -1), ((0, 1, 2), 1, -1, -1, -1)]
    sizes, actions, probs = LiveAnswers(PAPER, _SilentFirst())(rows, lambda done, total: None)
    assert sizes.tolist() == [1, 0, 1]
    assert actions.tolist() == [3, 3]
    assert probs.tolist() == [1.0, 1.0]
