"""The switching human's default schedule, one-human schedules, refused thresholds and first phase,
pinned for the mutation gate.

Expected values from the module's docstring: ``make_human("switching")`` plays the
cooperative human until the clock reaches 600 simulated seconds, then the lazy one; the
thresholds (one fewer than the humans) must increase; the phase in charge is the number of
thresholds reached.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.humans import HumanError, make_human
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn

PAPER = World("paper2015")


def turn_at(state: State, clock: float) -> Turn:
    obs = {"observation": PAPER.facts(state), "action_mask": PAPER.mask(state, Agent.HUMAN)}
    return Turn(PAPER, state, Agent.HUMAN, obs, clock=clock, tasks_solved=0)


def test_the_default_schedule_is_cooperative_then_lazy_from_600_seconds() -> None:
    human = SwitchingHuman()
    assert [h.name for h in human.humans] == ["cooperative", "lazy"] and human.by == "time"
    assert [human.phase_at(c, 0) for c in (0.0, 599.9, 600.0, 1e6)] == [0, 0, 1, 1]


def test_a_schedule_of_one_human_needs_no_threshold_and_plays_that_human_throughout() -> None:
    """One human, no thresholds: "one threshold fewer than humans" holds, so it is accepted,
    and every turn is that human's (phase 0), whatever the clock."""
    human = make_human("switching", humans=["lazy"], at=[])
    assert isinstance(human, SwitchingHuman)
    human.reset(PAPER, Agent.HUMAN, np.random.default_rng(0))
    state = PAPER.initial_state(np.random.default_rng(0))
    for clock in (0.0, 600.0, 1e6):
        human.act(turn_at(state, clock))
        assert human.phase == 0 and human.last_decision["human"] == "lazy"


def test_decreasing_thresholds_are_refused() -> None:
    with pytest.raises(HumanError, match="thresholds must increase"):
        make_human("switching", humans=["cooperative", "lazy", "random"], at=[120.0, 60.0])


def test_a_new_switching_human_is_in_its_first_phase_before_it_plays() -> None:
    assert SwitchingHuman(["cooperative", "lazy"], at=[0.0]).phase == 0


def test_more_thresholds_than_changes_of_human_are_refused() -> None:
    """Two humans change once: two thresholds are one too many (one fewer than humans)."""
    with pytest.raises(HumanError, match="one threshold fewer"):
        make_human("switching", humans=["cooperative", "lazy"], at=[60.0, 120.0])


def test_a_schedule_of_three_hundred_phases_is_accepted() -> None:
    """No cap on the phases: 300 humans and 299 increasing thresholds (counts past the small
    integers Python shares, so the count is compared by value)."""
    humans = ["cooperative", "lazy"] * 150
    human = SwitchingHuman(humans, at=[float(t) for t in range(1, 300)])
    assert len(human.humans) == 300 and human.phase_at(299.0, 0) == 299


def test_a_by_read_at_run_time_counts_time() -> None:
    """``by`` as a study file or a command line hands it, a string built at run time (not the
    literal's own object): "time" still means the clock."""
    by = "".join(["ti", "me"])
    human = SwitchingHuman(["cooperative", "lazy"], at=[60.0], by=by)
    assert [human.phase_at(c, 0) for c in (59.0, 60.0)] == [0, 1]
