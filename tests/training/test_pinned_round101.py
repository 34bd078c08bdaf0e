"""Values that round 101's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.agents.humans.trace import read_trace
from hg_marl.agents.planner import Planner
from hg_marl.core import Agent, Kind, State, World
from hg_marl.core.errors import PopulationError
from hg_marl.training.baselines import compare
from tests.agents.test_pinned_trace_gate import header, step
from tests.agents.test_population import GOOD
from tests.core.test_bins import PAPER
from tests.training.test_pinned_baselines_compare_gate import _config, _Result


def test_a_plan_served_from_the_cache_is_still_proven_optimal() -> None:
    # The planner's A* only returns a plan once its cost is proven minimal (a search cut short
    # by the budget fails instead), so a fresh plan is optimal; asked again from the same state
    # it is served from the cache, and a cached plan, or any suffix of it (Bellman's principle,
    # the module docstring), is optimal too: both answers say optimal=True.
    world = World("paper2015")
    planner = Planner(world)
    state = world.initial_state(np.random.default_rng(0))
    cold = planner.plan(state)
    assert cold.success and cold.optimal and not cold.cached
    again = planner.plan(state)
    assert again.cached and again.optimal
    assert cold.plan is not None and len(cold.plan) > 1
    suffix = planner.plan(cold.plan.states[1])
    assert suffix.cached and suffix.optimal


def test_a_population_description_that_is_not_text_is_refused(tmp_path: Path) -> None:
    # The module docstring: description is free text; a number there is a bad field,
    # refused as "path:line: description: expected a text" (line 3, where it is written).
    path = tmp_path / "p.toml"
    path.write_text(GOOD.replace('scenario = "paper2015"\n', 'scenario = "paper2015"\ndescription = 3\n', 1))
    with pytest.raises(PopulationError, match=r"p\.toml:3: description: expected a text"):
        load_population(path)
    path.write_text(GOOD.replace('scenario = "paper2015"\n', 'scenario = "paper2015"\ndescription = "ok"\n', 1))
    assert load_population(path).description == "ok"


def test_a_throw_lands_in_the_first_accepting_bin_in_reach_in_scenario_order(tmp_path: Path) -> None:
    # paper2015 plus a second bin, also reached from bin_side and accepting any colour: the
    # robot at bin_side (location 0) holding tape 0 reaches both, and the rule table's rule
    # says the throw goes into the first such bin in scenario order, the trashbin (place code
    # n_spots + 0 = 6), not second_bin (7).
    path = tmp_path / "two_robot_bins.toml"
    second = '\n[[bins]]\nname = "second_bin"\nrobot_reach = ["bin_side"]\nhuman_reach = false\n'
    path.write_text(PAPER.replace('name = "paper2015"', 'name = "two_robot_bins"') + second)
    world = World(str(path))
    assert world.bins_of == ((0, 1), (0, 1), (0, 1))
    throw = world.table.action_index(Agent.ROBOT, Kind.THROW, 0)
    out = world.step(State((world.hand[Agent.ROBOT], 0, 1), 0), Agent.ROBOT, throw)
    assert out.ok
    assert out.state.where[0] == world.n_spots == 6
    assert world.place_name(out.state.where[0]) == "trashbin"


def test_a_step_without_its_action_name_gets_the_headers_name_for_its_action(tmp_path: Path) -> None:
    # The trace format makes action_name optional on a step line (the index is what counts);
    # read, each step carries the header's name of its action: paper2015's human action 0 is
    # pick(tape1), and the last one is wait.
    world = World("paper2015")
    names = list(world.action_names[Agent.HUMAN])
    path = tmp_path / "t.jsonl"
    first, second = step(action=0), step(step=1, clock=1.0)
    path.write_text("".join(json.dumps(r) + "\n" for r in (header(), first, second)))
    (episode,) = read_trace(path)
    assert [s["action_name"] for s in episode.steps] == [names[0], "wait"]
    assert names[0] == "pick(tape1)"


def test_a_batched_cell_evaluates_at_the_next_multiple_of_eval_every_not_eval_every_after_the_last(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Updates every 70 steps (0, 70, 140, 210, 280), eval_every 100, training ends at 300. The
    # documented rule: a point at step 0, then each time the count reaches the next multiple of
    # 100. Worked by hand: 0 (next due 100), 70 < 100, 140 >= 100 (next due 200), 210 >= 200
    # (next due 300), 280 < 300; then the saved model at 300: [0, 140, 210, 300]. Due 100 steps
    # after the last point instead would give 0, 140 (due 240), 280, 300.
    from hg_marl.training.baselines import ppo_batched

    def fake_batched(config: Any, on_update: Any) -> _Result:
        for steps in range(0, 300, 70):
            on_update(steps, f"model@{steps}")
        return _Result(None, tmp_path / "b.json", 300)

    monkeypatch.setattr(compare, "runner_rate", lambda *a, **k: 1.0)
    monkeypatch.setattr(ppo_batched, "train_ppo_batched", fake_batched)
    monkeypatch.setattr(compare, "result_model", lambda path: "loaded")
    record = compare.run_cell(_config(tmp_path), "ppo_batched", "lazy", 0, tmp_path / "cell")
    assert [s for s, _ in record["curve"]] == [0, 140, 210, 300]
