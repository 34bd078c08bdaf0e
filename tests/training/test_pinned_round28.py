"""The values round 28's missed planted bugs changed, pinned after the round.

Round 28 planted 14 bugs in fourteen gated modules of the early fresh rounds, written
blind; 8 were caught. Each value below is stated from the rule the module documents, not
read from the code under test:

- a batched table calls a partner's ``follow`` (the :class:`FollowsClock` capability)
  before each of its moves, so a schedule of humans plays, on each table, the member of
  ``bisect_right(at, clock)``: the first member while the clock is below the switch time,
  the second from it on;
- a habit's discount may be 1 (undiscounted): ``0 <= gamma <= 1``, and the update's
  target is then ``r + max Q(s')`` (worked by hand on a tabular habit);
- a ``memory`` file's observation size is its facts plus the history features of its
  own ``history_cap`` (``hg_marl.envs.history.history_size(k, cap)``), not the default cap's;
- a decision made because the habit is untrained records the habit's visits here, not
  the criterion's ``min_visits``;
- a model file with any NaN or infinite weight is refused, naming the array;
- an oracle entry that cannot be written (a full disk, a folder under a file) is skipped:
  a cache is an optimisation, nothing is raised and nothing is left behind.
"""

from __future__ import annotations

import errno
import json
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import CompiledSchedule
from hg_marl.agents.habit import QLearner, QLearnerConfig
from hg_marl.agents.memory_numpy import NumpyMemoryPolicy, check_memory_file
from hg_marl.agents.memory_policy import MemoryNet, save_memory
from hg_marl.agents.meta.base import Expert, HabitView, PlanProposal
from hg_marl.agents.meta.controller import MetaController
from hg_marl.agents.model_file import load_model_file, save_model_file, world_fields
from hg_marl.agents.models.cache import save_entry
from hg_marl.core import Agent, World
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.array_partner import FollowsClock
from hg_marl.envs.batched import BatchedTable
from hg_marl.envs.history import history_size

# --- hg_marl/envs/array_partner.py ---


class _Waiter:
    """A schedule member that always waits and counts the tables it answered."""

    def __init__(self, name: str, wait: int) -> None:
        self.name, self.wait, self.answered = name, wait, 0

    def act(self, batch: object, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        self.answered += len(seen)
        return np.full(len(seen), self.wait, dtype=np.int64)


def test_a_schedule_of_humans_follows_each_tables_clock() -> None:
    world = World("paper2015")
    wait_h, wait_r = world.table.wait[Agent.HUMAN], world.table.wait[Agent.ROBOT]
    first, second = _Waiter("first", wait_h), _Waiter("second", wait_h)
    schedule = CompiledSchedule([first, second], [0, 1], [5.0], "time")
    assert isinstance(schedule, FollowsClock)
    env = BatchedTable(schedule, 2, world, Agent.ROBOT, continuing=True, max_cycles=None)
    env.reset(seed=0)
    phases = []
    for _ in range(10):
        clock = env.clock.copy()
        before = (first.answered, second.answered)
        env.step(np.full(2, wait_r))
        expected = (0, 2) if clock[0] >= 5.0 else (2, 0)  # bisect_right([5.0], clock): the second member from 5 s
        assert (first.answered - before[0], second.answered - before[1]) == expected, clock
        phases.append(expected)
    assert (2, 0) in phases and (0, 2) in phases  # the clock crossed the switch


# --- agents/habit.py ---


def test_an_undiscounted_habit_is_accepted_and_bootstraps_in_full() -> None:
    assert QLearnerConfig(gamma=1.0).gamma == 1.0
    with pytest.raises(ValueError, match="gamma"):
        QLearnerConfig(gamma=1.0 + 1e-9)
    habit = QLearner(2, 3, QLearnerConfig(alpha=1.0, gamma=1.0, features="tabular"))
    s1, s2 = np.array([1, 0], dtype=np.int8), np.array([0, 1], dtype=np.int8)
    habit.update(s2, 0, 1.0, s2, done=True)  # Q(s2, 0) = 1
    habit.update(s1, 1, 0.5, s2)  # target 0.5 + 1 * max Q(s2) = 1.5, alpha 1: Q(s1, 1) = 1.5
    assert habit.q_values(s1).tolist() == [0.0, 1.5, 0.0]


# --- agents/memory_numpy.py ---


def test_a_memory_file_with_its_own_history_cap_loads(tmp_path: Path) -> None:
    world = World("paper2015")
    obs_size = world.n_facts + history_size(2, 4)  # facts, then the history features of cap 4
    assert obs_size != world.n_facts + history_size(2)  # the default cap (8) gives another width
    net = MemoryNet(obs_size, world.n_actions(Agent.ROBOT), 6, recurrent=True)
    path = save_memory(net, tmp_path / "model.json", world_fields(world, Agent.ROBOT), history=2, cap=4)
    mf = load_model_file(path, seat="robot")
    shape = check_memory_file(mf)
    assert (shape.obs_size, shape.history, shape.cap) == (obs_size, 2, 4)
    logits, h = NumpyMemoryPolicy(mf).step(np.zeros((1, obs_size)), np.zeros((1, 6)))
    assert logits.shape == (1, world.n_actions(Agent.ROBOT)) and h.shape == (1, 6)
    # the same header claiming the default cap no longer matches its observation size
    header = json.loads(path.read_text())
    header["history_cap"] = 8
    path.write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match="obs_size"):
        check_memory_file(load_model_file(path, seat="robot"))


# --- agents/meta/controller.py ---


def _view(visits: int) -> HabitView:
    n = 4
    return HabitView(b"s", np.full(n, 1 / n), 2, np.zeros(n), np.ones(n), 0.0, 0.001, visits=visits)


@pytest.mark.parametrize("visits", [0, 1, 2])
def test_an_untrained_decision_records_the_habits_own_visits(visits: int) -> None:
    mc = MetaController("entropy", min_visits=3)
    mc.reset(np.random.default_rng(0))
    decision = mc.decide(_view(visits), PlanProposal.make(1, 4, 0.01))
    assert decision.expert is Expert.PLANNER and decision.reason == "habit_untrained"
    assert decision.stats["visits"] == float(visits)
    assert decision.record["visits"] == float(visits)


# --- agents/model_format.py ---


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_one_non_finite_weight_refuses_the_file(tmp_path: Path, bad: float) -> None:
    world = World("paper2015")
    n_a, n_f = world.n_actions(Agent.HUMAN), world.n_facts
    header = {**world_fields(world, Agent.HUMAN), "kind": "linear_softmax", "temperature": 1.0}
    w = np.zeros((n_a, n_f))
    w[1, 2] = bad  # one value of many
    save_model_file(tmp_path / "policy.json", header, {"W": w, "b": np.zeros(n_a)})
    with pytest.raises(ModelFileError, match="array 'W' holds NaN or infinity"):
        load_model_file(tmp_path / "policy.json")
    save_model_file(tmp_path / "policy.json", header, {"W": np.zeros((n_a, n_f)), "b": np.zeros(n_a)})
    assert load_model_file(tmp_path / "policy.json").arrays["W"].shape == (n_a, n_f)


# --- agents/models/cache.py ---


def test_an_entry_under_a_file_is_skipped(tmp_path: Path) -> None:
    (tmp_path / "file").write_text("")
    save_entry(tmp_path / "file" / "oracle" / "entry.npz", "k", {"v": np.zeros(2)})  # ENOTDIR: skipped
    assert [p.name for p in tmp_path.iterdir()] == ["file"]


def test_an_entry_on_a_full_disk_is_skipped(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def full(self: Path, data: bytes) -> int:
        raise OSError(errno.ENOSPC, "No space left on device", str(self))

    monkeypatch.setattr(Path, "write_bytes", full)
    save_entry(tmp_path / "oracle" / "entry.npz", "k", {"v": np.zeros(2)})
    assert list((tmp_path / "oracle").iterdir()) == []  # the temporary file removed, no entry
