"""Values that round 158's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.partner_specs import as_list
from hg_marl.agents.views import RobotView
from tests.agents.test_pinned_partner_specs_gate import _Scripted


def test_a_population_keeps_its_repeated_members_so_they_weigh_in_the_draw() -> None:
    # A population is its list of members, one drawn uniformly per episode: naming a member twice
    # is how a user weights it. ["lazy", "lazy", "cooperative"] has three members (lazy drawn with
    # probability 2/3), not two (1/2); the same Actor object named twice is two members as well.
    assert as_list(["lazy", "lazy", "cooperative"]) == ["lazy", "lazy", "cooperative"]
    actor = _Scripted()
    out = as_list((actor, actor))
    assert len(out) == 2 and out[0] is actor and out[1] is actor
    # In a view: over 300 seeded episodes lazy is drawn with probability 2/3 (mean 200, standard
    # deviation sqrt(300 * 2/3 * 1/3) ~ 8.2); merged into two members it would be 1/2 (mean 150).
    view = RobotView("paper2015", human=["lazy", "lazy", "cooperative"], max_cycles=5)
    lazy = sum(view.reset(seed=s)[1]["human"] == "lazy" for s in range(300))
    assert 175 <= lazy <= 225
