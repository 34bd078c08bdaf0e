"""Values that round 192's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from hg_marl.agents.humans.base import wait_index
from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.humans.family_out import Picky
from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.core import Agent, Kind, State, World
from hg_marl.training import switching
from hg_marl.training.population_gen import RANGES, sample_candidates
from hg_marl.training.switching import switching_table
from tests.agents.test_pinned_human_cooperative_gate import GOTO_TAPE1, PAPER, answer, planned
from tests.training.test_pinned_switching import CONFIG, _stand_ins


def test_picky_leaves_an_odd_object_alone_while_no_shared_spot_is_free() -> None:
    # paper2015: spots 0-2 are the robot's mats, 3 (mat_shared) the one shared spot, 4 and 5
    # (human_mat_1, human_mat_2) the human's only; the human reaches no bin. tape1 (even) lies on
    # mat_shared, tape2 (odd) on human_mat_1, tape3 on mat_left; the robot at bin_side (0), no
    # offer, the human's hands empty. Worked by hand from fo_picky's docstring: tape1 cannot be
    # binned by the human and already lies within the robot's reach; tape2 may only be moved onto
    # a free shared spot, and mat_shared is taken; tape3 is out of the human's reach: it waits.
    world = World("paper2015")
    blocked = State((3, 4, 0), 0)
    assert Picky().distribution(world, blocked) == [(wait_index(world), 1.0)]
    # The control: with mat_shared free (tape1 on mat_centre) it picks tape2 to move it there.
    free = State((1, 4, 0), 0)
    pick_tape2 = world.table.action_index(Agent.HUMAN, Kind.PICK, 1)
    assert Picky().distribution(world, free) == [(pick_tape2, 1.0)]


def test_the_cooperative_human_answers_a_known_robot_action_after_an_unknown_one_as_a_fresh_one() -> None:
    # Holding tape3 with the robot at table_left (the gate's state): the planner's answer with the
    # robot's goto(tape1) under way differs from its answer with the robot's action unknown. A human
    # asked with the action unknown first must still answer the goto as a cold planner does (the
    # reference ``planned``: a fresh planner's intent), not with the answer it kept for "unknown".
    state = State((0, 1, 8), 1)
    unknown, known = planned(PAPER, state, None), planned(PAPER, state, GOTO_TAPE1)
    assert unknown != known
    human = CooperativeHuman()
    assert answer(human, PAPER, state, -1) == unknown
    assert answer(human, PAPER, state, GOTO_TAPE1) == known
    assert answer(human, PAPER, state, -1) == unknown  # and back again


@pytest.mark.parametrize("p_idle", [0.8, 1.0])
def test_the_no_handover_human_idles_with_its_whole_p_idle(p_idle: float) -> None:
    # paper2015: tape2 on human_mat_1 (4, the human's only), mat_shared (3) free, tape1 and tape3
    # on the robot's mats, the robot at bin_side: the tidying move is pick(tape2) (to put it on
    # mat_shared). Mixed with wait at p_idle: wait with p_idle, pick(tape2) with 1 - p_idle
    # (0.8: 0.2; 1.0: never, as a probability one human waits at every turn).
    world = World("paper2015")
    state = State((0, 4, 2), 0)
    pick_tape2 = world.table.action_index(Agent.HUMAN, Kind.PICK, 1)
    dist = dict(NoHandoverHuman(p_idle=p_idle).distribution(world, state))
    assert dist[wait_index(world)] == pytest.approx(p_idle)
    assert dist.get(pick_tape2, 0.0) == pytest.approx(1.0 - p_idle)


def test_sampled_weights_are_rounded_to_hundredths_not_tenths() -> None:
    # The docstring: values rounded to 0.01. Every uniform weight is a whole number of hundredths,
    # and among 8 seeded candidates' 6 weights (48 draws) some are not whole tenths: 48 uniform
    # draws all landing on tenths after rounding to hundredths has probability 0.1 ** 48.
    candidates = sample_candidates("paper2015", 8, seed=0)
    values = [c[key] for c in candidates for key in RANGES]
    assert len(values) == 48
    assert all(math.isclose(v * 100, round(v * 100), abs_tol=1e-6) for v in values)
    assert sum(not math.isclose(v * 10, round(v * 10), abs_tol=1e-6) for v in values) > 24


def test_a_switching_cell_names_its_pair_first_member_first(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    # CONFIG switches A (lazy) and B (cooperative), A first: each cell's pair reads "A/B", the
    # order the pair was given in (and the one the schedule plays), and so does the printed table.
    _stand_ins(monkeypatch, {})
    summary = switching.run_switching(CONFIG, tmp_path)
    assert [c["pair"] for c in summary["cells"]] == ["A/B", "A/B"]
    rows = switching_table(summary).splitlines()[2:]
    assert len(rows) == 2 and all(row.startswith("A/B ") for row in rows)
