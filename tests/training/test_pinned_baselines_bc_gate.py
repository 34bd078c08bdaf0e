"""Behaviour cloning's trace reading, fits and accuracy, pinned for the mutation gate.

The traces are written by hand in the replay format (a header with the scenario, seat and
name lists, then one line per recorded turn), so every fact vector, mask and action is
known; the expected tables, first gradient step and accuracies are worked by hand from
the documented rules (majority action per fact vector; masked softmax regression by
full-batch gradient descent, learning rate 0.5; accuracy = recorded actions reproduced
over recorded actions). Nothing is timed.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.core import Agent, World
from hg_marl.training.baselines.bc import KINDS, Dataset, behaviour_clone, fit_linear, load_traces

WORLD = World("paper2015")
FACTS = list(WORLD.fact_names)


def _trace(path: Path, steps: list[tuple[list[int], list[int], int]], seat: str = "human", **header: Any) -> Path:
    """A one-episode trace of ``steps`` (facts, mask, action) in ``paper2015`` unless the header says otherwise."""
    agent = Agent.HUMAN if seat == "human" else Agent.ROBOT
    head = {
        "type": "header",
        "format": "hg_marl.trace",
        "version": 1,
        "episode": header.pop("episode", 0),
        "scenario": "paper2015",
        "seat": seat,
        "actor": "hand",
        "fact_names": FACTS,
        "action_names": list(WORLD.action_names[agent]),
        "meta": {},
        **header,
    }
    lines = [json.dumps(head)]
    for i, (facts, mask, action) in enumerate(steps):
        lines.append(
            json.dumps(
                {
                    "type": "step",
                    "step": i,
                    "clock": float(i),
                    "tasks_solved": 0,
                    "facts": facts,
                    "mask": mask,
                    "action": action,
                }
            )
        )
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _facts(*ones: int, n: int = len(FACTS)) -> list[int]:
    return [1 if i in ones else 0 for i in range(n)]


def _mask(*ones: int, seat: Agent = Agent.HUMAN) -> list[int]:
    return [1 if i in ones else 0 for i in range(WORLD.n_actions(seat))]


def test_the_kinds_are_table_and_linear_softmax() -> None:
    assert KINDS == ("table", "linear_softmax")


def test_a_dataset_is_frozen() -> None:
    data = Dataset(np.zeros((1, 1), np.int8), np.ones((1, 1), bool), np.zeros(1, np.int64), "s", Agent.HUMAN)
    with pytest.raises(dataclasses.FrozenInstanceError):
        data.scenario = "other"


def test_traces_of_one_seat_are_read_into_one_dataset_in_order(tmp_path: Path) -> None:
    """Two files of the human seat: their 2 + 1 turns in file order, as int8 facts, bool masks, int64 actions."""
    first = _trace(tmp_path / "a.jsonl", [(_facts(0), _mask(1, 30), 1), (_facts(1), _mask(30), 30)])
    second = _trace(tmp_path / "b.jsonl", [(_facts(2), _mask(2, 30), 2)], episode=4)
    data = load_traces([first, second])
    assert data.facts.dtype == np.int8 and data.masks.dtype == bool and data.actions.dtype == np.int64
    assert data.facts.tolist() == [_facts(0), _facts(1), _facts(2)]
    assert data.masks.tolist() == [[bool(v) for v in m] for m in (_mask(1, 30), _mask(30), _mask(2, 30))]
    assert data.actions.tolist() == [1, 30, 2]
    assert (data.scenario, data.seat) == ("paper2015", Agent.HUMAN)


def test_a_robot_seat_trace_is_the_robot_seat(tmp_path: Path) -> None:
    trace = _trace(tmp_path / "r.jsonl", [(_facts(0), _mask(17, seat=Agent.ROBOT), 17)], seat="robot")
    assert load_traces([trace]).seat == Agent.ROBOT


def test_traces_of_another_seat_or_world_are_refused_naming_the_episode(tmp_path: Path) -> None:
    human = _trace(tmp_path / "h.jsonl", [(_facts(0), _mask(30), 30)])
    robot = _trace(tmp_path / "r.jsonl", [(_facts(0), _mask(17, seat=Agent.ROBOT), 17)], seat="robot", episode=3)
    with pytest.raises(
        ValueError, match=r"r\.jsonl: episode 3 is from 'paper2015' \(robot\), not 'paper2015' \(human\) like the first"
    ):
        load_traces([human, robot])
    other = _trace(tmp_path / "o.jsonl", [(_facts(0), _mask(30), 30)], scenario="elsewhere", episode=1)
    with pytest.raises(ValueError, match=r"episode 1 is from 'elsewhere' \(human\), not 'paper2015' \(human\)"):
        load_traces([human, other])


def test_traces_without_a_turn_are_refused(tmp_path: Path) -> None:
    empty = _trace(tmp_path / "e.jsonl", [])
    with pytest.raises(ValueError, match=r"no recorded steps in .*e\.jsonl"):
        load_traces([empty])


def test_one_gradient_step_of_the_linear_fit_worked_by_hand() -> None:
    """Two turns, facts (1, 0) -> action 0 and (0, 1) -> action 1, action 2 never feasible.

    From zero weights the feasible actions are equally likely (p = 0.5, 0.5, 0), so the
    gradient (p - y) / 2 is (-0.25, 0.25, 0) on row 0 and (0.25, -0.25, 0) on row 1;
    times the facts and the rate 0.5: W = [[0.125, -0.125], [-0.125, 0.125], [0, 0]],
    and the bias's gradient sums to 0 per action.
    """
    data = Dataset(
        np.array([[1, 0], [0, 1]], np.int8),
        np.array([[1, 1, 0], [1, 1, 0]], bool),
        np.array([0, 1], np.int64),
        "s",
        Agent.HUMAN,
    )
    w, b = fit_linear(data, 3, iterations=1)
    assert w == pytest.approx(np.array([[0.125, -0.125], [-0.125, 0.125], [0.0, 0.0]]))
    assert b == pytest.approx(np.zeros(3))


def test_an_action_never_feasible_keeps_zero_weights_however_long_the_fit() -> None:
    """Masked out of every turn, action 2 has probability 0 and so no gradient: its row and bias stay 0."""
    data = Dataset(
        np.array([[1, 0], [0, 1], [1, 1]], np.int8),
        np.array([[1, 1, 0], [1, 1, 0], [1, 1, 0]], bool),
        np.array([0, 1, 1], np.int64),
        "s",
        Agent.HUMAN,
    )
    w, b = fit_linear(data, 3)
    assert w.shape == (3, 2) and b.shape == (3,)
    assert np.all(w[2] == 0.0) and b[2] == 0.0
    logits = np.where(data.masks, data.facts @ w.T + b, -np.inf)
    assert np.argmax(logits, axis=1).tolist() == [0, 1, 1]


def test_a_table_clone_reports_the_share_of_recorded_actions_it_reproduces(tmp_path: Path) -> None:
    """One fact vector with actions 1, 1, 2 (the table keeps 1: 2 of 3) and one with 30 (kept): 3 of 4."""
    trace = _trace(
        tmp_path / "t.jsonl",
        [
            (_facts(0), _mask(1, 2, 30), 1),
            (_facts(0), _mask(1, 2, 30), 2),
            (_facts(0), _mask(1, 2, 30), 1),
            (_facts(5), _mask(30), 30),
        ],
    )
    out, accuracy = behaviour_clone([trace], tmp_path / "policy")
    assert accuracy == pytest.approx(0.75)
    human = make_human("learned", path=str(out), deterministic=True)
    assert human.kind == "table"


def test_a_linear_clone_is_a_linear_softmax_policy(tmp_path: Path) -> None:
    """Two fact vectors, each with its own action: a linear map separates them, so 2 of 2."""
    trace = _trace(tmp_path / "t.jsonl", [(_facts(0), _mask(1, 2, 30), 1), (_facts(5), _mask(1, 2, 30), 2)])
    out, accuracy = behaviour_clone([trace], tmp_path / "policy", kind="linear_softmax")
    assert accuracy == 1.0
    assert make_human("learned", path=str(out)).kind == "linear_softmax"


@pytest.mark.parametrize("n_facts", [len(FACTS) - 1, len(FACTS) + 1])
def test_traces_with_more_or_fewer_facts_than_the_scenario_are_refused(tmp_path: Path, n_facts: int) -> None:
    """The actions match ``paper2015``'s human seat (31); the facts, one short or one over, do not."""
    names = [f"f{i}" for i in range(n_facts)]
    trace = _trace(tmp_path / "t.jsonl", [(_facts(0, n=n_facts), _mask(30), 30)], fact_names=names)
    with pytest.raises(
        ValueError,
        match=rf"traces do not match scenario 'paper2015': {n_facts} facts and 31 actions recorded, 24 and 31 expected",
    ):
        behaviour_clone([trace], tmp_path / "policy")


def test_an_unknown_kind_is_refused_before_anything_is_read(tmp_path: Path) -> None:
    with pytest.raises(
        ValueError, match=r"unknown behaviour-cloning kind 'mlp'; use one of \('table', 'linear_softmax'\)"
    ):
        behaviour_clone([tmp_path / "missing.jsonl"], tmp_path / "p", kind="mlp")
