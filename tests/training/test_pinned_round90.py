"""The values round 90's missed planted bugs changed, pinned after the round.

Round 90 planted 16 bugs in sixteen gated modules, written blind; 12 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- ``entropy``: entropies at most ``tie_tolerance`` apart are a tie, broken by a coin
  (``abs(h_habit - h_planner) <= tie_tolerance``); with a tolerance of 0, two equal
  entropies are still a tie, so both experts are drawn;
- ``history``: the features restart with each episode; after an explicit ``reset()`` the
  next step is the new episode's first cycle and its features hold that cycle, whatever
  the tables did before the reset (tables that ended just before it included);
- ``generated`` scenarios: location 0 is the one next to the human (the generator's
  docstring), so it is the handover location, whatever the number of locations;
- a compiled ``switching`` human is named after its phases in order, one name per phase
  (a member playing two phases is compiled once but named in each), as the schedule it
  stands for.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.array_partners import CompiledSchedule
from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal, planner_distribution
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.views import robot_vector_env
from hg_marl.core.scenario_generated import generate_scenario
from hg_marl.envs.history import history_names

# --- agents/meta/entropy.py ---


def test_equal_entropies_with_a_tolerance_of_zero_are_a_tie_broken_by_a_coin() -> None:
    # the habit's distribution is the planner's own: the two entropies are the same number,
    # |h_habit - h_planner| = 0 <= 0, a tie at every decision; a fair coin over 60 ties
    # draws both experts (the chance of one expert only is 2 * 2**-60)
    criterion = EntropyCriterion(tie_tolerance=0.0)
    criterion.reset(np.random.default_rng(3))
    p = planner_distribution(0, 3)
    plan = PlanProposal.make(0, 3, 0.0)
    chosen = set()
    for i in range(60):
        view = HabitView(bytes([i]), p.copy(), 0, np.zeros(3), np.ones(3), 0.0, 0.0)
        chosen.add(criterion.choose(view, plan))
        assert criterion.stats["h_habit"] == criterion.stats["h_planner"]
    assert chosen == {Expert.HABIT, Expert.PLANNER}


# --- hg_marl/envs/history.py ---


def test_after_an_explicit_reset_the_first_step_keeps_its_cycle_on_every_table() -> None:
    # next-step autoreset, max_cycles=2: two waits truncate every table; then the caller
    # resets all tables itself. The following step is the new episode's first cycle, so
    # the robot's own last action (its wait) is in its history on every table.
    env = robot_vector_env(4, "paper2015", human="cooperative", max_cycles=2, history=2)
    env.reset(seed=0)
    n_f = env.world.n_facts
    wait = env.world.table.wait[0]
    acts = np.full(4, wait)
    env.step(acts)
    _, _, _, trunc, _ = env.step(acts)
    assert trunc.all()
    env.reset(seed=1)
    obs, *_ = env.step(acts)
    own_wait = history_names(2).index("own_kind[-1]=wait")
    assert obs[:, n_f + own_wait].all()


# --- hg_marl/core/scenario_generated.py ---


@pytest.mark.parametrize("locations", [1, 2, 3, 5])
def test_a_generated_scenarios_handover_location_is_location_0_next_to_the_human(locations: int) -> None:
    scenario = generate_scenario(objects=3, locations=locations, seed=7)
    assert scenario.handover_locations == frozenset({0})
    assert scenario.robot_locations[0] == "loc0"


# --- agents/array_partners.py ---


class _Member:
    """A compiled member stand-in: a name, no tables (the schedule's name needs nothing else)."""

    def __init__(self, name: str) -> None:
        self.name = name


def test_a_compiled_switching_human_is_named_after_each_of_its_phases() -> None:
    # phases: lazy, then cooperative, then lazy again (two members, three phases)
    schedule = CompiledSchedule([_Member("lazy"), _Member("cooperative")], [0, 1, 0], [10.0, 20.0], "time")
    assert schedule.name == "switching(lazy,cooperative,lazy)"
