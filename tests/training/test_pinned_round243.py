"""Values that round 243's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario_file import parse_scenario
from tests.agents.test_meta import N, view
from tests.core.test_registry import TOYS
from tests.training.test_pinned_round63 import _inline

# --- agents/meta/learning_state.py ---


def test_with_min_visits_zero_a_settled_habit_acts_in_a_state_never_learnt_from() -> None:
    # The docstring: the habit acts where its RMS TD error is below ``threshold`` and it has
    # learnt from the state "at least min_visits times". With min_visits = 0 (a valid count)
    # and a TD error of 0 < 0.5, a state met 0 times qualifies: 0 >= 0, so no plan is wanted.
    criterion = LearningStateCriterion(threshold=0.5, min_visits=0)
    assert criterion.wants_plan(view(sd=np.zeros(N), visits=0)) is False
    # the control: the same state with min_visits = 1 is not yet trusted
    assert LearningStateCriterion(threshold=0.5, min_visits=1).wants_plan(view(sd=np.zeros(N), visits=0)) is True


# --- hg_marl/core/registry.py ---


def test_a_registry_lists_its_entries_in_the_order_they_were_registered() -> None:
    # TOYS registers the class Toy ("toy") first, then the entry "lazy_toy": a Mapping built
    # from that list iterates in that order (sorted, "lazy_toy" would come first).
    assert list(TOYS) == ["toy", "lazy_toy"]
    assert TOYS.listing() == "toy, lazy_toy"


# --- hg_marl/core/scenario_file.py ---


def test_a_layout_group_sharing_its_first_spot_with_an_earlier_group_is_refused() -> None:
    # The first group draws from s0 and s1, the second from s1 alone: s1 is listed twice, and
    # the reader refuses groups that share spots, whichever place the shared spot has in the list.
    two_groups = 'layout = [{ count = 1, spots = ["s0", "s1"] }, { count = 1, spots = ["s1"] }]'
    text = _inline().replace('layout = [{ count = 2, spots = ["s0", "s1"] }]', two_groups)
    assert two_groups in text
    with pytest.raises(ScenarioError, match="s1 already listed by an earlier group"):
        parse_scenario(tomllib.loads(text), "inline.toml", text=text)


# --- hg_marl/core/scenario_model.py ---


def test_an_unreachable_spot_of_the_second_layout_group_is_a_problem() -> None:
    # Two groups, the second drawing from s1 and "shelf", a spot nobody reaches: every spot a
    # layout group may draw counts (solvability_problems' docstring), the second group's too.
    two_groups = 'layout = [{ count = 1, spots = ["s0"] }, { count = 1, spots = ["s1", "shelf"] }]'
    text = _inline(spots='{ name = "shelf" }').replace('layout = [{ count = 2, spots = ["s0", "s1"] }]', two_groups)
    assert two_groups in text
    with pytest.raises(ScenarioError, match="no agent reaches spot 'shelf'"):
        parse_scenario(tomllib.loads(text), "inline.toml", text=text, strict=True)
