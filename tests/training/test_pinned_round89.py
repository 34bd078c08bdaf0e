"""The values round 89's missed planted bugs changed, pinned after the round.

Round 89 planted 16 bugs in sixteen gated modules, written blind; 9 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the ``planner`` criterion plays the planner always (the paper's "planner alone"), also
  when the planner finds no plan;
- a states-budget refusal names the option that raises that budget, ``--max-states``;
- a header's ``fact_names`` and ``action_names`` are lists of names: one number among them
  refuses the header;
- interchangeable objects are those accepted by the same bins (all of them), not those
  sharing a first bin;
- the robot's batched seat runs in the ``autoreset_mode`` it is given (Gymnasium's
  ``same_step`` or ``next_step``);
- an offer lapses on the partner's reply only (docs/task.md): the giver acting again with
  its offer still standing reports no lapse;
- the adaptation sweep's runs last the configured ``duration``.
"""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.fixed import PlannerOnly
from hg_marl.agents.model_format import read_header
from hg_marl.agents.models.budget import Budget, OverBudget
from hg_marl.agents.vector_envs import robot_vector_env
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from hg_marl.core.relabel import Relabel
from hg_marl.core.types import Kind, State
from hg_marl.training.adaptation import AdaptationConfig, adaptation_jobs


def test_the_planner_criterion_plays_the_planner_also_when_it_finds_no_plan() -> None:
    # "Always the planner": the planner-only condition never hands a decision to the habit,
    # whatever the proposal says (a failed search included).
    habit = HabitView(b"s", np.array([0.5, 0.5]), 1, np.zeros(2), np.zeros(2), 0.0, 0.0)
    for success in (True, False):
        plan = PlanProposal(success, 0, np.array([0.9, 0.1]), 0.0)
        assert PlannerOnly().choose(habit, plan) is Expert.PLANNER


def test_a_states_refusal_advises_raising_max_states() -> None:
    # The refusal closes with the option that raises the budget it names (the states budget).
    budget = Budget(seconds=None, memory=None, states=10, clock=lambda: 0.0, free_memory=lambda: None)
    budget.check("explore", 5, states=10)  # at the budget: accepted (the control)
    with pytest.raises(OverBudget, match="max_states=10") as info:
        budget.check("explore", 6, states=11)
    assert "raise --max-states or" in str(info.value)
    assert "--max-seconds" not in str(info.value)


@pytest.mark.parametrize("key", ["fact_names", "action_names"])
def test_a_names_list_holding_a_number_is_refused(tmp_path: Path, key: str) -> None:
    # Every entry of a names list is a name (a string); one number refuses the header.
    header = {
        "format": "hg_marl.model",
        "kind": "table",
        "seat": "robot",
        "file": "model.npz",
        "fact_names": ["f0", "f1"],
        "action_names": ["a0", "wait"],
    }
    path = tmp_path / "model.json"
    path.write_text(json.dumps(header))
    assert read_header(path)[key] == header[key]  # the control: all names, accepted
    path.write_text(json.dumps({**header, key: ["f0", 1]}))
    with pytest.raises(ModelFileError, match=f"field '{key}': expected a list of names"):
        read_header(path)


def test_objects_are_interchangeable_only_when_every_bin_accepting_them_is_the_same() -> None:
    # Objects 1 and 2 are accepted by bins 0 and 1, object 0 by bin 0 alone: only 1 and 2 are
    # interchangeable (swapping 0 with either changes where it may go). Relabel reads only
    # ``table`` and ``bins_of`` from the world, so a stand-in holding those states the case.
    world = SimpleNamespace(table=None, bins_of=((0,), (0, 1), (0, 1)))
    relabel = Relabel(world)  # type: ignore[arg-type]
    assert relabel.classes == ((1, 2),)
    assert relabel.active
    alone = Relabel(SimpleNamespace(table=None, bins_of=((0,), (0, 1))))  # type: ignore[arg-type]
    assert alone.classes == ()
    assert not alone.active


@pytest.mark.parametrize(
    ("mode", "want"), [("same_step", AutoresetMode.SAME_STEP), ("next_step", AutoresetMode.NEXT_STEP)]
)
def test_the_robot_seat_runs_in_the_autoreset_mode_it_is_given(mode: str, want: AutoresetMode) -> None:
    # A partner given to the seat replaces the compiled human (nothing is compiled); the
    # mode is Gymnasium's, stated in the env's metadata.
    partner = SimpleNamespace(name="stand-in")
    env = robot_vector_env(num_envs=2, partner=partner, autoreset_mode=mode)
    assert env.autoreset_mode is want
    assert env.metadata["autoreset_mode"] is want


def test_the_giver_acting_again_reports_no_lapse_of_its_standing_offer() -> None:
    # docs/task.md: the *partner's* reply (anything but take) lets an offer lapse. The robot
    # acting again while its own offer stands is no reply: wherever the next state still holds
    # the offer, no let_lapse event may be reported (an event must agree with the state).
    world = World("paper2015")
    start = world.initial_state(np.random.default_rng(0))
    handover = min(world.table.handover)
    where = list(start.where)
    where[0] = world.hand[Agent.ROBOT]
    offering = State(tuple(where), handover, int(Agent.ROBOT), 0)
    wait = next(i for i, a in enumerate(world.actions(Agent.ROBOT)) if a.kind is Kind.WAIT)
    kept = 0
    for index in range(world.n_actions(Agent.ROBOT)):
        out = world.step(offering, Agent.ROBOT, index)
        if out.state.offer_by == Agent.ROBOT and out.state.offer_obj == 0:
            kept += 1
            assert not any(e.kind == "let_lapse" for e in out.events), (world.action_names[0][index], out.events)
    assert world.step(offering, Agent.ROBOT, wait).state.offer_by == Agent.ROBOT  # the case is met
    assert kept >= 1
    # the partner's reply other than take does let it lapse (the rule's other half)
    human_wait = next(i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.WAIT)
    reply = world.step(offering, Agent.HUMAN, human_wait)
    assert reply.state.offer_by == -1
    assert [e.kind for e in reply.events] == ["let_lapse"]


def test_the_adaptation_runs_last_the_configured_duration() -> None:
    # The config's duration is each run's simulated length (its switch times are within it).
    config = AdaptationConfig(seeds=2, duration=90.0, switches=("lazy",), robots=("planner", "habit"))
    jobs = adaptation_jobs(config)
    assert len(jobs) == 4
    assert {job.duration for job in jobs} == {90.0}
