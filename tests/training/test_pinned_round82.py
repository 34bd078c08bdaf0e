"""The values round 82's missed planted bugs changed, pinned after the round.

Round 82 planted 16 bugs in sixteen gated modules, written blind; 6 were caught. Each
value below is stated from the rule the module documents (or a simpler reference written
here), not read from the code under test:

- a switching human's logged decision is its phase human's own, with the phase and that
  human's name added;
- the learning-state criterion logs the visits the habit made from this state;
- a count refused by :func:`~hg_marl.training.limits.check_count` raises the caller's error type,
  whatever the reason (a bool, a fraction, below the minimum, over the limit);
- a ``memory`` header's ``history_cap`` is at least 1;
- an oracle cache key holds the scenario's content, not only its name;
- the observed partner is surprised by an answer it gave *less than* half its mass;
- a solve from several roots re-draws one of them uniformly: its seconds per task are the
  mean of each root's own;
- the planner's split tables: takes need an empty hand, so the held rows hold no take;
- an ``--hp`` override of an option the command line already gives is refused;
- the compiled robot's enumeration accepts a scenario of exactly ``max_states`` states.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hg_marl.agents.compiled import CompileError
from hg_marl.agents.compiled_robot import robot_states
from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.agents.memory_numpy import check_memory_file
from hg_marl.agents.meta.base import HabitView
from hg_marl.agents.meta.learning_state import LearningStateCriterion
from hg_marl.agents.models.cache import result_key
from hg_marl.agents.models.layouts import layout_distribution
from hg_marl.agents.observed_partner import ObservedPartner
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.planner.tables import split_entries
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ConfigError, HgMarlError, ModelFileError
from hg_marl.training.baselines.ppo_recurrent import config_from_options
from hg_marl.training.limits import check_count
from tests.training.test_pinned_round73 import _memory_file  # the same well-formed memory file


class _Logged:
    """A phase human that always waits and logs its own decision fields."""

    name = "logged"

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        pass

    def act(self, turn: object) -> int:
        self.last_decision = {"reason": "always waits", "p": 0.25}
        return 0


def test_a_switching_humans_decision_keeps_its_phase_humans_own_fields() -> None:
    # the switching human delegates: its record is the phase human's, with phase and name added
    human = SwitchingHuman(humans=[_Logged(), _Logged()], at=[10.0])
    human.act(SimpleNamespace(clock=0.0, tasks_solved=0))
    assert human.last_decision == {"reason": "always waits", "p": 0.25, "phase": 0, "human": "logged"}
    human.act(SimpleNamespace(clock=10.0, tasks_solved=0))
    assert human.last_decision == {"reason": "always waits", "p": 0.25, "phase": 1, "human": "logged"}


def test_the_learning_state_criterion_logs_the_states_own_visits() -> None:
    # 7 visits, min_visits 3, a TD RMS of 0.1 under 0.5: settled; the log holds 0.1 and 7 (not the threshold 3)
    habit = HabitView(b"s", np.ones(3) / 3, 1, np.zeros(3), np.array([0.9, 0.1, 0.9]), 0.0, 0.0, visits=7)
    criterion = LearningStateCriterion(threshold=0.5, min_visits=3)
    assert criterion.wants_plan(habit) is False
    assert criterion.stats == {"td_rms": pytest.approx(0.1), "visits": 7.0}


class _CallersError(HgMarlError):
    """An error type only this test raises."""


@pytest.mark.parametrize("value", [True, 1.5, 0, 11])
def test_check_count_raises_the_callers_error_type_for_every_refusal(value: object) -> None:
    # a bool, a fraction, below the minimum 1, over the limit 10: each refused with the type the caller gave
    with pytest.raises(_CallersError, match="--seeds"):
        check_count(value, "--seeds", 10, error=_CallersError)


def test_a_memory_header_with_a_history_cap_of_0_is_refused_naming_the_field() -> None:
    # the control (cap 1) is accepted; a cap of 0 is below the range [1, 1000] and refused by name
    assert check_memory_file(_memory_file()).cap == 1
    with pytest.raises(ModelFileError, match="field 'history_cap': expected an integer in \\[1, 1000\\]"):
        check_memory_file(_memory_file(history_cap=0))


def test_the_oracle_cache_key_changes_with_the_scenarios_content_under_the_same_name() -> None:
    # the same name, no handover place: another table (another answer), so another key
    world = World("paper2015")
    edited = World(dataclasses.replace(world.scenario, handover_locations=frozenset()))
    assert edited.scenario.name == world.scenario.name
    options = {"tolerance": 1e-9}
    assert result_key(world, "cooperative", options) != result_key(edited, "cooperative", options)
    assert result_key(world, "cooperative", options) == result_key(World("paper2015"), "cooperative", options)


class _EvenBase:
    """A base partner answering 0 or 1 with probability 1/2 each, wherever it is asked."""

    def distribution(self, world: World, state: object, robot_action: int) -> list[tuple[int, float]]:
        return [(0, 0.5), (1, 0.5)]


def test_an_answer_given_exactly_half_the_mass_is_no_surprise() -> None:
    # a surprise is an answer the model gave *less than* half its mass: 1/2 is not, 0 is
    world = World("paper2015")
    state = layout_distribution(world)[0][0]
    partner = ObservedPartner()
    partner.base = _EvenBase()
    partner.update(world, state, 0, 1)
    assert partner.version == 0 and partner.surprised == {}
    partner.update(world, state, 2, 5)  # never offered by the base: probability 0
    assert partner.version == 1 and partner.surprised == {(state, 2): 1}


def test_a_solve_from_two_roots_takes_the_mean_of_their_seconds_per_task() -> None:
    # a solved task re-draws one of the roots uniformly, so the expected seconds to the next
    # success from the re-draw is the mean of each root's own (renewal: each root solved alone)
    world = World("paper2015")
    first, second = (s for s, _ in layout_distribution(world)[:2])
    one = oracle_rate(world, "cooperative", roots=(first,), cache=False).seconds_per_task
    two = oracle_rate(world, "cooperative", roots=(second,), cache=False).seconds_per_task
    both = oracle_rate(world, "cooperative", roots=(first, second), cache=False)
    assert both.seconds_per_task == pytest.approx((one + two) / 2, rel=1e-6)
    assert both.rate_per_hour == pytest.approx(3600.0 / ((one + two) / 2), rel=1e-6)


def test_the_held_rows_of_the_split_tables_hold_no_pick_and_no_take() -> None:
    # one row with one entry of every kind a plan uses, in this order
    kinds = (Kind.PICK, Kind.THROW, Kind.GIVE, Kind.TAKE, Kind.PLACE)
    row = tuple((k, int(k), None, -1) for k in kinds)
    entries = ([[[row]]], [[[row]]])
    picks, takes, held = split_entries(entries)
    for agent in (0, 1):
        assert [e[0] for e in picks[agent][0][0][0]] == [Kind.PICK]
        assert [e[0] for e in takes[agent][0][0][0]] == [Kind.TAKE]
        assert [e[0] for e in held[agent][0][0][0]] == [Kind.THROW, Kind.GIVE, Kind.PLACE]


def test_an_hp_override_of_an_option_the_command_line_gives_is_refused() -> None:
    # --seed is an option of the command: --hp seed=5 would silently replace it, so it is refused
    values = {"humans": ("cooperative",), "seed": 3, "out": Path("unused")}
    assert config_from_options(values, ("gamma=0.9",)).seed == 3
    with pytest.raises(ConfigError, match="--hp 'seed=5'"):
        config_from_options(values, ("seed=5",))


def test_the_compiled_robots_enumeration_accepts_exactly_max_states_states() -> None:
    # the budget is "at most max_states": the exact count passes, one fewer is refused
    world = World("paper2015")
    n = len(robot_states(world, 10**6))
    assert len(robot_states(world, n)) == n
    with pytest.raises(CompileError, match="max_states"):
        robot_states(world, n - 1)
