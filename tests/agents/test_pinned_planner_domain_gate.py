"""The HTN domain's status codes and its explanation of an unreachable object, pinned for the mutation gate.

Worked by hand on ``paper2015``: its places are the six spots (0-5: mat_left, mat_centre,
mat_right, mat_shared, human_mat_1, human_mat_2), the bin (6), the robot's hand (7) and the
human's hand (8); the domain's status codes go on with "offered by the human" (9) and
"offered by the robot" (10). An offered object stays in its giver's hand until taken.

Each method's least work is worked by hand from the durations every layout here uses
(pick 2, throw 2, give 1, take 1.5, place 2, goto 3 s) and the module docstring's rules
(a goto to carry the object where its spot is not in reach of its bins or of the handover
location, and one empty-handed goto to fetch it where no release location reaches its spot).

The robot reaches no human mat, so a tape on ``human_mat_1`` can only be disposed of with
the human's help: with a human who only waits, no method of ``dispose`` applies to it.
"""

from __future__ import annotations

from pathlib import Path

from test_pinned_planner_plan_gate import TO_THE_HUMAN, layout

from hg_marl.agents.planner import Planner
from hg_marl.agents.planner.domain import Domain, Work
from hg_marl.agents.planner.models import RestrictedHuman, cooperative
from hg_marl.core import Kind, State, World

NONE: frozenset[Kind] = frozenset()
PICK, GIVE, TAKE = frozenset({Kind.PICK}), frozenset({Kind.GIVE}), frozenset({Kind.TAKE})


def test_the_status_codes_follow_the_places_with_the_two_offers() -> None:
    domain = Domain(World("paper2015"), cooperative())
    assert (domain.robot_hand, domain.human_hand, domain.human_offer, domain.robot_offer) == (7, 8, 9, 10)
    assert domain.n_status == 11


def test_an_offered_objects_status_says_who_offers_it_and_the_others_keep_their_place() -> None:
    """The robot holds and offers tape1 (offer_by 0); the human holds and offers tape3 (offer_by 1)."""
    domain = Domain(World("paper2015"), cooperative())
    by_robot = State(where=(7, 1, 4), robot_at=3, offer_by=0, offer_obj=0)
    assert [domain.status(by_robot, o) for o in range(3)] == [10, 1, 4]
    by_human = State(where=(0, 1, 8), robot_at=3, offer_by=1, offer_obj=2)
    assert [domain.status(by_human, o) for o in range(3)] == [0, 1, 9]


def test_an_object_no_method_reaches_is_named_with_its_place_and_the_human_model() -> None:
    """Tapes on mat_left, mat_right and human_mat_1, a human who only waits: tape3 is out of
    reach (tape1 and tape2 the robot disposes of alone), and the explanation says so."""
    world = World("paper2015")
    idle = RestrictedHuman("idle", frozenset({Kind.WAIT}))
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    assert Domain(world, idle).explain_unreachable(state) == (
        "no decomposition of dispose(tape3): it is on human_mat_1 and no method (robot alone, handovers, "
        "human alone, human places) applies with the 'idle' human"
    )
    # a cooperative human can bring it over (gives it, or places it on mat_shared): nothing to explain
    assert Domain(world, cooperative()).explain_unreachable(state) == ""


def test_a_human_who_never_picks_cannot_give_or_place_an_object_lying_on_its_mat() -> None:
    """The same tapes, a human who gives, places, takes and throws but never picks: an object
    on a human mat must be picked before it is given or placed, so no method applies to tape3
    (the module docstring's early proof), and the planner says so at once instead of searching
    every state; the same human holding tape3 can give it (a handover to the robot applies)."""
    world = World("paper2015")
    no_pick = RestrictedHuman("no pick", frozenset({Kind.GIVE, Kind.PLACE, Kind.TAKE, Kind.THROW}))
    domain = Domain(world, no_pick)
    assert [name for name, _ in domain.works(2, 4, 1)] == []
    state = State(where=(0, 2, 4), robot_at=1, offer_by=-1, offer_obj=-1)
    assert domain.explain_unreachable(state).startswith("no decomposition of dispose(tape3): it is on human_mat_1")
    result = Planner(world, human_model=no_pick).plan(state)
    assert not result.success and result.reason.startswith("unreachable: no decomposition of dispose(tape3)")
    assert "handover_h2r" in [name for name, _ in domain.works(2, domain.human_hand, 1)]


def test_paper2015_on_the_shared_mat_robot_alone_handover_to_the_robot_and_the_human_placing() -> None:
    """The bin is reached from bin_side (0) only, mat_shared from human_side (3) only, the
    handover location is human_side; the human reaches no bin. Releases are at bin_side
    alone, so fetching the tape or the handover costs an empty goto (3 s).

    - robot alone: pick 2 + throw 2 + carry 3 + fetch 3 = 10;
    - the human picks and gives (3 s of its work, all of it holding), the robot fetches 3,
      takes 1.5, carries 3, throws 2: 9.5;
    - the human picks and places (4 s, holding for the pick's 2), then the robot's least
      disposal from a spot both reach (mat_shared again): 10.
    """
    domain = Domain(World("paper2015"), cooperative())
    assert domain.works(2, 3, 1) == [
        ("robot_alone", Work(10.0, 0.0, PICK, NONE)),
        ("handover_h2r", Work(9.5, 3.0, NONE, PICK, 3.0)),
        ("human_places", Work(10.0, 4.0, NONE, PICK, 2.0)),
    ]


def test_roboergosum_an_object_for_the_human_reached_bin_from_the_handover_locations_mat() -> None:
    """Object 3 goes into bin 1 (robot from location 1, the human reaches it); placemat1 is
    reached from location 0, the handover location, and both locations release objects,
    so nothing is fetched empty-handed.

    - robot alone: pick 2 + throw 2 + carry 3 (location 0 to 1) = 7;
    - the robot picks and gives at once (3, no carry), the human takes and throws (3.5,
      holding for the take's 1.5).
    """
    world = World("roboergosum")
    domain = Domain(world, cooperative())
    assert domain.works(3, 0, 0) == [
        ("robot_alone", Work(7.0, 0.0, PICK, NONE)),
        ("handover_r2h", Work(3.0, 3.5, PICK, NONE, 1.5)),
    ]


def test_a_bin_only_the_human_reaches_is_served_by_handing_over_at_its_side(tmp_path: Path) -> None:
    """``to_the_human``: the tape on a mat reached from ``table`` (0), the bin by the human
    only, the handover at ``human_side`` (1), the one release location. From the mat: pick 2
    + give 1 + carry 3 + fetch 3 = 9 for the robot, take 1.5 + throw 2 for the human.
    Held by the robot: give 1, plus a goto from the table. Offered: the human's take and
    throw are left. In the human's hand: its throw."""
    domain = Domain(layout(tmp_path, TO_THE_HUMAN), cooperative())
    hand = (domain.robot_hand, domain.human_hand)
    after = Work(0.0, 3.5, NONE, NONE, 1.5)
    assert domain.works(0, 0, 0) == [("handover_r2h", after._replace(robot=9.0, robot_next=PICK))]
    assert domain.works(0, hand[0], 0) == [("handover_r2h", after._replace(robot=4.0, robot_next=GIVE))]
    assert domain.works(0, hand[0], 1) == [("handover_r2h", after._replace(robot=1.0, robot_next=GIVE))]
    assert domain.works(0, domain.robot_offer, 1) == [("handover_r2h", after._replace(human_next=TAKE))]
    assert domain.works(0, hand[1], 1) == [("human_alone", Work(0.0, 2.0, NONE, frozenset({Kind.THROW})))]


def test_a_human_who_takes_but_never_picks_still_throws_what_it_took(tmp_path: Path) -> None:
    """``to_the_human`` with a human who only takes and throws (no pick): the robot picks
    the tape and gives it at the human's side, the human takes and throws it. In the
    human's hand the tape needs only the human's throw (2 s); without a throw it needs
    something no method gives. Worked by hand: robot pick 2, goto 3, give 1; human take
    1.5, throw 2; the plan ends with both waiting."""
    world = layout(tmp_path, TO_THE_HUMAN)
    takes = RestrictedHuman("takes", frozenset({Kind.TAKE, Kind.THROW}))
    domain = Domain(world, takes)
    assert domain.works(0, domain.human_hand, 1) == [("human_alone", Work(0.0, 2.0, NONE, frozenset({Kind.THROW})))]
    assert Domain(world, RestrictedHuman("takes only", frozenset({Kind.TAKE}))).works(0, domain.human_hand, 1) == []
    result = Planner(world, human_model=takes).plan(State((0,), 0))
    assert result.success and result.plan is not None
    robot, human = result.plan.streams
    assert [s.name.split("(")[0] for s in robot if not s.name.startswith("wait")] == ["pick", "goto", "give"]
    assert [s.name.split("(")[0] for s in human if not s.name.startswith("wait")] == ["take", "throw"]
