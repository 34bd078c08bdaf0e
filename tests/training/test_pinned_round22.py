"""The values round 22's missed planted bugs changed, pinned after the round.

Round 22 planted 14 bugs in fourteen user-facing modules outside the mutation gate after
their promises had been pinned (``tests/training/test_pinned_promises_e.py``); 6 were
caught. Each value below is stated from the rule the module documents:

- ``hg-marl run`` prints the run's own simulated time (a run ends at its first cycle past
  the duration, so the clock is not the duration asked);
- ``hg-marl plan`` says "not proven optimal" of a plan the search did not prove;
- ``hg-marl population generate`` accepts as many candidates as the members it asks for;
- ``hg-marl switching --pairs A/B`` plays A first;
- the noisy human's seconds for an action are the cycle's, ``max(d_robot, d_human)``:
  with the robot's ``goto`` (3 s) under way, each is raised to 3 s;
- the adversarial human steals only from spots the robot can also reach;
- the text picture lists under a bin what was thrown into it, not what lies on the spot
  with the bin's index;
- ``hg-marl reproduce --adaptation-seeds N`` gives the adaptation runs N seeds.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.adversarial import AdversarialHuman
from hg_marl.agents.humans.noisy import NoisyHuman
from hg_marl.agents.robots import make_robot
from hg_marl.core import Agent, Kind, World
from hg_marl.envs.render import render_ansi
from hg_marl.training.runner import RunConfig, run
from tests.cli_helpers import run_main


class _Stop(Exception):
    """Raised by a stand-in to end a command once the value under test is known."""


def test_the_run_command_prints_the_runs_own_simulated_time() -> None:
    expected = run(make_robot("planner"), make_human("lazy"), RunConfig(scenario="paper2015", duration=30, seed=0))
    clock = float(expected.summary["simulated_time"])
    assert clock != 30.0  # the last cycle ends past the duration
    code, out, _ = run_main(["run", "--robot", "planner", "--human", "lazy", "--duration", "30", "--seed", "0"])
    assert code == 0
    (line,) = [ln for ln in out.splitlines() if "simulated time" in ln]
    assert line.split()[-2] == f"{clock:.1f}"


def test_the_plan_command_says_not_proven_of_a_plan_not_proven(monkeypatch: pytest.MonkeyPatch) -> None:
    import hg_marl.training.commands.plan as plan_command

    class Unproven(plan_command.Planner):
        def plan(self, state: Any) -> Any:
            return dataclasses.replace(super().plan(state), optimal=False)

    monkeypatch.setattr(plan_command, "Planner", Unproven)
    code, out, _ = run_main(["plan", "--scenario", "paper2015", "--seed", "0"])
    assert code == 0
    assert "(not proven optimal)" in out


def test_the_population_command_accepts_as_many_candidates_as_members(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import hg_marl.training.population_gen as population_gen

    seen: dict[str, Any] = {}

    def stop(config: Any, *args: Any, **kwargs: Any) -> Any:
        seen["config"] = config
        raise _Stop

    monkeypatch.setattr(population_gen, "generate", stop)
    args = ["population", "generate", "--scenario", "paper2015", "--out", str(tmp_path / "p.toml")]
    with pytest.raises(_Stop):
        run_main([*args, "--train", "2", "--validation", "1", "--held-out", "1", "--candidates", "4"])
    assert seen["config"].candidates == 4
    code, _, err = run_main([*args, "--train", "2", "--validation", "1", "--held-out", "1", "--candidates", "3"])
    assert code == 2 and "--candidates" in err


def test_a_switching_pair_a_b_plays_a_first(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import hg_marl.training.switching as switching

    seen: dict[str, Any] = {}

    def stop(config: Any) -> None:
        seen["pairs"] = config.pairs
        raise _Stop

    monkeypatch.setattr(switching, "check_config", stop)
    population = Path("populations/paper2015.toml").resolve()
    from hg_marl.agents.humans.population import load_population

    names = [m.name for m in load_population(population).members()][:2]
    args = ["switching", "--population", str(population), "--scenario", "paper2015"]
    with pytest.raises(_Stop):
        run_main([*args, "--pairs", f"{names[0]}/{names[1]}", "--periods", "20", "--out", str(tmp_path)])
    assert seen["pairs"] == ((names[0], names[1]),)


def test_the_noisy_humans_seconds_are_the_cycles_with_the_robots_action_under_way() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    goto = next(i for i, a in enumerate(world.actions(Agent.ROBOT)) if a.kind is Kind.GOTO)
    d_goto = world.durations.of(Kind.GOTO)
    human = NoisyHuman()
    alone, under_goto = human.scores(world, state), human.scores(world, state, goto)
    assert alone.keys() == under_goto.keys() and len(alone) >= 2
    for index, seconds in alone.items():
        d_human = world.step(state, Agent.HUMAN, index).duration
        assert under_goto[index] == pytest.approx(seconds + max(d_goto, d_human) - d_human, abs=1e-9)


def test_the_adversarial_human_steals_only_from_spots_the_robot_also_reaches() -> None:
    world = World("roboergosum")
    spots = world.scenario.spots
    picks = 0
    for seed in range(100):
        state = world.initial_state(np.random.default_rng(seed))
        (index, _), *_ = AdversarialHuman().distribution(world, state)
        action = world.actions(Agent.HUMAN)[index]
        if action.kind is Kind.PICK:
            picks += 1
            spot = spots[state.where[action.obj]]
            assert spot.reach.human and spot.reach.robot_from  # a shared spot
    assert picks > 0
    # one object left, on a spot only the human reaches: nothing to steal, so it waits
    paper = World("paper2015")  # spot 4, human_mat_1, is the human's alone
    state = paper.initial_state(np.random.default_rng(0))
    alone = state._replace(where=(4, *[paper.n_spots] * (paper.n_objects - 1)))
    assert not paper.scenario.spots[4].reach.robot_from
    assert AdversarialHuman().distribution(paper, alone) == [(paper.n_actions(Agent.HUMAN) - 1, 1.0)]


def test_the_text_picture_lists_under_a_bin_what_was_thrown_into_it() -> None:
    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    assert state.where[:2] == (0, 4)  # tape1 on spot 0, tape2 on spot 4
    thrown = state._replace(where=(state.where[0], world.n_spots, state.where[2]))  # tape2 in the bin
    lines = render_ansi(world, thrown, 0.0, 0, 0).splitlines()
    (bin_line,) = [ln for ln in lines if ln.strip().startswith("bin ")]
    (first_spot,) = [ln for ln in lines if ln.strip().startswith(f"spot {world.scenario.spots[0].name}")]
    assert bin_line.split()[-1] == "tape2"
    assert first_spot.split()[-1] == "tape1"


def test_the_reproduce_command_gives_the_adaptation_its_own_seeds(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import hg_marl.training.reproduce as reproduce

    seen: dict[str, Any] = {}

    def stop(config: Any, **kwargs: Any) -> Any:
        seen["config"] = config
        raise _Stop

    monkeypatch.setattr(reproduce, "reproduce", stop)
    with pytest.raises(_Stop):
        run_main(["reproduce", "--seeds", "2", "--adaptation-seeds", "3", "--out", str(tmp_path / "out")])
    assert (seen["config"].seeds, seen["config"].adaptation_seeds) == (2, 3)
