"""The values round 66's missed planted bugs changed (``mutation/planted.py``, FRESH66), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

import pandas as pd
import pytest

from hg_marl.agents.humans.lazy import LazyHuman
from hg_marl.agents.humans.no_handover import NoHandoverHuman
from hg_marl.core import Agent, State, World
from hg_marl.training.report import crossplay_table, mean_table


@pytest.mark.parametrize("p_idle", [-0.1, 1.5])
def test_the_no_handover_human_refuses_an_idle_chance_that_is_not_a_probability(p_idle: float) -> None:
    # The docstring: "p_idle: probability of doing nothing at any turn" and every scripted human
    # validates it as a probability in [0, 1]; -0.1 and 1.5 are not, 0 and 1 (the ends) are.
    with pytest.raises(ValueError, match="p_idle must be a probability"):
        NoHandoverHuman(p_idle=p_idle)
    assert NoHandoverHuman(p_idle=0.0).p_idle == 0.0
    assert NoHandoverHuman(p_idle=1.0).p_idle == 1.0


def test_the_mean_score_table_averages_three_seeds_not_their_median() -> None:
    # The docstring: "Robots x humans mean score". By hand: robot A's scores with human h over
    # three seeds are 0, 0 and 0.9, mean (0 + 0 + 0.9) / 3 = 0.30 (the median would be 0.00);
    # robot B's 0.2, 0.5, 0.5 have mean 0.40 (median 0.50).
    rows = [
        {"robot": r, "human": "h", "scenario": "paper2015", "seed": i, "score": v}
        for r, values in (("A", [0.0, 0.0, 0.9]), ("B", [0.2, 0.5, 0.5]))
        for i, v in enumerate(values)
    ]
    frame = pd.DataFrame(rows)
    frame["oracle_rate"], frame["reference"] = 100.0, "oracle"
    assert mean_table(frame).to_numpy().ravel().tolist() == pytest.approx([0.3, 0.4])
    assert crossplay_table(frame).splitlines()[2:4] == ["| A | 0.30 |", "| B | 0.40 |"]


def test_the_lazy_human_is_not_declared_equivariant_because_its_rule_is_not() -> None:
    # A human is ``equivariant`` when relabelling interchangeable objects in the state
    # relabels its answer the same way (base.StationaryHuman; the oracle then keeps one state
    # per relabelling class). In ``asymmetric_advantages`` tape2 and tape3 (objects 1 and 2,
    # the same bins) lie on middle_1 and middle_2 (spots 1 and 2, which the human reaches) in
    # the first state and swapped in the second. An equivariant human that picks tape2 in the
    # first would pick tape3 in the second; the lazy human tidies "the first object" by index,
    # so it picks tape2 in both (checked here as a property of its answers), and therefore
    # must not say it is equivariant: the oracle would merge states it answers differently.
    world = World("asymmetric_advantages")
    lazy = LazyHuman(p_idle=0.0)
    names = world.action_names[Agent.HUMAN]
    first = [names[i] for i, _ in lazy.distribution(world, State((0, 1, 2, 3), 0))]
    swapped = [names[i] for i, _ in lazy.distribution(world, State((0, 2, 1, 3), 0))]
    assert first == swapped == ["pick(tape2)"]  # an equivariant rule would give pick(tape3) second
    assert LazyHuman.equivariant is False
    assert lazy.equivariant is False
