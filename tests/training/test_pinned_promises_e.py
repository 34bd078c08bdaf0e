"""Promises of the user-facing training, agent and env modules that no earlier test pinned.

Each section pins what a user reads or relies on in one module: the JSON writer's text,
the commands' refusals (one line naming the option, exit 2) and printed fields, the
scripted humans' documented tactics and probabilities, the switching human's thresholds,
the parallel env's mismatch message, the renderer's text, and the play session's counts.
Expected values are worked by hand from the docstrings and help texts (the defaults they
state, the format strings they promise), from a simpler reference computed in the test
(a softmax, a sum of terms), or from a property (probabilities summing to one).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import hg_marl
from hg_marl.agents.humans import make_human
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import HumanError
from tests.cli_helpers import error_lines, run_main


def _population(tmp_path: Path) -> Path:
    """A two-member population file with one spread, written by hand."""
    path = tmp_path / "pop.toml"
    path.write_text(
        'name = "tiny"\nscenario = "paper2015"\n\n[spread.train]\nselected = -1.5\nrandom = -2.25\n\n'
        '[[members]]\nname = "a"\nsplit = "train"\nspec = "preference:accept=0.9"\n\n'
        '[[members]]\nname = "b"\nsplit = "train"\nspec = "preference:accept=0.2"\n'
    )
    return path


# ---- training/io.py ----------
def test_write_json_writes_non_finite_floats_as_null_sorted_and_indented(tmp_path: Path) -> None:
    from hg_marl.training.io import write_json

    # docstring: indented (2), strict JSON, NaN as null; keys sorted; one trailing newline
    path = write_json(tmp_path / "r.json", {"b": float("nan"), "a": [1, float("-inf")]})
    assert path.read_text() == '{\n  "a": [\n    1,\n    null\n  ],\n  "b": null\n}\n'


def test_write_json_stringifies_keys_and_writes_tuples_and_numpy_floats(tmp_path: Path) -> None:
    from hg_marl.training.io import write_json

    # a non-string key becomes its str (so it sorts among the others), a tuple a list,
    # a numpy float a plain number
    path = write_json(tmp_path / "r.json", {3: (np.float64(0.5), float("inf")), "a": 1})
    assert path.read_text() == '{\n  "3": [\n    0.5,\n    null\n  ],\n  "a": 1\n}\n'


# ---- training/commands/run.py ----------
def test_run_list_prints_robots_criteria_and_humans_one_line_each() -> None:
    from hg_marl.agents.humans import available_humans
    from hg_marl.agents.meta import available_criteria
    from hg_marl.agents.robots import available_robots

    code, out, _ = run_main(["run", "--list"])
    assert code == 0
    assert out.splitlines() == [
        "robots:   " + ", ".join(available_robots()),
        "criteria: " + ", ".join(available_criteria()),
        "humans:   " + ", ".join(available_humans()),
    ]


def test_run_refuses_criterion_given_twice_and_model_for_a_robot_without_one(tmp_path: Path) -> None:
    code, _, err = run_main(["run", "--robot", "hybrid:criterion=vpi", "--criterion", "vpi", "--duration", "30"])
    assert code == 2
    assert len(error_lines(err)) == 1 and "--criterion and --robot/--robot-param both set criterion" in err
    code, _, err = run_main(["run", "--robot", "planner", "--model", str(tmp_path / "m.zip"), "--duration", "30"])
    assert code == 2 and "--model is for --robot sb3 or memory, not planner" in err


def test_run_summary_header_names_robot_human_scenario_seed_and_duration() -> None:
    code, out, _ = run_main(["run", "--robot", "planner", "--human", "lazy", "--duration", "30", "--seed", "4"])
    assert code == 0
    lines = out.splitlines()
    # the format string: "robot R with human H on S, seed N, D simulated s" (D with no decimals)
    assert lines[0] == "robot planner with human lazy on paper2015, seed 4, 30 simulated s"
    assert [line.split()[0] for line in lines[1:5]] == ["tasks", "robot", "planner", "simulated"]


# ---- training/commands/plan.py ----------
def test_plan_refuses_an_unknown_human_model_naming_human() -> None:
    code, out, err = run_main(["plan", "--human", "bogus"])
    assert code == 2 and out == ""
    lines = error_lines(err)
    assert len(lines) == 1 and "--human: " in lines[0]


def test_plan_cost_terms_add_up_to_the_cost_and_header_names_the_inputs() -> None:
    code, out, _ = run_main(["plan", "--seed", "2", "--human", "lazy"])
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == "scenario paper2015, seed 2, human model lazy"
    (cost_line,) = [line for line in lines if line.startswith("cost ")]
    cost = float(cost_line.split()[1])
    start = lines.index(cost_line) + 1
    terms = [float(line.split()[-1]) for line in lines[start:] if line.startswith("  ")]
    assert terms and math.fsum(terms) == pytest.approx(cost, abs=2e-3 * len(terms))
    assert lines[-1].startswith("planning time ") and lines[-1].endswith(" nodes expanded")


def test_plan_without_a_plan_in_budget_says_so_and_exits_1() -> None:
    code, out, _ = run_main(["plan", "--budget", "1"])
    assert code == 1
    lines = out.splitlines()
    assert lines[1].startswith("no plan: ")
    assert lines[2].startswith("planning time ") and lines[2].endswith(" nodes")


# ---- training/commands/population.py ----------
def test_population_generate_refuses_all_splits_empty(tmp_path: Path) -> None:
    args = ["population", "generate", "--out", str(tmp_path / "p.toml")]
    code, _, err = run_main([*args, "--held-out", "0", "--train", "0", "--validation", "0"])
    assert code == 2
    assert error_lines(err) == [line for line in error_lines(err) if "--held-out, --train, --validation" in line]
    assert "at least one member" in err


def test_population_generate_counts_default_splits_against_candidates(tmp_path: Path) -> None:
    # defaults: held_out 8 + train 8 + validation 4 = 20 members; 10 candidates (more than
    # any one split) are still too few for all three
    code, _, err = run_main(["population", "generate", "--out", str(tmp_path / "p.toml"), "--candidates", "10"])
    assert code == 2 and "--candidates: 10 is fewer than the 20 members asked for" in err


def test_population_show_prints_header_spread_and_member_rows(tmp_path: Path) -> None:
    code, out, _ = run_main(["population", "show", str(_population(tmp_path))])
    assert code == 0
    assert out.splitlines() == [
        "tiny: 2 members measured on paper2015",
        "spread train: selected -1.50, random -2.25",
        f"{'name':<6} {'split':<10} spec",
        f"{'a':<6} {'train':<10} preference:accept=0.9",
        f"{'b':<6} {'train':<10} preference:accept=0.2",
    ]


# ---- training/commands/switching.py ----------
def test_switching_refuses_a_pair_of_one_member_twice(tmp_path: Path) -> None:
    pop = str(_population(tmp_path))
    code, _, err = run_main(["switching", "--population", pop, "--pairs", "a/a", "--out", str(tmp_path / "o")])
    assert code == 2
    assert len(error_lines(err)) == 1 and "--pairs 'a/a': expected two different members A/B" in err


def test_switching_refuses_periods_that_are_not_numbers_and_unknown_members(tmp_path: Path) -> None:
    pop = str(_population(tmp_path))
    base = ["switching", "--population", pop, "--out", str(tmp_path / "o")]
    code, _, err = run_main([*base, "--pairs", "a/b", "--periods", "10,soon"])
    assert code == 2 and "--periods '10,soon': expected a comma list of seconds" in err
    code, _, err = run_main([*base, "--pairs", "a/zed"])
    assert code == 2 and f"--pairs: zed not a member of {pop} (a, b)" in err


# ---- training/commands/traces.py ----------
def _trace_dir(tmp_path: Path) -> Path:
    from hg_marl.training.play.session import PlaySession

    ticks = iter(float(k) for k in range(1000))
    session = PlaySession(record=tmp_path / "play", player="alice", timer=lambda: next(ticks))
    for _ in range(3):
        session.play("wait")
    session.close()
    return tmp_path / "play"


def test_traces_no_compare_prints_only_the_recorded_row(tmp_path: Path) -> None:
    code, out, _ = run_main(["traces", str(_trace_dir(tmp_path)), "--no-compare"])
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == "1 session(s) by alice against planner"
    assert len(lines) == 3 and lines[2].split()[:2] == ["recorded", "3"]
    assert "closest scripted human" not in out


def test_traces_compare_names_the_nearest_scripted_human_first_in_the_ranking(tmp_path: Path) -> None:
    code, out, _ = run_main(["traces", str(_trace_dir(tmp_path))])
    assert code == 0
    last = out.splitlines()[-1]
    best = last.split(": ")[1].split(" (")[0]
    ranked = last.split("acceptance: ")[1].rstrip(")").split(", ")
    distances = [float(item.split()[1]) for item in ranked]
    # the ranking is ascending and the named human is one at the smallest distance
    assert distances == sorted(distances)
    assert best in [item.split()[0] for item, d in zip(ranked, distances, strict=True) if d == distances[0]]


# ---- agents/humans/noisy.py ----------
def test_noisy_refuses_a_negative_temperature() -> None:
    from hg_marl.agents.humans.noisy import NoisyHuman

    with pytest.raises(ValueError, match="temperature must be non-negative"):
        NoisyHuman(temperature=-0.5)
    NoisyHuman(temperature=0.0)  # 0 is allowed: the cooperative human


def test_noisy_distribution_is_the_softmax_of_minus_scores_over_temperature() -> None:
    from hg_marl.agents.humans.noisy import NoisyHuman

    world = World("paper2015")
    state = world.initial_state(np.random.default_rng(0))
    human = NoisyHuman(temperature=3.0)
    scores = human.scores(world, state)
    finite = {i: c for i, c in scores.items() if math.isfinite(c)}
    best = min(finite.values())
    weights = {i: math.exp(-(c - best) / 3.0) for i, c in finite.items()}  # reference softmax
    total = sum(weights.values())
    dist = dict(human.distribution(world, state))
    assert len(dist) > 1 and set(dist) == set(weights)
    for i, w in weights.items():
        assert dist[i] == pytest.approx(w / total)


# ---- agents/humans/adversarial.py ----------
def test_adversarial_steals_first_the_object_the_robot_is_about_to_pick() -> None:
    world = World("roboergosum")  # paper2015 has no spot both reach: nothing to steal there
    state = world.initial_state(np.random.default_rng(0))
    spots = world.scenario.spots
    both = [
        o for o, p in enumerate(state.where) if p < world.n_spots and spots[p].reach.human and spots[p].reach.robot_from
    ]
    near = [o for o in both if world.spot_reachable(state, Agent.ROBOT, state.where[o])]
    far = [o for o in both if o not in near]
    assert near and far and far[0] < near[0]  # the preference decides, not the object order
    ((index, p),) = make_human("adversarial").distribution(world, state)  # p_idle defaults to 0
    action = world.actions(Agent.HUMAN)[index]
    assert p == 1.0 and action.kind is Kind.PICK and action.obj == near[0]


def test_adversarial_p_idle_mixes_wait_in_with_that_probability() -> None:
    world = World("roboergosum")
    state = world.initial_state(np.random.default_rng(0))
    dist = dict(make_human("adversarial:p_idle=0.25").distribution(world, state))
    names = world.action_names[Agent.HUMAN]
    (wait,) = [i for i in dist if names[i] == "wait"]
    assert len(dist) == 2 and dist[wait] == pytest.approx(0.25)
    assert sum(dist.values()) == pytest.approx(1.0)


# ---- agents/humans/lazy.py ----------
def test_lazy_waits_with_its_default_p_idle_of_0_3() -> None:
    world = World("paper2015")
    names = world.action_names[Agent.HUMAN]
    rng = np.random.default_rng(0)
    for _ in range(20):  # a layout where the lazy human has something to tidy
        state = world.initial_state(rng)
        dist = dict(make_human("lazy").distribution(world, state))
        if len(dist) == 2:
            break
    (wait,) = [i for i in dist if names[i] == "wait"]
    assert dist[wait] == pytest.approx(0.3)  # docstring default
    assert sum(dist.values()) == pytest.approx(1.0)


# ---- agents/humans/switching.py ----------
def test_switching_human_moves_on_at_the_threshold_itself_and_counts_tasks_by_tasks() -> None:
    from hg_marl.agents.humans.switching import SwitchingHuman

    by_time = SwitchingHuman(["cooperative", "lazy", "random"], at=[60.0, 120.0])
    # "until the clock reaches 600": at the threshold the next human is in charge
    assert [by_time.phase_at(c, 99) for c in (0.0, 59.9, 60.0, 119.9, 120.0, 1e6)] == [0, 0, 1, 1, 2, 2]
    by_tasks = SwitchingHuman(["cooperative", "lazy"], at=[3], by="tasks")
    assert [by_tasks.phase_at(1e6, n) for n in (0, 2, 3)] == [0, 0, 1]


def test_switching_human_refuses_equal_thresholds_and_reset_returns_to_phase_0() -> None:
    from hg_marl.agents.humans.switching import SwitchingHuman

    with pytest.raises(ValueError, match="thresholds must increase"):
        SwitchingHuman(["cooperative", "lazy", "random"], at=[60.0, 60.0])
    human = SwitchingHuman(["cooperative", "lazy"], at=[0.0])
    env = hg_marl.env()
    env.reset(seed=0)
    raw = env.unwrapped
    human.reset(raw.world, Agent.HUMAN, np.random.default_rng(0))
    env.step(raw.world.n_actions(Agent.ROBOT) - 1)  # the robot waits; the clock is >= 0
    human.act(raw.turn("human"))
    assert human.phase == 1 and human.last_decision["phase"] == 1 and human.last_decision["human"] == "lazy"
    human.reset(raw.world, Agent.HUMAN, np.random.default_rng(0))
    assert human.phase == 0


# ---- hg_marl/envs/parallel.py ----------
def test_parallel_step_names_missing_and_unexpected_agents_sorted() -> None:
    from hg_marl.envs.parallel import AgentMismatchError, parallel_env

    env = parallel_env()
    env.reset(seed=0)
    with pytest.raises(AgentMismatchError) as info:
        env.step({"robot": 0, "zed": 1, "alf": 2})
    # str(), not a KeyError repr: no surrounding quotes
    assert str(info.value) == (
        "parallel step needs one action for each live agent ['human', 'robot']; "
        "missing ['human'], unexpected ['alf', 'zed']"
    )


def test_parallel_step_plays_a_whole_cycle() -> None:
    from hg_marl.envs.parallel import parallel_env

    env = parallel_env()
    env.reset(seed=0)
    world = World("paper2015")
    waits = {"robot": world.n_actions(Agent.ROBOT) - 1, "human": world.action_names[Agent.HUMAN].index("wait")}
    obs, rewards, _, _, _ = env.step(waits)
    assert set(obs) == set(rewards) == {"robot", "human"}
    assert env.unwrapped.cycles == 1


# ---- hg_marl/envs/render.py ----------
def test_caption_shows_clock_tasks_and_dash_for_no_action_yet() -> None:
    from hg_marl.envs.render import caption_of

    world = World("paper2015")
    wait = world.action_names[Agent.HUMAN].index("wait")
    assert caption_of(world, 12.345, 2, (-1, wait)) == "t=12.3s  tasks=2   robot: -   human: wait"


def test_reach_tint_colours_spots_by_who_reaches_them() -> None:
    from hg_marl.envs.render import reach_tint

    # the module docstring: blue robot only, red human only, purple both, grey nobody
    expected = {(True, True): (150, 100, 200), (True, False): (120, 150, 230), (False, True): (230, 130, 130)}
    expected[(False, False)] = (160, 160, 160)
    seen = set()
    for name in ("paper2015", "roboergosum"):
        for spot in World(name).scenario.spots:
            key = (bool(spot.reach.robot_from), spot.reach.human)
            seen.add(key)
            assert reach_tint(spot) == expected[key]
    assert len(seen) >= 3


# ---- training/play/session.py ----------
def test_session_summary_text_before_any_move_uses_plurals_and_omits_response_time() -> None:
    from hg_marl.training.play.session import PlaySession

    session = PlaySession(player="bob", seed=1, timer=lambda: 0.0)
    text = session.summary_text()
    assert text.startswith("bob played 0 moves with the robot planner on paper2015 (seed 1): 0 tasks solved in ")
    assert "s a task" not in text and "response time" not in text
    assert "Handovers: you gave 0 and the robot took 0" in text


def test_session_refuses_a_move_after_close_and_an_index_out_of_range() -> None:
    from hg_marl.training.play.session import PlaySession

    ticks = iter(float(k) for k in range(100))
    session = PlaySession(player="bob", timer=lambda: next(ticks))
    n = len(session.world.action_names[Agent.HUMAN])
    with pytest.raises(HumanError, match=rf"action {n} is not an index in \[0, {n}\)"):
        session.play(n)
    session.play("wait")
    assert session.summary()["moves"] == 1 and session.summary()["mean_response_time"] == 1.0
    session.close()
    with pytest.raises(HumanError, match="the game is over"):
        session.play("wait")


# ---- training/commands/reproduce.py ----------
def test_reproduce_refuses_too_many_seeds_naming_the_option(tmp_path: Path) -> None:
    from hg_marl.training.limits import MAX_SEEDS

    code, out, err = run_main(["reproduce", "--out", str(tmp_path / "r"), "--seeds", str(MAX_SEEDS + 1)])
    assert code == 2 and out == ""
    lines = error_lines(err)
    assert len(lines) == 1 and "--seeds" in lines[0]
    assert not (tmp_path / "r").exists()


def test_reproduce_refuses_a_non_positive_duration_naming_duration(tmp_path: Path) -> None:
    code, out, err = run_main(["reproduce", "--out", str(tmp_path / "r"), "--duration", "0"])
    assert code == 2 and out == ""
    lines = error_lines(err)
    assert len(lines) == 1 and "--duration" in lines[0]
