"""Test-side references, written independently of the code under test.

``person_choice`` is how the tests play: a person who clears their own side and hands
over what only the robot can bin (take an offer, give what is in hand, throw, pick,
else wait). ``expected_drawing`` says what the page must show for a state, computed
from the world's raw codes (spots, then bins, then the robot's and the human's hands).
"""

from __future__ import annotations

from hg_marl.core import State, World

PREFERENCE = ("take(", "give(", "throw(", "pick(")


def person_choice(names: list[str]) -> str:
    """The action a cooperative person picks among the feasible ``names``."""
    for prefix in PREFERENCE:
        for name in names:
            if name.startswith(prefix):
                return name
    return "wait"


def expected_drawing(world: World, state: State) -> dict[str, object]:
    """Robot location, each object's place, the pending offer, as the page must draw them."""
    sc = world.scenario
    n_spots, n_bins = len(sc.spots), len(sc.bins)
    places = [f"spot:{s.name}" for s in sc.spots] + [f"bin:{b.name}" for b in sc.bins]
    places += ["hand:robot", "hand:human"]
    assert len(places) == n_spots + n_bins + 2
    return {
        "robot": sc.robot_locations[state.robot_at],
        "objects": {sc.objects[o]: places[p] for o, p in enumerate(state.where)},
        "offer": None if state.offer_by < 0 else (sc.objects[state.offer_obj], ("robot", "human")[state.offer_by]),
    }
