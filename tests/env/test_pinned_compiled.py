"""What the compiled partners' cache keys cover, how the disk cache is used, and the packed keys.

A compiled table is reused only when everything that made it is unchanged: the scenario,
the durations, the partner's spec (and the files a ``path=`` names), a switching
closure, the stall rule's ``K`` for the robot, and the code of every module that can
change an answer. The code part is checked on a copy of the sources
(``tests/source_copy.py``), so one file at a time can be edited.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents import compiled, compiled_robot
from hg_marl.agents.compiled import Packer, cache_key, compile_human
from hg_marl.agents.compiled_robot import CompiledRobot, compile_robot, robot_cache_key
from hg_marl.agents.humans.learned import save_learned_policy
from hg_marl.core import Agent, World
from hg_marl.envs.batched import BatchState
from tests.source_copy import copy_sources, edit_code, edit_docs, write

COVERED = [
    "hg_marl/core/world.py",
    "agents/planner/costs.py",
    "agents/compiled.py",
    "agents/models/builder.py",
    "agents/content.py",
]
"""One file of each source both tables are keyed by (the import walk reaches them from both)."""
HUMAN_OWN = ["agents/humans/lazy.py", "agents/humans/cooperative.py"]
"""Sources of the human tables alone: the robot's table (the planner's proposals) never runs a human."""
ROBOT_OWN = ["agents/compiled_robot.py", "agents/robots/planner.py", "agents/robots/base.py", "agents/partner.py"]
"""The robot table's own sources (beside the human tables' ones)."""


@pytest.fixture(scope="module")
def world() -> World:
    return World("paper2015")


@pytest.fixture()
def sources(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A copy of the sources; the content keys read the code from it."""
    root = copy_sources(tmp_path / "src", monkeypatch)
    (root / "agents/unrelated.py").write_text("x = 1\n")
    return root


@pytest.mark.parametrize("rel", COVERED)
def test_an_edited_source_changes_both_keys(sources: Path, world: World, rel: str) -> None:
    human, robot = cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)
    edit_code(sources / rel)
    assert cache_key(world, "lazy") != human
    assert robot_cache_key(world, "planner", 4) != robot


@pytest.mark.parametrize("rel", ROBOT_OWN[1:])
def test_the_robots_own_sources_change_its_key_only(sources: Path, world: World, rel: str) -> None:
    human, robot = cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)
    edit_code(sources / rel)
    assert robot_cache_key(world, "planner", 4) != robot
    assert cache_key(world, "lazy") == human  # a planner robot's source cannot change a human's answers


@pytest.mark.parametrize("rel", HUMAN_OWN)
def test_the_humans_sources_change_their_key_only(sources: Path, world: World, rel: str) -> None:
    human, robot = cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)
    edit_code(sources / rel)
    assert cache_key(world, "lazy") != human
    assert robot_cache_key(world, "planner", 4) == robot


def test_a_file_outside_the_sources_changes_no_key(sources: Path, world: World) -> None:
    human, robot = cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)
    edit_code(sources / "agents/unrelated.py")
    assert (cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)) == (human, robot)


def test_a_comment_changes_no_key_and_a_new_import_brings_its_module_in(sources: Path, world: World) -> None:
    human, robot = cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)
    edit_docs(sources / "agents/compiled.py")
    assert (cache_key(world, "lazy"), robot_cache_key(world, "planner", 4)) == (human, robot)
    lazy = sources / "agents/humans/lazy.py"
    write(lazy, lazy.read_text() + "\nfrom hg_marl.agents import unrelated  # noqa\n")
    imported = cache_key(world, "lazy")
    assert imported != human
    edit_code(sources / "agents/unrelated.py")  # now reached from a keyed module
    assert cache_key(world, "lazy") != imported


def test_keys_cover_scenario_durations_spec_and_closure(world: World) -> None:
    base = cache_key(world, "lazy")
    assert cache_key(world, "lazy") == base  # a pure function of its inputs
    slower = World("paper2015", durations=replace(world.durations, wait=2.0))
    others = {
        "scenario": cache_key(World("generated:objects=2,seed=4"), "lazy"),
        "durations": cache_key(slower, "lazy"),
        "spec": cache_key(world, "lazy:p_idle=0.5"),
        "closure": cache_key(world, "lazy", ("cooperative",)),
        "another closure": cache_key(world, "lazy", ("noisy",)),
    }
    assert len({base, *others.values()}) == 6, others


def test_robot_keys_cover_scenario_durations_spec_and_the_stall_rule(world: World) -> None:
    base = robot_cache_key(world, "planner", 4)
    slower = World("paper2015", durations=replace(world.durations, goto=4.0))
    others = [
        robot_cache_key(World("generated:objects=2,seed=4"), "planner", 4),
        robot_cache_key(slower, "planner", 4),
        robot_cache_key(world, "planner:x=1", 4),
        robot_cache_key(world, "planner", 5),
    ]
    assert len({base, *others}) == 5 and robot_cache_key(world, "planner", 4) == base


def test_the_files_a_path_names_are_keyed(world: World, tmp_path: Path) -> None:
    """What the loader reads (the header and the weights it names) is keyed; another file is not."""
    weights = np.zeros((world.n_actions(Agent.HUMAN), world.n_facts))
    folder = save_learned_policy(tmp_path / "policy", world, weights=weights)
    spec = f"learned:path={folder}"
    first = cache_key(world, spec)
    (folder / "notes.txt").write_text("read by nobody")
    assert cache_key(world, spec) == first
    npz = folder / "policy.npz"
    npz.write_bytes(npz.read_bytes() + b"\0")  # the weights file the header names
    second = cache_key(world, spec)
    header = folder / "policy.json"
    header.write_text(header.read_text() + " ")
    third = cache_key(world, spec)
    assert len({first, second, third}) == 3
    # a closure member naming a file is keyed by its content too
    closure_key = cache_key(world, "lazy", (spec,))
    npz.write_bytes(npz.read_bytes() + b"\0")
    assert cache_key(world, "lazy", (spec,)) != closure_key


def test_human_disk_cache_file_name_reuse_and_rebuild(
    world: World, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    first = compile_human(world, "lazy", cache=tmp_path)
    key = cache_key(world, "lazy")
    path = tmp_path / f"paper2015-{key[:24]}.npz"
    assert [p.name for p in tmp_path.iterdir()] == [path.name]

    def no_build(*args: object, **kwargs: object) -> None:
        raise AssertionError("built again")

    with monkeypatch.context() as m:  # a matching entry is loaded, never rebuilt
        m.setattr(compiled, "answer_table", no_build)
        loaded = compile_human(world, "lazy", cache=str(tmp_path))
        assert (loaded.keys == first.keys).all() and (loaded.actions == first.actions).all()
    compiled.save_table(path, "0" * 64, {"keys": np.zeros(1, dtype=np.int64)})  # a foreign entry at the path
    rebuilt = compile_human(world, "lazy", cache=tmp_path)
    assert (rebuilt.keys == first.keys).all()
    with np.load(path) as data:
        assert str(data["key"]) == key  # overwritten with the right entry
    path.write_bytes(b"not a zip")  # a corrupt entry is rebuilt too
    assert len(compile_human(world, "lazy", cache=tmp_path)) == len(first)


def test_no_disk_cache_unless_a_folder_is_named(world: World, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    for cache in (None, False, True):
        compile_human(world, "lazy", cache=cache)
    compile_human(world, compiled.make_human("lazy"), cache=tmp_path / "named")  # an instance: no content key
    assert list(tmp_path.iterdir()) == []
    monkeypatch.setenv("HG_MARL_CACHE", str(tmp_path / "root"))
    compile_human(world, "lazy", cache=True)
    assert [p.parent for p in (tmp_path / "root").rglob("*.npz")] == [tmp_path / "root" / "partners"]


def test_robot_disk_cache_file_name_reuse_and_rebuild(
    world: World, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    small = World("generated:objects=2,seed=4,human_only=0.8")
    first = compile_robot(small, cache=tmp_path, stall_after=3)
    key = robot_cache_key(small, "planner", 3)
    path = tmp_path / f"generated-robot-{key[:24]}.npz"
    assert [p.name for p in tmp_path.iterdir()] == [path.name]
    with monkeypatch.context() as m:
        m.setattr(compiled_robot, "enumerate_plans", lambda *a, **k: (_ for _ in ()).throw(AssertionError("built")))
        loaded = compile_robot(small, cache=tmp_path, stall_after=3)
        assert (loaded.keys == first.keys).all() and loaded.stall_after == 3
    compiled.save_table(path, "0" * 64, {"keys": np.zeros(1, dtype=np.int64), "actions": np.zeros(1, dtype=np.int64)})
    assert (compile_robot(small, cache=tmp_path, stall_after=3).keys == first.keys).all()
    monkeypatch.delenv("HG_MARL_CACHE", raising=False)
    monkeypatch.chdir(tmp_path)
    compile_robot(small, cache=True)
    compile_robot(small, cache=None)
    assert sorted(p.name for p in tmp_path.iterdir()) == [path.name]


def _reference_key(radix: list[int], digits: list[int]) -> int:
    """Mixed radix: digit i weighs the product of the radices before it."""
    key, weight = 0, 1
    for r, d in zip(radix, digits, strict=True):
        assert 0 <= d < r
        key += d * weight
        weight *= r
    return key


def test_packed_keys_are_the_mixed_radix_number_of_the_state(world: World) -> None:
    packer = Packer(world)
    rng = np.random.default_rng(0)
    layouts = [world.initial_state(np.random.default_rng(s)) for s in range(32)]
    b = BatchState.of(layouts)
    seen = rng.integers(-1, world.n_actions(Agent.ROBOT), size=len(layouts))
    keys = packer.pack(b, seen)
    for i, s in enumerate(layouts):
        digits = [*s.where, s.robot_at, s.offer_by + 1, s.offer_obj + 1, int(seen[i]) + 1]
        assert int(keys[i]) == packer.pack_one(s, int(seen[i])) == _reference_key(packer.radix, digits)


def test_an_offer_is_part_of_the_key(world: World) -> None:
    packer = Packer(world)
    s = world.initial_state(np.random.default_rng(0))
    offered = s._replace(offer_by=0, offer_obj=1)
    keys = {packer.pack_one(x, seen) for x in (s, offered) for seen in (-1, 0, 5)}
    assert len(keys) == 6


def test_every_compiled_robot_state_is_found_in_its_table() -> None:
    small = World("generated:objects=2,seed=4,human_only=0.8")
    robot = compile_robot(small, cache=None)
    plans = compiled_robot.enumerate_plans(small)
    states = sorted(plans)
    actions, found = robot.plan(BatchState.of(states))
    assert found.all() and robot.fallbacks == 0
    assert actions.tolist() == [plans[s] for s in states]
    empty = CompiledRobot(small, {"keys": np.zeros(0, dtype=np.int64), "actions": np.zeros(0, dtype=np.int64)})
    actions, found = empty.plan(BatchState.of(states[:3]))
    assert not found.any() and empty.fallbacks == 3 and actions.tolist() == [plans[s] for s in states[:3]]


class _Recording:
    """A stationary human (the registry's ``lazy``) that records the robot action it is asked about."""

    uses_robot_action = False
    name = "recording"

    def __init__(self) -> None:
        self.inner = compiled.make_human("lazy")
        self.asked: list[int] = []

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        self.inner.reset(world, agent, rng)

    def distribution(self, world: World, state: object, robot_action: int = -1) -> list[tuple[int, float]]:
        self.asked.append(robot_action)
        return list(self.inner.distribution(world, state, robot_action))


def test_the_live_fallback_asks_the_question_the_table_was_compiled_with(world: World) -> None:
    """A human that ignores the robot's action is compiled with -1 as its key: the fallback asks with -1 too."""
    human = _Recording()
    table = compile_human(world, human, cache=None)
    assert set(human.asked) == {-1}
    human.asked.clear()
    batch = BatchState.of([world.initial_state(np.random.default_rng(s)) for s in range(3)])
    batch.offer_by[:], batch.offer_obj[:] = 1, 0  # the human's own offer to the robot: outside the table
    table.act(batch, np.array([3, 5, 7]), np.random.default_rng(0))
    assert table.fallbacks == 3 and human.asked == [-1, -1, -1]
