"""Round 35 of the fresh planted bugs: the values its missed bugs changed, pinned.

Each expected value is stated by hand, from the documented rule or from a simpler
reference (the runner itself, a freshly built environment), not computed with the code
under test.
"""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from hg_marl.core import Action, Agent, Kind, State, World

try:  # the sb3 extra, imported at collection: torch's import (about 2 s) is no single test's time
    import stable_baselines3  # noqa: F401

    HAS_SB3 = True
except ImportError:  # pragma: no cover (CI installs the extra)
    HAS_SB3 = False

needs_sb3 = pytest.mark.skipif(not HAS_SB3, reason="needs the sb3 extra")


def test_a_job_with_decision_time_uncharged_runs_uncharged() -> None:
    """``Job.charge_decision_time=False`` reaches the runner: the run is the runner's own uncharged run."""
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.robots import make_robot
    from hg_marl.training.backends import execute
    from hg_marl.training.runner import RunConfig, run
    from hg_marl.training.store import Job

    result = execute(Job(robot="habit", seed=0, duration=30.0, charge_decision_time=False))
    assert result.config.charge_decision_time is False
    reference = run(
        make_robot("habit"),
        make_human("cooperative"),
        RunConfig(scenario="paper2015", duration=30.0, seed=0, charge_decision_time=False),
    )
    np.testing.assert_array_equal(result.log["time"].to_numpy(), reference.log["time"].to_numpy())
    assert result.summary["simulated_time"] == reference.summary["simulated_time"]


@pytest.mark.sb3
@needs_sb3
def test_a_comparison_cell_with_another_episode_length_is_another_cell() -> None:
    """The module's promise, "a changed setting never reuses an old cell": ``max_cycles`` 100 and 200 give two keys."""
    from hg_marl.training.baselines.compare import cell_fields
    from hg_marl.training.baselines.comparison import CompareConfig
    from hg_marl.training.store import content_key

    short = cell_fields(CompareConfig(max_cycles=100), "ppo", "lazy", 0)
    long = cell_fields(CompareConfig(max_cycles=200), "ppo", "lazy", 0)
    assert content_key("compare_cell", short) != content_key("compare_cell", long)


def test_a_population_file_without_a_name_is_named_by_its_stem(tmp_path: Path) -> None:
    """No ``name`` field: the population is called after its file, without ``.toml`` (as a
    scenario file is named by its stem, docs/studies.md)."""
    from hg_marl.agents.humans.population import load_population

    path = tmp_path / "mixed.toml"
    path.write_text('[[members]]\nname = "m1"\nsplit = "train"\nspec = "lazy"\n', encoding="utf-8")
    assert load_population(path).name == "mixed"


def test_the_planner_share_of_the_last_third_counts_the_last_third_only() -> None:
    """Decisions at 0, 1, ..., 9 s: the last third starts at 6 s (2/3 of 9), four decisions,
    one of them the planner's (at 9 s): 0.25; the whole run: 7 of 10."""
    from hg_marl.training.paper import ConditionLogs, summarise_condition

    experts = ["planner"] * 6 + ["habit"] * 3 + ["planner"]
    log = pd.DataFrame(
        {
            "time": np.arange(10, dtype=float),
            "expert": experts,
            "reward": 0.0,
            "failed": False,
            "weight_amplitude": 0.0,
        }
    )
    row = summarise_condition(ConditionLogs("hybrid", [log]))
    assert row["planner_share_last_third"] == pytest.approx(0.25)
    assert row["planner_share"] == pytest.approx(0.7)


@pytest.mark.sb3
@needs_sb3
def test_the_sb3_vec_envs_seed_seeds_the_next_reset_only() -> None:
    """``seed(s)`` seeds the next reset; the reset after it goes on from that generator, as
    the batched env's own reset(seed=s) then reset() do (so it deals other tables)."""
    from hg_marl.wrappers.sb3 import batched_vec_env

    vec = batched_vec_env(4)
    vec.seed(3)
    first = vec.reset()
    second = vec.reset()
    reference = batched_vec_env(4).env
    reference_first, _ = reference.reset(seed=3)
    reference_second, _ = reference.reset()
    np.testing.assert_array_equal(first, reference_first)
    np.testing.assert_array_equal(second, reference_second)
    assert not np.array_equal(second, first)


def test_a_tidy_human_throws_what_it_holds_when_its_bin_is_in_reach_before_handing_over() -> None:
    """``tidy_action``: "throw it if its bin is within reach, else hand it over". On
    asymmetric_advantages the human holds tape4, reaches human_bin, and the robot stands at
    ``home`` (a handover place, give feasible): the lazy human (p_idle 0) throws it."""
    from hg_marl.agents.humans import make_human

    world = World("asymmetric_advantages")
    # spots robot_mat 0, middle_1 1, middle_2 2, human_mat 3; bins 4, 5; robot's hand 6, human's hand 7
    state = State(where=(0, 1, 2, 7), robot_at=0)
    assert world.feasible(state, Agent.HUMAN, Action(Kind.GIVE, 3))
    assert world.feasible(state, Agent.HUMAN, Action(Kind.THROW, 3))
    dist = make_human("lazy:p_idle=0").distribution(world, state)
    assert [(world.action_names[Agent.HUMAN][i], p) for i, p in dist] == [("throw(tape4)", 1.0)]


@pytest.mark.sb3
@needs_sb3
def test_an_off_policy_stop_winds_back_one_step_per_environment() -> None:
    """Off-policy, four environments: the interrupted step counted 4 transitions never stored,
    so 100 counted steps become 96."""
    from hg_marl.training.baselines.callbacks import StopOnSignal

    stop = StopOnSignal()
    model = SimpleNamespace(replay_buffer=object(), n_envs=4, num_timesteps=100)
    stop.model = model
    stop.request()  # what the signal handler calls
    assert stop.on_step() is False
    assert stop.stopped
    assert model.num_timesteps == 96


def test_a_scripted_seats_first_decision_after_a_reset_is_the_new_episodes() -> None:
    """``reset(seed=s)`` starts afresh: the lazy human (p_idle 0) first picks the tape on its
    own side of the new table (tape2 with seed 0, tape3 with seed 1), not the last episode's."""
    import hg_marl
    from hg_marl.agents.adapters import scripted_v0

    env = scripted_v0(hg_marl.env(), human="lazy:p_idle=0")
    world = env.unwrapped.world
    picked = []
    for seed in (0, 1):
        env.reset(seed=seed)
        where = env.unwrapped.world_state.where
        (mine,) = [o for o, place in enumerate(where) if world.scenario.spots[place].name.startswith("human_mat")]
        mask = env.observe("human")["action_mask"]
        assert mask.sum() == 1
        assert world.action_names[Agent.HUMAN][int(mask.argmax())] == f"pick({world.scenario.objects[mine]})"
        picked.append(world.scenario.objects[mine])
    assert picked == ["tape2", "tape3"]
