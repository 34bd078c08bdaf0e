"""History features: the AEC env, the robot's view and the batched table agree, and match a plain reference."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.views import RobotView, robot_vector_env
from hg_marl.core import Agent, Kind, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import BatchState
from hg_marl.envs.history import HistoryTracker, cycle_from_turn, history_names, history_size
from hg_marl.envs.table_cleaning import raw_env

K, CAP, CYCLES, TABLES = 3, 8, 40, 6


def reference(world: World, cycles: list[tuple[int, bool, int, bool]], observer: int) -> np.ndarray:
    """The features written out from the definition, one cycle list at a time (no arrays shared with the code)."""
    kinds = [[s.kind for s in world.table.specs[a]] for a in (0, 1)]
    out: list[int] = []
    partner = 1 - observer
    for who in (partner, observer):
        for j in range(K):
            one_hot = [0] * len(Kind)
            if j < len(cycles):
                c = cycles[-1 - j]
                one_hot[int(kinds[who][c[2 * who]])] = 1
            out += one_hot
        out += [int(j < len(cycles) and not cycles[-1 - j][2 * who + 1]) for j in range(K)]
    since = 0
    for c in cycles:
        moved = c[2 * partner + 1] and kinds[partner][c[2 * partner]] in (Kind.PICK, Kind.THROW, Kind.TAKE, Kind.PLACE)
        since = 0 if moved else min(since + 1, CAP)
    out += [int(since == v) for v in range(CAP + 1)]
    return np.array(out, dtype=np.int8)


class Script:
    """A human (an Actor and an ArrayPartner) that plays pre-drawn actions: ``plan[table][cycle]``."""

    name = "script"

    def __init__(self, plan: np.ndarray) -> None:
        self.plan, self.t, self.row = plan, np.zeros(len(plan), dtype=np.int64), 0

    def reset(self, world: Any, agent: Any, rng: Any) -> None:
        self.t[self.row] = 0

    def act(self, turn_or_batch: Any, seen: Any = None, rng: Any = None) -> Any:
        if isinstance(turn_or_batch, BatchState):
            rows = turn_or_batch.rows
            out = self.plan[rows, self.t[rows]]
            self.t[rows] += 1
            return out
        out = int(self.plan[self.row, self.t[self.row]])
        self.t[self.row] += 1
        return out


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination"])
@pytest.mark.parametrize("seed", [0, 1])
def test_features_equal_on_the_aec_env_the_view_and_the_batched_table(scenario: str, seed: int) -> None:
    """Random (often infeasible) actions for both seats: the three give the reference's features cycle by cycle."""
    world = World(scenario)
    rng = np.random.default_rng(seed)
    robot = rng.integers(world.n_actions(Agent.ROBOT), size=(TABLES, CYCLES))
    human = rng.integers(world.n_actions(Agent.HUMAN), size=(TABLES, CYCLES))
    starts = [world.initial_state(rng) for _ in range(TABLES)]
    n_f = world.n_facts
    batched = robot_vector_env(TABLES, scenario, partner=Script(human), continuing=True, max_cycles=None, history=K)
    obs, _ = batched.reset(seed=seed, options={"states": starts})
    compared = failed = moved = 0
    for i in range(TABLES):
        aec = raw_env(scenario=scenario, continuing=True, max_cycles=None, history=K)
        aec.reset(options={"state": starts[i]})
        script = Script(human)
        script.row = i
        view = RobotView(scenario, human=script, continuing=True, max_cycles=None, history=K)
        view_obs, _ = view.reset(options={"state": starts[i]})
        cycles: list[tuple[int, bool, int, bool]] = []
        for t in range(CYCLES):
            expect = reference(world, cycles, 0)
            assert np.array_equal(aec.observe("robot")["observation"][n_f:], expect)
            assert np.array_equal(aec.observe("human")["observation"][n_f:], reference(world, cycles, 1))
            assert np.array_equal(view_obs[n_f:], expect)
            aec.step(int(robot[i, t]))
            r_ok = not aec.infos["robot"]["failed"]
            reward = aec.rewards["robot"]
            aec.step(int(human[i, t]))
            h_ok = not aec.infos["human"]["failed"]
            turn = aec.turn("robot")
            assert cycle_from_turn(turn) == (int(robot[i, t]), r_ok, int(human[i, t]), h_ok)
            view_obs, *_ = view.step(int(robot[i, t]))
            cycles.append((int(robot[i, t]), r_ok, int(human[i, t]), h_ok))
            if reward or aec.rewards["robot"]:  # a success re-draws the table at random: stop comparing
                break
            compared += 1
            failed += not (r_ok and h_ok)
            moved += h_ok and world.table.specs[1][int(human[i, t])].kind in (Kind.PICK, Kind.THROW, Kind.TAKE)
    assert compared >= TABLES * CYCLES // 2
    assert failed and moved  # the sequences exercise both failure bits and the progress counter
    # the batched table on the same actions (every table at once), against the AEC env replayed per table
    envs = [raw_env(scenario=scenario, continuing=True, max_cycles=None, history=K) for _ in range(TABLES)]
    for i, e in enumerate(envs):
        e.reset(options={"state": starts[i]})
    live = np.ones(TABLES, dtype=bool)
    for t in range(CYCLES):
        for i, e in enumerate(envs):
            if live[i]:
                assert np.array_equal(obs[i], e.observe("robot")["observation"]), (i, t)
        obs, reward, *_ = batched.step(robot[:, t])
        for i, e in enumerate(envs):
            e.step(int(robot[i, t]))
            won = e.rewards["robot"]
            e.step(int(human[i, t]))
            live[i] &= not (won or e.rewards["robot"] or reward[i])


def test_history_zero_is_the_plain_observation_and_sizes_add_up() -> None:
    env = raw_env(scenario="paper2015")
    assert env.observe("robot")["observation"].shape == (World("paper2015").n_facts,)
    assert history_size(0) == 0 and history_names(0) == ()
    # k kinds one-hot and k failure bits per agent, then cap + 1 bins: 2*3*8 + 9 = 57
    assert history_size(3, 8) == 57 == len(history_names(3, 8))
    env = raw_env(scenario="paper2015", history=3)
    assert env.observe("robot")["observation"].shape == (World("paper2015").n_facts + 57,)


def test_progress_counter_counts_and_clips() -> None:
    """A partner that only waits: 0, 1, ..., cap, cap; one successful pick brings it back to 0."""
    world = World("paper2015")
    tr = HistoryTracker(world, 1, 1, cap=3)
    wait_h, wait_r = world.table.wait[1], world.table.wait[0]
    seen = []
    for _ in range(5):
        seen.append(int(tr.since[0, 1]))
        tr.record(np.array([wait_r]), np.array([True]), np.array([wait_h]), np.array([True]))
    seen.append(int(tr.since[0, 1]))
    assert seen == [0, 1, 2, 3, 3, 3]
    pick = world.table.action_index(Agent.HUMAN, Kind.PICK, 0, 0)
    tr.record(np.array([wait_r]), np.array([True]), np.array([pick]), np.array([False]))  # a failed pick: no progress
    assert tr.since[0, 1] == 3
    tr.record(np.array([wait_r]), np.array([True]), np.array([pick]), np.array([True]))
    assert tr.since[0, 1] == 0


@pytest.mark.parametrize("bad", [-1, 1.5, "3", 65])
def test_bad_history_is_one_error_naming_it(bad: object) -> None:
    with pytest.raises(ConfigError, match="history"):
        raw_env(scenario="paper2015", history=bad)  # type: ignore[arg-type]


def test_autoreset_forgets_the_history_of_the_new_episode() -> None:
    """Next-step autoreset: the step after a truncation returns the new episode's empty history."""
    env = robot_vector_env(4, "paper2015", human="cooperative", max_cycles=2, history=2)
    obs, _ = env.reset(seed=0)
    n_f = env.world.n_facts
    assert not obs[:, n_f:-9].any()
    wait = env.world.table.wait[0]
    acts = np.full(4, wait)
    obs, _, _, trunc, _ = env.step(acts)
    assert obs[:, n_f:-9].any(axis=1).all()  # a cycle happened: kinds recorded
    obs, _, _, trunc, _ = env.step(acts)
    assert trunc.all()
    obs, *_ = env.step(acts)  # the reset step
    assert not obs[:, n_f:-9].any() and obs[:, -9].all()  # empty history, 0 cycles since progress
