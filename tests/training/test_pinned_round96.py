"""Round 96's missed bugs, pinned after the round (``FRESH96`` in ``mutation/planted.py``).

- a replay reports the game's total reward (the sum over every cycle, which the recording's
  end line also states), not the reward of its last cycle only;
- ``greedy_play`` of the recurrent SB3 baseline reports tasks per *hour* of simulated play.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.trace import read_trace
from hg_marl.training.play.replay import replay_run, replay_trace
from hg_marl.training.play.session import PlaySession
from tests.play.reference import person_choice


def test_a_replay_reports_the_whole_games_reward_not_its_last_cycles(tmp_path: Path) -> None:
    # A cooperative person plays until a task is solved, then a few moves more, so the game's
    # reward was earned before its last cycle. The expected total is the session's own running
    # sum of the rewards, written in the trace's end line (the recording), not the replay's.
    session = PlaySession("planner", seed=0, record=tmp_path, player="tester")
    for _ in range(200):
        if session.tasks_solved >= 1:
            break
        session.play(person_choice([c.name for c in session.choices()]))
    assert session.tasks_solved >= 1, "the control: the scripted game solves a task"
    for _ in range(3):
        session.play(person_choice([c.name for c in session.choices()]))
    trace = session.close()
    assert trace is not None
    (episode,) = read_trace(trace)
    total = float(episode.end["rewards"])
    assert total > 0, "the control: the game earned some reward"
    last = float(replay_run(trace).log["reward"].iloc[-1])
    assert last != pytest.approx(total), "the control: the last cycle alone did not earn the total"
    result = replay_trace(trace)
    assert result.rewards == pytest.approx(total)


class _RandomFeasible:
    """A stand-in model: a seeded uniform draw among each table's feasible actions (the env's masks)."""

    def __init__(self) -> None:
        self.env: Any = None
        self.rng = np.random.default_rng(0)

    def predict(self, obs: Any, state: Any = None, episode_start: Any = None, deterministic: bool = True) -> Any:
        masks = np.asarray(self.env.action_masks())
        return np.array([self.rng.choice(np.flatnonzero(row)) for row in masks], dtype=np.int64), state


def test_greedy_play_reports_tasks_per_hour_of_simulated_play(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The expected rate is worked from the steps themselves: the tasks solved (rewards summed
    # over every table and step) over the simulated seconds every table played, times 3600.
    pytest.importorskip("stable_baselines3")
    from hg_marl.training.baselines import recurrent_ppo_sb3
    from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config, greedy_play

    config = RecurrentSb3Config(
        humans=("cooperative",), scenario="forced_coordination", history=0, episode_seconds=600.0, out=tmp_path
    ).check()
    model = _RandomFeasible()
    totals = {"tasks": 0.0, "seconds": 0.0}
    make = recurrent_ppo_sb3.make_vec

    def spying(config: RecurrentSb3Config, num_envs: int) -> Any:
        venv = make(config, num_envs)
        env, step = venv.env, venv.env.step
        model.env = env

        def counted(action: Any) -> Any:
            before = env.clock.copy()
            out = step(action)
            totals["tasks"] += float(np.sum(out[1]))
            totals["seconds"] += float(np.sum(out[4]["clock"] - before))
            return out

        env.step = counted
        return venv

    monkeypatch.setattr(recurrent_ppo_sb3, "make_vec", spying)
    play = greedy_play(model, config, num_envs=2, seconds=120.0, seed=0)
    assert totals["tasks"] > 0, "the control: the stand-in policy solves tasks"
    assert play.tasks_per_hour == pytest.approx(totals["tasks"] / totals["seconds"] * 3600.0)
    assert play.infeasible == 0.0
