"""Values that round 183's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pandas as pd

from hg_marl.agents.humans.adversarial import AdversarialHuman
from hg_marl.agents.humans.family_out import Shy, robot_stuck
from hg_marl.core import Agent, State, World
from hg_marl.training.stalls import report
from tests.agents.test_pinned_human_adversarial_gate import named
from tests.training.test_pinned_stalls import _store_run, _study


def test_the_shy_partner_never_hands_over_even_to_a_robot_stuck_at_the_handover_place() -> None:
    # asymmetric_advantages with a human_bin the human does not reach (so it reaches no bin). Places:
    # robot_mat 0, middle_1 1, middle_2 2, human_mat 3, the human's hand 7. Tapes 1-3 lie on human_mat,
    # the human holds tape4 and the robot stands empty-handed at home, its handover location: nothing
    # is within its reach from anywhere (the middle mats are free), so its only move is wait (stuck).
    # The shy partner then tidies, but "never takes nor hands over": it cannot throw, so it puts tape4
    # on the first free shared spot, middle_1, although give(tape4) is feasible.
    base = World("asymmetric_advantages").scenario
    robot_bin, human_bin = base.bins
    no_reach = dataclasses.replace(human_bin.reach, human=False)
    world = World(dataclasses.replace(base, bins=(robot_bin, dataclasses.replace(human_bin, reach=no_reach))))
    state = State((3, 3, 3, 7), 0)
    names = world.action_names[Agent.HUMAN]
    assert robot_stuck(world, state)
    assert "give(tape4)" in [names[i] for i in world.feasible_indices(state, Agent.HUMAN)]
    assert named(world, Shy().distribution(world, state)) == [("place(tape4,middle_1)", 1.0)]


def test_the_adversary_never_steals_back_what_lies_out_of_the_robots_reach() -> None:
    # paper2015, robot at bin_side (0), the adversary empty-handed. Tactic 4 steals only from a spot
    # both reach, and mat_shared (3) is the only one. tape1 on human_mat_1 (4, the human's alone: where
    # tactic 3 hides things), tape2 and tape3 on the robot's mats: nothing to steal, so it waits.
    world = World("paper2015")
    adversary = AdversarialHuman()
    assert named(world, adversary.distribution(world, State((4, 0, 1), 0))) == [("wait", 1.0)]
    # tape2 on mat_shared instead: that one is stolen, not tape1 (object 0) from its hiding place.
    assert named(world, adversary.distribution(world, State((4, 3, 1), 0))) == [("pick(tape2)", 1.0)]


def test_a_run_without_any_task_on_a_solvable_cell_is_a_stall(tmp_path: Path) -> None:
    # The study of test_pinned_stalls: habit:alpha=0.5 with picky:k=2 once (one task at 250 s, longest
    # stretch 750 s). A second habit run with the same partner and scenario solves nothing in its
    # 1000 s: the cell is solvable (other runs solved tasks in it), so this run counts, and its whole
    # length is its longest stretch: 2 runs, 2 stalls, the worst 1000 s on seed 5.
    out = _study(tmp_path)
    job = {
        "scenario": "paper",
        "duration": 1000.0,
        "robot": "habit",
        "robot_params": {"alpha": 0.5},
        "human": "picky",
        "human_params": {"k": 2},
        "seed": 5,
    }
    log = pd.DataFrame({"time": [10.0, 20.0], "tasks_solved": [0, 0], "reason": ["habit", "habit"]})
    _store_run(out, "ee05", job, log)
    habit = [ln for ln in report(out).splitlines() if ln.startswith("| habit")]
    assert habit == ["| habit:alpha=0.5 | 2 | 2 | 1000 (picky:k=2, paper, seed 5) | 0.0 |"]
