"""Values that round 191's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import LiveRobots
from hg_marl.agents.content import content_key, named_files
from hg_marl.agents.humans.population import load_population
from hg_marl.agents.robots.hybrid import HybridRobot
from hg_marl.core import Agent
from hg_marl.core.errors import PopulationError
from hg_marl.envs.array_partner import ResetsRows
from hg_marl.envs.batched import BatchedTable
from tests.agents.test_population import GOOD
from tests.training.test_pinned_round92 import WORLD, _turn


def test_a_file_given_as_a_path_in_the_fields_is_keyed_by_its_bytes(tmp_path: Path) -> None:
    # "every text in the settings is looked at": a Path is a path-like text (canonical writes it
    # as its str), so a file given as a Path object is keyed as the same file given as text: by
    # its text and the SHA-256 of its bytes, worked here with hashlib; editing it changes the key.
    path = tmp_path / "t.jsonl"
    path.write_bytes(b"abc")
    fields = {"trace": path}
    assert named_files(fields) == {str(path): {"t.jsonl": hashlib.sha256(b"abc").hexdigest()}}
    assert named_files(fields) == named_files({"trace": str(path)})
    before = content_key("test", fields, ())
    path.write_bytes(b"abcd")
    assert named_files(fields) == {str(path): {"t.jsonl": hashlib.sha256(b"abcd").hexdigest()}}
    assert content_key("test", fields, ()) != before


def test_a_member_name_of_exactly_32_characters_loads_and_33_are_refused(tmp_path: Path) -> None:
    # The documented bound: a short id of letters, digits, '_' or '-', 1-32 characters, both ends
    # inclusive. "m" + 31 digits is 32 characters and loads; one more character is refused.
    longest = "m" + "0" * 31
    assert len(longest) == 32
    path = tmp_path / "p.toml"
    path.write_text(GOOD.replace('name = "m00"', f'name = "{longest}"'))
    assert [m.name for m in load_population(path).train] == [longest]
    path.write_text(GOOD.replace('name = "m00"', f'name = "{longest}0"'))
    with pytest.raises(PopulationError, match=r"members\[0\]\.name"):
        load_population(path)


def test_a_frozen_hybrids_criterion_still_observes_each_reward() -> None:
    # learn=False freezes the habit, not the MetaController: the transition is still pending at
    # the second turn (LearningRobot._learn_from: "whether a transition was pending, whether or
    # not learning is on"), so the VPI criterion's running reward R moves by rate_step x (r - R).
    # From R = 0 with r = 1 and the default rate_step 0.02: R = 0.02, learning on or off.
    state = WORLD.initial_state(np.random.default_rng(0))
    for learn in (True, False):
        robot = HybridRobot(criterion="vpi", learn=learn)
        robot.reset(WORLD, Agent.ROBOT, np.random.default_rng(0))
        robot.act(_turn(state))
        assert robot.meta.criterion.reward_rate == 0.0
        robot.act(_turn(state, reward=1.0))
        assert robot.meta.criterion.reward_rate == 0.02


def test_live_robots_are_reset_with_their_tables() -> None:
    # LiveRobots keeps an actor per table and starts them afresh in reset_rows: it offers the
    # ResetsRows capability (the protocol asks for that method only), so a batched table's reset
    # resets every actor on the table's world (a Robot's reset sets its world; before it, None).
    live = LiveRobots(WORLD, "random", 3)
    assert all(actor.world is None for actor in live.actors)
    capabilities: object = live  # checked through another name: isinstance would narrow its type
    assert isinstance(capabilities, ResetsRows)
    env = BatchedTable(live, 3, WORLD, Agent.ROBOT, continuing=True, max_cycles=None)
    env.reset(seed=0)
    assert all(actor.world is WORLD for actor in live.actors)
