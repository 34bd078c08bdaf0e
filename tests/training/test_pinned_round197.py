"""Values that round 197's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import contextlib
import json
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace

import pytest

from hg_marl.agents.model_format import read_header
from hg_marl.agents.models.forked import check_jobs
from hg_marl.agents.vector_envs import robot_vector_env
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.history import HistoryVectorEnv
from hg_marl.training.baselines.recipes import COVERAGE_CYCLES, CoveragePartner, recipe_partner
from hg_marl.training.store import Job, Store, StoredRun
from hg_marl.training.sweep import run_jobs
from tests.training.test_pinned_promises_c import JOB, Recording, _run_result


def test_a_refused_jobs_count_shows_the_value_as_given() -> None:
    # The message ends "got {jobs!r}": a count given as the text "3" is shown quoted, '3', so the
    # user sees it was a string, not the number 3.
    with pytest.raises(ValueError, match=r"got '3'$"):
        check_jobs("3")


def test_a_header_without_a_seat_is_refused(tmp_path: Path) -> None:
    # A header must say which seat it was trained in ("robot" or "human"); one with no "seat"
    # field at all is refused naming the field and what it got (nothing: None).
    header = {"format": "hg_marl.model", "kind": "table", "fact_names": [], "action_names": [], "file": "m.npz"}
    path = tmp_path / "m.json"
    path.write_text(json.dumps({**header, "seat": "robot"}))
    assert read_header(path)["seat"] == "robot"
    path.write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match=r"field 'seat': expected 'robot' or 'human', got None"):
        read_header(path)


def test_the_coverage_recipe_moves_tables_by_up_to_its_whole_cycle_count() -> None:
    # The module docstring: "after each reset a table is moved by 0 .. COVERAGE_CYCLES - 1 cycles",
    # COVERAGE_CYCLES being 24; the recipe's partner draws from all 24 counts, not from half of them.
    partner = recipe_partner(World("paper2015"), ("random",), "coverage", None)
    assert isinstance(partner, CoveragePartner)
    assert partner.cycles == COVERAGE_CYCLES == 24


def test_a_runs_key_holds_the_robots_own_parameters() -> None:
    # Two jobs that differ only by the robot's criterion are two runs: the key's robot entry holds
    # the robot's parameters as given (the human's, here none, do not stand in for them).
    vpi = Job(robot="hybrid", seed=0, robot_params={"criterion": "vpi"}, human_params={})
    habit = Job(robot="hybrid", seed=0, robot_params={"criterion": "habit"}, human_params={})
    assert vpi.key_fields()["robot"] == {"name": "hybrid", "params": {"criterion": "vpi"}}
    assert vpi.key() != habit.key()


class _ClaimWatching(Store):
    """A store that records, for each look at an entry, whether it repairs and whether the claim is held."""

    def __init__(self, root: Path) -> None:
        super().__init__(root)
        self.held: set[str] = set()
        self.looks: list[tuple[bool, bool]] = []

    @contextlib.contextmanager
    def claim(self, key: str) -> Iterator[bool]:
        with super().claim(key) as held:
            if held:
                self.held.add(key)
            try:
                yield held
            finally:
                self.held.discard(key)

    def get(self, job: Job, key: str | None = None, *, repair: bool = False) -> StoredRun | None:
        self.looks.append((repair, (key or job.key()) in self.held))
        return super().get(job, key, repair=repair)


def test_a_sweep_repairs_a_damaged_entry_only_under_its_claim(tmp_path: Path) -> None:
    # Without the claim "an incomplete entry may be one being written, and is only skipped": a
    # sweep first looks without repairing, then takes the claim and only then looks again to
    # repair (remove) the damaged entry and run the job. So every repairing look holds the claim.
    store = _ClaimWatching(tmp_path)
    key = store.put(JOB, _run_result()).key
    (store.entry(key) / "log.csv.gz").unlink()
    runs, stats = run_jobs([JOB], store, Recording(capacity=1))
    assert store.looks == [(False, False), (True, True)]
    assert stats.ran == 1 and runs[0].key == key


def test_the_robots_batched_seat_keeps_no_history_by_default() -> None:
    # history=0 by default: the plain table, whose observation is paper2015's fact vector of
    # 4 + 4 reach facts (3 tapes and the bin, each seat), 3 isIn, 1 human-robot reach,
    # 3 + 3 in hand and 3 + 3 offers = 24 facts, with no earlier actions appended.
    env = robot_vector_env(num_envs=1, partner=SimpleNamespace(name="stand-in"))
    assert not isinstance(env, HistoryVectorEnv)
    obs, _ = env.reset(seed=0)
    assert obs.shape == (1, 24)


def test_the_human_reaches_the_spots_on_its_side_wherever_the_robot_is() -> None:
    # paper2015's spots: mat_left, mat_centre, mat_right (the robot's, from table_left/right),
    # mat_shared (the human's, and the robot's from human_side), human_mat_1 and human_mat_2 (the
    # human's). The robot at bin_side (location 0) reaches none; the human reaches spots 3, 4, 5.
    world = World("paper2015")
    at_bin = State((0, 1, 4), 0)
    assert [world.spot_reachable(at_bin, Agent.HUMAN, s) for s in range(6)] == [False] * 3 + [True] * 3
    assert [world.spot_reachable(at_bin, Agent.ROBOT, s) for s in range(6)] == [False] * 6
    at_left = State((0, 1, 4), 1)
    assert [world.spot_reachable(at_left, Agent.ROBOT, s) for s in range(6)] == [True, True] + [False] * 4
