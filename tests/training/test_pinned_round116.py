"""Values that round 116's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
import io
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

import hg_marl
from hg_marl.agents.adapters import ScriptedSeatWrapper
from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.fixed import PlannerOnly
from hg_marl.agents.model_format import read_arrays, write_arrays
from hg_marl.agents.model_limits import SB3_SLACK_BYTES, sb3_budget
from hg_marl.agents.models import budget as budget_module
from hg_marl.agents.robots import make_robot
from hg_marl.agents.robots.uniform import RandomRobot
from hg_marl.agents.vector_envs import human_vector_env
from hg_marl.core import Agent, World
from hg_marl.core.relabel import Relabel
from hg_marl.core.types import Action, Kind, State
from hg_marl.training.baselines.evaluation import actor_rate
from hg_marl.training.sweep import run_sweep
from tests.training.test_pinned_baselines_evaluation_gate import _tasks
from tests.training.test_pinned_round44 import _Waiter
from tests.training.test_pinned_sweep_gate import JOBS


def test_the_planner_criterion_plays_the_planner_also_when_the_habit_proposes_the_same_action() -> None:
    # "Always the planner": the expert is the planner whatever the habit proposes, so the
    # planner-only condition's planner share is 100 %, also where both propose action 1.
    habit = HabitView(b"s", np.array([0.1, 0.9]), 1, np.zeros(2), np.zeros(2), 0.0, 0.0)
    plan = PlanProposal.make(1, 2, 0.0)
    assert plan.action == habit.action
    assert PlannerOnly().choose(habit, plan) is Expert.PLANNER


def test_private_bytes_count_the_clean_and_the_dirty_private_pages(monkeypatch: pytest.MonkeyPatch) -> None:
    # A hand-made smaps_rollup: 300 kB clean and 200 kB dirty private pages, 1000 kB shared.
    # The process maps alone 300 + 200 = 500 kB = 512,000 bytes; the shared pages are not its own.
    rollup = (
        "00400000-7fff00000000 ---p 00000000 00:00 0 [rollup]\n"
        "Rss:                1500 kB\n"
        "Shared_Clean:       1000 kB\n"
        "Shared_Dirty:          0 kB\n"
        "Private_Clean:       300 kB\n"
        "Private_Dirty:       200 kB\n"
    )
    asked: list[str] = []

    def fake_open(path: str, *args: Any, **kwargs: Any) -> io.StringIO:
        asked.append(path)
        return io.StringIO(rollup)

    monkeypatch.setattr(budget_module, "open", fake_open, raising=False)
    assert budget_module.private_bytes(4321) == 500 * 1024 == 512_000
    assert asked == ["/proc/4321/smaps_rollup"]


def test_a_boolean_array_is_written_and_read_back_as_weights(tmp_path: Path) -> None:
    # Booleans are numbers to the format (kind "b", as the npy headers are checked on reading):
    # a mask is written, hashed and read back as it was.
    path = tmp_path / "mask.npz"
    mask = np.array([[True, False, True], [False, False, True]])
    sha = write_arrays(path, {"mask": mask, "w": np.arange(3.0)})
    assert sha == hashlib.sha256(path.read_bytes()).hexdigest()
    back = read_arrays(path, sha)
    assert back["mask"].dtype == np.bool_
    np.testing.assert_array_equal(back["mask"], mask)


def test_an_sb3_header_setting_ortho_init_is_held_to_its_networks_budget() -> None:
    # Box(4,) in, Discrete(3) out, net_arch [8]: each of the policy, value and Q networks has
    # (4 + 1) x 8 + (8 + 1) x 3 = 40 + 27 = 67 weights; 3 x 67 = 201, x 8 bytes x 3 (Adam)
    # x 2 (targets) = 9,648 bytes, plus the slack. ortho_init changes no shape, so it changes nothing.
    header: dict[str, Any] = {
        "algo": "PPO",
        "observation_space": {"type": "Box", "shape": [4]},
        "action_space": {"type": "Discrete", "n": 3},
        "policy_kwargs": {"net_arch": [8], "ortho_init": False},
    }
    assert SB3_SLACK_BYTES == 1 << 20
    assert sb3_budget(header) == 9_648 + 1_048_576
    header["policy_kwargs"] = {"net_arch": [8], "ortho_init": True, "activation_fn": "relu"}
    assert sb3_budget(header) == 9_648 + 1_048_576


def test_a_goto_to_the_last_object_is_mapped_back_to_the_object_it_stands_for() -> None:
    # paper2015's three tapes are interchangeable; tape1 at place 0, tape2 at 4, tape3 at 2.
    # Sorted by place, the canonical objects are tape1 (0), tape3 (2), tape2 (4): orig = (0, 2, 1),
    # so the canonical goto(object 2), the last object, is the original goto(tape2) (object 1).
    world = World("paper2015")
    relabel = Relabel(world)
    canonical, orig = relabel.canonical(State((0, 4, 2), 0))
    assert orig == (0, 2, 1)
    assert canonical.where == (0, 2, 4)
    goto = world.index(Agent.ROBOT, Action(Kind.GOTO, -1, 2))
    back = relabel.action_back(Agent.ROBOT, goto, orig)
    assert world.action_names[Agent.ROBOT][back] == "goto(tape2)"
    assert back == world.index(Agent.ROBOT, Action(Kind.GOTO, -1, 1))


def test_run_sweeps_on_done_hears_each_jobs_summary(tmp_path: Path) -> None:
    # on_done "is called with each job and its summary": the runner's summary fields
    # (runner.summarise), the same numbers the sweep returns, and not the job's description.
    fields = {
        "tasks_solved",
        "actions",
        "failed_actions",
        "simulated_time",
        "duration",
        "planner_share",
        "final_weight_amplitude",
        "human_as_expected",
    }
    heard: list[tuple[int, dict[str, Any]]] = []
    results = run_sweep(JOBS, tmp_path, on_done=lambda job, summary: heard.append((job.seed, summary)))
    assert sorted(seed for seed, _ in heard) == [0, 1, 2]
    for seed, summary in heard:
        assert set(summary) == fields
        assert summary["duration"] == 40.0
        assert summary == {k: v for k, v in results[seed].items() if k not in ("job", "key")}


@pytest.mark.parametrize(
    ("mode", "want"), [("same_step", AutoresetMode.SAME_STEP), ("next_step", AutoresetMode.NEXT_STEP)]
)
def test_the_human_seat_runs_in_the_autoreset_mode_it_is_given(mode: str, want: AutoresetMode) -> None:
    # A robot instance is live (nothing compiled); the mode is Gymnasium's, stated in the metadata.
    env = human_vector_env(num_envs=2, robot=_Waiter(), autoreset_mode=mode, cache=False)
    assert env.autoreset_mode is want
    assert env.metadata["autoreset_mode"] is want


def test_an_unknown_scripted_seat_is_named_alone_in_the_refusal() -> None:
    # "bob" is not an agent; "robot" is: the refusal names the one that is wrong.
    env = hg_marl.env()
    with pytest.raises(ValueError) as info:
        ScriptedSeatWrapper(env, {"robot": RandomRobot(), "bob": RandomRobot()})
    assert str(info.value) == "scripted seats ['bob'] are not agents of this env ['robot', 'human']"


def test_actor_rate_is_the_mean_over_three_seeds_not_their_median() -> None:
    # Random robots with the cooperative human for 700 s on seeds 0, 1, 2: the seeds' tasks
    # differ unevenly (their mean is not their median), and the rate is their mean x 36 / 7.
    tasks = [_tasks(make_robot("random"), "cooperative", "paper2015", 700.0, seed) for seed in (0, 1, 2)]
    assert sum(tasks) != 3 * sorted(tasks)[1]  # else a median would pass as the mean
    rate = actor_rate(lambda: make_robot("random"), "cooperative", "paper2015", 700.0, [0, 1, 2])
    assert rate == pytest.approx(sum(tasks) / 3 * 36 / 7)
