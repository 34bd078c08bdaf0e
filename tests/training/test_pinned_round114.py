"""Values that round 114's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

from hg_marl.agents.array_partners import CompiledPopulation
from hg_marl.training.play.replay import replay_trace
from tests.env.test_pinned_array_partners_gate import _Member
from tests.play.test_pinned_play_replay_gate import _record


def test_a_replay_summary_names_the_robot_asked_for_not_the_recorded_one(tmp_path: Path) -> None:
    # The game is recorded against "planner"; the replay asks for "planner:partner_aware=false",
    # the same robot (partner_aware is false by default), so the recorded table is reproduced and
    # the replay runs. The summary names the robot that was replayed, the one asked for: the
    # recording's robot is only the default when none is given (the gate checks that case).
    trace = _record(tmp_path / "a", robot="planner", seed=3, moves=4)
    asked = "planner:partner_aware=false"
    result = replay_trace(trace, robot=asked)
    assert result.robot == asked
    assert result.moves == 4


def test_a_population_is_named_by_its_members_joined_with_plus() -> None:
    # A population plays its members at once (one drawn per table), so its name joins them with
    # "+": "a+b+c" for members a, b and c, in their order. A comma list means something else in
    # the project (several separate partners, e.g. compare's --humans a,b: one training each;
    # a schedule's "switching(a,b)"), so a population named "a,b,c" would read as three partners.
    population = CompiledPopulation([_Member("a"), _Member("b"), _Member("c")])
    assert population.name == "a+b+c"
    assert CompiledPopulation([_Member("lazy")]).name == "lazy"
