"""Values that round 106's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.registry import make_human
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.models.solve import solve
from hg_marl.core import World
from hg_marl.core.errors import HumanError
from tests.agents.test_pinned_model_solve_gate import _model


def test_the_not_stationary_refusal_names_the_human_by_its_registry_name() -> None:
    # A switching human has no distribution: the refusal quotes its name, 'switching' (the registry's
    # name for it), not the Python object's repr ("<...SwitchingHuman object at 0x...>").
    human = make_human("switching", humans=["cooperative", "lazy"], at=[10.0])
    with pytest.raises(HumanError, match="stationary") as refused:
        stationary_human(human, World("paper2015"))
    message = str(refused.value)
    assert "'switching' has none" in message
    assert "object at" not in message


def test_the_completing_waits_q_is_zero_whatever_transitions_it_carries() -> None:
    # Two states by hand: state 0's one pair takes 4 s to state 1; state 1's completing wait
    # (pair 1) carries a transition back to state 0 (2 s), as if the re-draw were stored on it.
    # "V = 0 after the completing wait" (the solver's docstring), so V = [4, 0] and the reported
    # q (the plain operator from the values) is [4, 0]: each state's chosen pair's q is its value.
    # Read as an ordinary pair the wait's q would be 2 + V(0) = 6 s.
    model = _model([0, 1, 2], [1, 0], [1.0, 1.0], [4.0, 2.0], pairs=1)
    solution = solve(model)
    assert solution.values.tolist() == [4.0, 0.0]
    assert solution.q.tolist() == [4.0, 0.0]
    assert solution.best_pair.tolist() == [0, 1]
    assert solution.q[solution.best_pair].tolist() == solution.values.tolist()
    assert solution.seconds_per_task == 6.0  # the re-draw's 2 s, then 4 s from state 0
