"""Values that round 141's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hg_marl.agents.headroom import JointModel, headroom
from hg_marl.agents.models.answers import stationary_human
from hg_marl.core import Agent, World
from hg_marl.training.baselines.bc import behaviour_clone
from hg_marl.training.play.session import PlaySession
from tests.agents.test_headroom import CROSSING, C, G
from tests.agents.test_oracle import TINY
from tests.play.reference import person_choice
from tests.play.test_pinned_play_session_gate import ticking
from tests.training.test_pinned_baselines_bc_gate import _facts, _mask, _trace


def test_a_headroom_without_failed_actions_solves_the_model_without_them() -> None:
    # headroom(failed_actions=False) must model no deliberately infeasible robot action. The
    # reference is the Python enumeration (JointModel, another code path than the array
    # builder headroom uses) built with and without it: on the tiny scenario the option
    # changes the rate C's optimal policy earns against G (CROSSING's rates do not depend on it),
    # so a headroom that modelled the failing action anyway would report the other number.
    world = World(TINY)
    labels = ("cooperative", G, C)  # headroom's rows: cooperative first, then the true partners

    def reference(failed: bool) -> float:
        model = JointModel(world, [stationary_human(spec, world) for spec in labels], failed_actions=failed)
        return model.rate(model.optimal_policy(2), 1)  # C's optimal policy played with G

    without, with_failed = reference(False), reference(True)
    assert without != pytest.approx(with_failed)  # the option is visible in this cell
    result = headroom(TINY, [("G", G), ("C", C)], failed_actions=False)
    assert result.assumed == ("cooperative", "G", "C")
    assert result.rates[2, 0] == pytest.approx(without)
    assert headroom(TINY, [("G", G), ("C", C)]).rates[2, 0] == pytest.approx(with_failed)
    # and where the option changes nothing, the hand-worked crossing (test_headroom.py) is unchanged
    assert headroom(CROSSING, [("G", G), ("C", C)], failed_actions=False).rates[1].tolist() == pytest.approx(
        [3600 / 17.5, 3600 / 18]
    )


def test_the_summary_text_counts_the_robots_moves_not_its_experts() -> None:
    # The robot moves first, then once after each of the person's moves: 1 + 2 = 3 moves, all
    # chosen by the planner robot's planner ("planner 3"). Counting distinct experts would say 1.
    session = PlaySession(robot="planner", player="p", seed=0, timer=ticking())
    for _ in range(2):
        session.play(person_choice([c.name for c in session.choices()]))
    assert dict(session.experts) == {"planner": 3}
    assert "The robot's 3 moves were chosen by: planner 3." in session.summary_text()


def test_the_recurrent_sb3_run_trains_with_the_batch_size_it_was_given(tmp_path: Path) -> None:
    pytest.importorskip("sb3_contrib")
    from hg_marl.training.baselines.recurrent_ppo_sb3 import train
    from tests.training.test_recurrent_ppo_sb3 import _config

    # 2 tables x 8 steps = 16 transitions a rollout, cut into minibatches of 4 (not n_steps=8)
    config = _config(tmp_path, steps=16, num_envs=2, n_steps=8, batch_size=4, history=0)
    result = train(config)
    assert result.model.batch_size == 4
    assert result.model.n_steps == 8


def test_a_robot_seat_trace_is_cloned_into_a_robot_seat_policy(tmp_path: Path) -> None:
    # One robot-seat step (action 17 of paper2015's 18 robot actions, test_pinned_round109.py):
    # the table policy written is the robot seat's, with the robot's 18 action names, so it
    # plays in the seat it was recorded in.
    trace = _trace(tmp_path / "r.jsonl", [(_facts(0), _mask(17, seat=Agent.ROBOT), 17)], seat="robot")
    path, accuracy = behaviour_clone([trace], tmp_path / "out", kind="table")
    assert accuracy == 1.0
    header = json.loads((path / "policy.json").read_text())
    assert header["seat"] == "robot"
    assert header["action_names"] == list(World("paper2015").action_names[Agent.ROBOT])
    assert len(header["action_names"]) == 18
