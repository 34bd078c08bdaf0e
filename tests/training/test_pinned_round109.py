"""Values that round 109's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

from gymnasium import spaces

from hg_marl.agents.model_sb3 import space_from_json
from hg_marl.core import Agent
from hg_marl.training.baselines.bc import behaviour_clone
from hg_marl.training.baselines.ppo_recurrent import config_from_options
from tests.training.test_pinned_baselines_bc_gate import _facts, _mask, _trace


def test_a_discrete_space_whose_header_names_no_start_starts_at_zero() -> None:
    # agents/model_sb3.py's space_from_json: "start" defaults to 0, as gymnasium's Discrete(n) does,
    # so a hand-written header {"type": "Discrete", "n": 5} is the actions 0..4 (start 0), not 1..5.
    space = space_from_json({"type": "Discrete", "n": 5}, "header")
    assert isinstance(space, spaces.Discrete)
    assert (int(space.n), int(space.start)) == (5, 0)
    assert space == spaces.Discrete(5)
    assert space.contains(0) and not space.contains(5)


def test_a_boolean_hp_override_is_read_whatever_its_case() -> None:
    # ppo_recurrent's config_from_options: a bool is true for 1, true or yes in any case (the
    # text is lower-cased), so "True" and "YES" turn the progress bar on and "False" leaves it off.
    assert config_from_options({}, ("progress=True",)).progress is True
    assert config_from_options({}, ("progress=YES",)).progress is True
    assert config_from_options({}, ("progress=False",)).progress is False


def test_a_robot_seat_trace_is_cloned_against_the_robots_action_count(tmp_path: Path) -> None:
    # bc.behaviour_clone checks the masks against the recorded seat's action count: paper2015's
    # robot seat has 18 actions (its human seat 31), so a robot trace of 18-entry masks is cloned,
    # not refused as "18 actions recorded, 31 expected". Its one step (action 17 at a fact vector)
    # is the table's majority there, so the clone reproduces 1 of 1 recorded actions: accuracy 1.0.
    trace = _trace(tmp_path / "r.jsonl", [(_facts(0), _mask(17, seat=Agent.ROBOT), 17)], seat="robot")
    assert len(_mask(17, seat=Agent.ROBOT)) == 18
    path, accuracy = behaviour_clone([trace], tmp_path / "out", kind="table")
    assert accuracy == 1.0
    assert path.exists()
