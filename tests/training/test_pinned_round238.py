"""Values that round 238's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.agents.views import RobotView


def test_a_population_of_two_partners_draws_both() -> None:
    # Each reset draws one of the two humans with the view's seeded generator, each with
    # probability 1/2: over 20 seeds both are met (one never drawn has probability 2 * 2**-20),
    # and the human the info names is the one that plays the episode.
    view = RobotView("paper2015", human=["lazy", "random"], max_cycles=5)
    seen = set()
    for seed in range(20):
        _, info = view.reset(seed=seed)
        assert info["human"] == view.human.name
        seen.add(info["human"])
    assert seen == {"lazy", "random"}
