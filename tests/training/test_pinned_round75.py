"""The values round 75's missed planted bugs changed, pinned after the round.

Round 75 planted 16 bugs in sixteen gated modules, written blind; 11 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- ``fo_picky`` throws, takes and hands over only the even objects; an odd one it holds it
  only puts on a free shared spot (family_out's docstring);
- a tidy human moves an object out of the robot's reach when *some* shared spot is free,
  not only when every one is (``base.tidy_action``'s docstring: "a free shared spot");
- the cooperative human mixes its planned action with ``wait`` at ``p_idle``;
- the ``no_handover`` human's rule tidies "the first object" by index, so relabelling
  interchangeable objects does not relabel its answer: it must not say it is equivariant;
- ``runner_rate(..., deterministic=False)`` hands ``deterministic=False`` to the robot.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.humans.base import tidy_action
from hg_marl.agents.humans.cooperative import CooperativeHuman
from hg_marl.agents.humans.family_out import Picky
from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.core import Agent, State, World
from hg_marl.training.baselines import evaluation

# paper2015 with a second shared spot (mat_shared_2) beside mat_shared. Spots, in order:
# mat_left 0, mat_centre 1, mat_right 2, mat_shared 3, mat_shared_2 4, human_mat_1 5,
# human_mat_2 6; the human reaches 3..6 and no bin (the trashbin is the robot's only).
TWO_SHARED = """
name = "two_shared"
robot_locations = ["bin_side", "table_left", "table_right", "human_side"]
handover_locations = ["human_side"]
robot_start = ["bin_side"]

[[objects]]
name = "tape1"

[[objects]]
name = "tape2"

[[objects]]
name = "tape3"

[[bins]]
name = "trashbin"
robot_reach = ["bin_side"]
human_reach = false

[[spots]]
name = "mat_left"
robot_reach = ["table_left"]

[[spots]]
name = "mat_centre"
robot_reach = ["table_left", "table_right"]

[[spots]]
name = "mat_right"
robot_reach = ["table_right"]

[[spots]]
name = "mat_shared"
robot_reach = ["human_side"]
human_reach = true

[[spots]]
name = "mat_shared_2"
robot_reach = ["human_side"]
human_reach = true

[[spots]]
name = "human_mat_1"
human_reach = true

[[spots]]
name = "human_mat_2"
human_reach = true

[[layout]]
count = 2
spots = ["mat_left", "mat_centre", "mat_right"]

[[layout]]
count = 1
spots = ["human_mat_1", "human_mat_2"]
"""


def _names(world: World, dist: list[tuple[int, float]]) -> list[tuple[str, float]]:
    names = world.action_names[Agent.HUMAN]
    return [(names[i], p) for i, p in dist]


def test_a_tidy_human_moves_an_object_out_of_reach_while_one_of_two_shared_spots_is_free(tmp_path: Path) -> None:
    # Worked by hand from tidy_action's docstring: empty-handed, the human picks an object of
    # its area that the robot cannot reach from anywhere when there is a free shared spot to
    # move it to. tape1 lies on mat_shared (3, taken), tape2 on human_mat_1 (5, only the
    # human's), tape3 on mat_left (0, out of the human's reach); mat_shared_2 (4) is free;
    # the robot stands at bin_side (no handover). tape1 is already within the robot's reach
    # and the human reaches no bin, so the one useful move is pick(tape2).
    path = tmp_path / "two_shared.toml"
    path.write_text(TWO_SHARED, encoding="utf-8")
    world = World(str(path))
    names = world.action_names[Agent.HUMAN]
    one_free = State((3, 5, 0), 0)
    assert names[tidy_action(world, one_free, give=False)] == "pick(tape2)"
    assert names[tidy_action(world, one_free, give=True)] == "pick(tape2)"
    # The control: both shared spots taken (tape3 on mat_shared_2), nowhere to move tape2 to.
    assert tidy_action(world, State((3, 5, 4), 0), give=False) == -1


@pytest.mark.parametrize(
    ("held", "expected"),
    [(0, "give(tape1)"), (2, "give(tape3)"), (1, "place(tape2,mat_shared)")],
)
def test_fo_picky_hands_over_only_its_even_objects(held: int, expected: str) -> None:
    # paper2015: the human holds tape<held+1> (place code 6 spots + 1 bin + 1 = 8, the
    # human's hand), the robot waits empty-handed at human_side (3), the handover place,
    # mat_shared is free. Worked by hand from fo_picky's docstring: an even object (tape1,
    # tape3) is tidied as by a helpful human, who cannot reach the trashbin and hands it
    # over; an odd one (tape2) it never hands over, it only puts it on a free shared spot.
    world = World("paper2015")
    where = [0, 1, 2]
    where[held] = 8
    state = State(tuple(where), 3)
    assert world.holding(state, Agent.HUMAN) == held
    assert _names(world, Picky().distribution(world, state)) == [(expected, 1.0)]


def test_the_cooperative_human_idles_with_its_probability() -> None:
    # The module's rule: when the robot offers an object the human takes it, and the planned
    # action is mixed with wait at p_idle. paper2015: the robot stands at human_side (3), the
    # handover place, offering tape1 (in its hand: place code 6 spots + 1 bin = 7); the human
    # is empty-handed, tape2 and tape3 lie on mat_left and mat_right.
    world = World("paper2015")
    state = State((7, 0, 2), 3, offer_by=int(Agent.ROBOT), offer_obj=0)
    assert _names(world, CooperativeHuman(p_idle=0.0).distribution(world, state)) == [("take(tape1)", 1.0)]
    mixed = dict(_names(world, CooperativeHuman(p_idle=0.5).distribution(world, state)))
    assert mixed == {"take(tape1)": pytest.approx(0.5), "wait": pytest.approx(0.5)}
    always = dict(_names(world, CooperativeHuman(p_idle=1.0).distribution(world, state)))
    assert always.get("wait") == pytest.approx(1.0) and always.get("take(tape1)", 0.0) == pytest.approx(0.0)


def test_the_no_handover_human_is_not_declared_equivariant_because_its_rule_is_not() -> None:
    # A human is ``equivariant`` when relabelling interchangeable objects relabels its answer
    # the same way (base.StationaryHuman). In asymmetric_advantages tape2 and tape3 (objects
    # 1 and 2, the same bins) lie on middle_1 and middle_2 (spots 1 and 2, which the human
    # reaches and whose objects it can throw into human_bin) in the first state and swapped
    # in the second. An equivariant rule that picks tape2 in the first would pick tape3 in
    # the second; the no_handover human tidies the first object by index, so it picks tape2
    # in both (a property of its answers), and therefore must not say it is equivariant.
    world = World("asymmetric_advantages")
    human = NoHandoverHuman(p_idle=0.0)
    first = _names(world, human.distribution(world, State((0, 1, 2, 3), 0)))
    swapped = _names(world, human.distribution(world, State((0, 2, 1, 3), 0)))
    assert first == swapped == [("pick(tape2)", 1.0)]
    assert NoHandoverHuman.equivariant is False
    assert human.equivariant is False


class _GreedyModel:
    """A stand-in model with SB3's ``predict`` signature and no distribution (it is never run)."""

    policy = object()

    def predict(self, obs: Any, deterministic: bool = True, action_masks: Any = None) -> tuple[int, None]:
        return 0, None


@pytest.mark.parametrize("deterministic", [False, True])
def test_runner_rate_hands_its_deterministic_flag_to_the_robot(
    monkeypatch: pytest.MonkeyPatch, deterministic: bool
) -> None:
    # runner_rate's documented argument: ``deterministic`` picks the policy's mode (True) or
    # a sample from it (False); the robot it builds must carry what the caller asked for.
    # actor_rate is replaced by one that only builds the robot (no run).
    built: list[Any] = []

    def build_only(make_robot: Any, human: str, scenario: str, duration: float, seeds: Any) -> float:
        built.append(make_robot())
        return 0.0

    monkeypatch.setattr(evaluation, "actor_rate", build_only)
    evaluation.runner_rate(_GreedyModel(), "facts", "cooperative", "paper2015", deterministic=deterministic)
    assert [robot.deterministic for robot in built] == [deterministic]
