"""Values that round 247's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.planner.models import lazy
from hg_marl.agents.robots.partnering import Partnering
from hg_marl.core import Agent, Kind, World


def test_the_lazy_human_gives_places_picks_and_throws_but_never_takes() -> None:
    # The lazy human "only handles objects on spots it reaches (picks, throws, gives, places)
    # and never takes what the robot offers": of the human's kinds (all but GOTO) only TAKE is
    # missing, and WAIT is always there. So a give is something this human does.
    model = lazy()
    assert model.allowed_kinds == frozenset({Kind.PICK, Kind.THROW, Kind.GIVE, Kind.PLACE, Kind.WAIT})
    world = World("paper2015")
    gives = [i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.GIVE]
    takes = [i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.TAKE]
    assert gives and takes
    assert all(model.allows(world, i) for i in gives)
    assert not any(model.allows(world, i) for i in takes)


def test_a_partner_aware_robots_estimate_is_the_posteriors_type_even_with_a_block() -> None:
    # paper2015, partner aware, nothing observed yet: the posterior is its prior, 0.7 on the
    # cooperative type and 0.1 on each of lazy, no_handover and noisy, so the most probable type
    # is "cooperative". A block by the monitor restricts that type's model; it does not replace
    # the estimate the decision record shows with the block count ("blocked=1" is the estimate
    # of a robot without a posterior).
    world = World("paper2015")
    partnering = Partnering(world, None, None, partner_aware=True)
    assert partnering.estimate == "cooperative"
    give = next(a for a in world.actions(Agent.HUMAN) if a.kind is Kind.GIVE)
    partnering.monitor.blocked = frozenset({give})
    assert partnering.estimate == "cooperative"
