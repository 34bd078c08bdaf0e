"""The belief robot's members' models: solved when first consulted, kept by content.

Counted, never timed: the oracle's model builder is wrapped with a counter, so "read
from the cache" is "no model was built" and "rebuilt" is "one model was built".
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import hg_marl.agents.oracle as oracle_module
from hg_marl.agents import member_models
from hg_marl.agents.humans import make_human
from hg_marl.agents.member_models import MemberModels, clear_memo
from hg_marl.agents.oracle import oracle_rate
from hg_marl.agents.robots.belief import BeliefRobot
from hg_marl.core import World
from hg_marl.core.errors import RobotError
from hg_marl.training.runner import RunConfig, run

SCENARIOS = Path(__file__).resolve().parents[2] / "hg_marl" / "core" / "scenarios"
COOP = "preference"
MAT = "preference:handover=-1.0,shared=1.0"
IDLE = "preference:p_idle=0.5"


@pytest.fixture
def builds(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[int]]:
    """Counts the oracle's model builds (one per member solved from scratch); a fresh process memo."""
    clear_memo()
    count: list[int] = []
    real = oracle_module.build_model

    def counted(*args: object, **kwargs: object) -> object:
        count.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(oracle_module, "build_model", counted)
    yield count
    clear_memo()


def _population(tmp_path: Path, specs: tuple[str, ...]) -> str:
    text = 'name = "t"\nscenario = "paper2015"\n'
    for k, spec in enumerate(specs):
        text += f'\n[[members]]\nname = "m{k}"\nsplit = "train"\nspec = "{spec}"\n'
    path = tmp_path / "population.toml"
    path.write_text(text)
    return str(path)


def test_the_first_move_solves_only_the_member_it_consults(tmp_path: Path, builds: list[int]) -> None:
    # Three members, equal priors: "map" consults the first (np.argmax of a tie), so one build.
    robot = BeliefRobot(population=_population(tmp_path, (COOP, MAT, IDLE)), cache=str(tmp_path / "c"))
    run(robot, make_human("cooperative"), RunConfig(duration=60.0, seed=0, max_decisions=1))
    assert robot.members_built() == [0] and len(builds) == 1


def test_lazy_members_decide_as_members_solved_at_the_start(tmp_path: Path, builds: list[int]) -> None:
    # Solving on demand only moves wall-clock work: the run's log is the log of a robot
    # whose every member was solved before its first move.
    population = _population(tmp_path, (COOP, MAT, IDLE))

    def log(eager: bool) -> pd.DataFrame:
        robot = BeliefRobot(population=population)
        if eager:
            robot.members.reset(World("paper2015"))
            for m in range(3):
                robot.members.result(m)
        out = run(robot, make_human(MAT), RunConfig(duration=400.0, seed=2)).log
        return out.drop(columns=["planning_time", "decision_time"])

    pd.testing.assert_frame_equal(log(eager=False), log(eager=True))


def test_a_second_robot_reads_the_members_from_the_disk_cache(tmp_path: Path, builds: list[int]) -> None:
    cache = str(tmp_path / "cache")
    world = World("paper2015")
    first = MemberModels((COOP, MAT), cache)
    first.reset(world)
    rates = [first.result(m).rate_per_hour for m in range(2)]
    assert len(builds) == 2 and len(list(Path(cache).glob("*.npz"))) == 2
    clear_memo()  # a new process: only the disk is left
    second = MemberModels((COOP, MAT), cache)
    second.reset(world)
    assert [second.result(m).rate_per_hour for m in range(2)] == rates
    assert len(builds) == 2  # nothing built again
    # the cached values are the oracle's own (solved here without any cache)
    state = world.initial_state(np.random.default_rng(0))
    fresh = oracle_rate(world, MAT, cache=False)
    assert second.result(1).value_at(world, state) == fresh.value_at(world, state)


def test_a_named_cache_folder_is_created_and_tried_before_any_work(tmp_path: Path, builds: list[int]) -> None:
    # The folder a user names is an output: created with its missing parents (the user named
    # it), empty of the write probe, and nothing solved yet.
    folder = tmp_path / "a" / "b"
    BeliefRobot(population=_population(tmp_path, (COOP, MAT)), cache=str(folder))
    assert folder.is_dir() and list(folder.iterdir()) == [] and builds == []


@pytest.mark.parametrize(("where", "why"), [("file/sub", "Not a directory"), ("file", "File exists")])
def test_a_cache_folder_that_cannot_be_written_is_refused_in_one_line(tmp_path: Path, where: str, why: str) -> None:
    # A folder through a file (or the file itself) cannot hold the cache: refused when the
    # robot is built, naming the parameter and the system's reason (POSIX's ENOTDIR and
    # EEXIST texts), instead of every run solving its members again.
    (tmp_path / "file").write_text("x")
    folder = tmp_path / where
    with pytest.raises(RobotError) as refused:
        BeliefRobot(population=_population(tmp_path, (COOP,)), cache=str(folder))
    assert str(refused.value) == f"belief.cache {folder}: cannot write in it ({why})"
    assert (tmp_path / "file").read_text() == "x"


def test_the_process_memo_serves_a_second_robot_without_a_disk_cache(
    builds: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    world = World("paper2015")
    for _ in range(2):
        models = MemberModels((COOP,), "")
        assert models.cache is None  # nothing on disk
        models.reset(world)
        models.result(0)
    assert len(builds) == 1


def test_a_changed_member_rebuilds_that_member_only(tmp_path: Path, builds: list[int]) -> None:
    cache = str(tmp_path / "cache")
    world = World("paper2015")
    before = MemberModels((COOP, MAT), cache)
    before.reset(world)
    before.result(0), before.result(1)
    clear_memo()
    after = MemberModels((COOP, IDLE), cache)  # the second member's spec changed
    after.reset(world)
    after.result(0), after.result(1)
    assert len(builds) == 3  # two at first, then only the changed member


def test_a_changed_scenario_file_rebuilds(tmp_path: Path, builds: list[int]) -> None:
    cache = str(tmp_path / "cache")
    scenario = tmp_path / "table.toml"
    text = (SCENARIOS / "paper2015.toml").read_text()
    scenario.write_text(text)
    for _ in range(2):  # the same content twice: built once
        clear_memo()
        models = MemberModels((COOP,), cache)
        models.reset(World(str(scenario)))
        models.result(0)
    assert len(builds) == 1
    scenario.write_text(text.replace('robot_start = ["bin_side"]', 'robot_start = ["table_left"]'))
    clear_memo()
    models = MemberModels((COOP,), cache)
    models.reset(World(str(scenario)))
    models.result(0)
    assert len(builds) == 2


def test_a_robot_moved_to_another_world_drops_the_old_results(builds: list[int]) -> None:
    models = MemberModels((COOP,), "")
    models.reset(World("paper2015"))
    models.result(0)
    models.reset(World("paper2015"))
    assert models.built() == [0]  # same world: kept
    models.reset(World("forced_coordination"))
    assert models.built() == []
    assert models.result(0).scenario == "forced_coordination"


def test_the_memo_keeps_at_most_its_bound(builds: list[int], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    monkeypatch.setattr(member_models, "MEMO_ENTRIES", 2)
    world = World("paper2015")
    models = MemberModels((COOP, MAT, IDLE), "")
    models.reset(world)
    for m in range(3):
        models.result(m)
    assert len(member_models._MEMO) == 2
    again = MemberModels((COOP,), "")  # the oldest was dropped: solved again
    again.reset(world)
    again.result(0)
    assert len(builds) == 4


@pytest.mark.parametrize("spec", [MAT, IDLE])
def test_the_backup_satisfies_the_oracles_bellman_equation(spec: str) -> None:
    """At every state of a solved model, the best one-step backup is the state's value.

    The oracle's values are the expected seconds to the next success under the optimal
    policy, so ``V(s) = min_a sum p (tau + V(next))`` (Bellman's optimality equation, to the
    solver's tolerance), and the completing wait on a clean table costs nothing: a property
    of the values, not a re-computation of :func:`backup`. Solved without failed actions,
    so every action the policy takes is one :func:`backup` offers.
    """
    from hg_marl.agents.member_models import backup
    from hg_marl.agents.models.python_model import PythonModel
    from hg_marl.agents.planner.space import Relabel

    world = World("paper2015")
    result = oracle_rate(world, spec, failed_actions=False, cache=False, symmetry=False)
    model = PythonModel(world, make_human(spec), False, 1)
    relabel = Relabel(world)
    checked = 0
    for state in list(result.values)[:300]:
        value = result.value_at(world, state)
        if not np.isfinite(value):
            continue
        q = backup(world, state, result, model, relabel)
        assert min(q.values()) == pytest.approx(value, abs=1e-6)
        if world.is_clean(state):
            assert q[world.n_actions(0) - 1] == 0.0 and value == pytest.approx(0.0, abs=1e-9)
        checked += 1
    assert checked >= 100
