"""Round 45 of the fresh planted bugs: the values its missed bugs changed, pinned.

The expected values are stated independently of the code under test: the exact sums of a
state with an infinite value are "None: some value is infinite" (``ExactSums.sums``'s
docstring), whatever the other objects add up to, checked on tables made by hand; the
entropy-and-cost criterion's filtered costs are ``(1 - rate) * old + rate * new`` (the
filter of :mod:`hg_marl.agents.meta.entropy`), worked by hand from two costs per expert; a
registry's listing is written as a Python call (``name(k=v, ...)``), so a text default is
quoted as Python writes it and told apart from a number with the same digits; a ``|`` list
of file paths is searched item by item (``content``'s module docstring), each file keyed by
the SHA-256 of its bytes computed here with ``hashlib``.
"""

from __future__ import annotations

import hashlib
import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.content import named_files
from hg_marl.agents.meta.base import HabitView, PlanProposal
from hg_marl.agents.meta.entropy_cost import EntropyAndCostCriterion
from hg_marl.agents.planner.exactsum import ExactSums
from hg_marl.core.errors import ConfigError
from hg_marl.core.registry import Registry


def _tables(k: int, inf_status: int) -> list[list[list[list[float]]]]:
    """``k`` weights, one robot location, two objects, two statuses: object 0 is a dead end in
    status ``inf_status``, worth 1.5 * (weight + 1) otherwise; object 1 is worth 0 in status 0
    and 2.5 in status 1."""
    out = []
    for w in range(k):
        obj0 = [math.inf if s == inf_status else 1.5 * (w + 1) for s in range(2)]
        obj1 = [0.0, 2.5]
        out.append([[obj0, obj1]])
    return out


@pytest.mark.parametrize("k", [5, 3])  # five weights: the 64-bit fields' path; three: the masked fields'
def test_a_dead_end_has_no_sums_even_when_the_other_objects_add_up_to_zero(k: int) -> None:
    # by the docstring, None whenever some object's value is infinite; object 1 in status 0
    # adds exactly 0, the case where the packed total is the dead-end flag and nothing else
    tabs = _tables(k, inf_status=1)
    sums = ExactSums(tabs, tabs, n_objects=2)
    assert sums.packed is not None
    assert sums.sums(False, 0, [1, 0]) is None
    assert sums.sums(False, 0, [1, 1]) is None
    assert sums.of_places(False, 0, [1, 0], -1, 0) is None
    # and a state without an infinite value is the plain sum, by hand
    assert sums.sums(False, 0, [0, 1]) == tuple(1.5 * (w + 1) + 2.5 for w in range(k))
    assert sums.sums(False, 0, [0, 0]) == tuple(1.5 * (w + 1) for w in range(k))


def _habit(cost: float) -> HabitView:
    probs = np.array([0.7, 0.2, 0.1])
    return HabitView(b"s", probs, 0, np.zeros(3), np.ones(3), 1.0, cost, visits=10)


def test_entropy_and_cost_filters_each_experts_cost_with_the_new_value_weighted_by_rate() -> None:
    # rate 0.6: a filtered cost is 0.4 * old + 0.6 * new, the first value taken as it is.
    # The planner is consulted twice in the state at costs 1.0 then 0.5: 0.4 + 0.3 = 0.7;
    # the habit's costs 0.1, 0.1 then 0.5 give 0.04 + 0.3 = 0.34. Scaled by the larger, 0.7:
    # t_planner = 1 and t_habit = 0.34 / 0.7 (swapped weights give 0.26 / 0.8).
    crit = EntropyAndCostCriterion(rate=0.6)
    crit.reset(np.random.default_rng(0))
    for plan_cost in (1.0, 0.5):
        crit.wants_plan(_habit(0.1))
        crit.choose(_habit(0.1), PlanProposal.make(0, 3, plan_cost))
    crit.wants_plan(_habit(0.5))
    habit = 0.4 * (0.4 * 0.1 + 0.6 * 0.1) + 0.6 * 0.5
    assert crit.stats["t_planner"] == pytest.approx(1.0)
    assert crit.stats["t_habit"] == pytest.approx(habit / 0.7)
    assert habit == pytest.approx(0.34)


class _Toy:
    name = "toy"

    def __init__(self, mode: str = "1", level: int = 1, rate: float = 0.5) -> None:
        self.mode, self.level, self.rate = mode, level, rate


def test_a_registrys_listing_quotes_a_text_default_as_a_python_call_writes_it() -> None:
    # the listing reads as a call, toy(mode='1', level=1, rate=0.5): the text default '1'
    # and the number 1 must not read the same
    registry = Registry("thing", ConfigError, [_Toy], list_params=True)
    assert registry.listing() == "toy(mode='1', level=1, rate=0.5)"
    with pytest.raises(ConfigError) as info:
        registry.make("nope")
    assert str(info.value) == "unknown thing 'nope'; available: toy(mode='1', level=1, rate=0.5)"


def test_each_file_of_a_bar_separated_list_is_keyed_by_its_bytes(tmp_path: Path) -> None:
    # ``a|b`` names two files (no colon in either path): each is keyed by its own bytes
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    a.write_bytes(b"x,y\n1,2\n")
    b.write_bytes(b"x,y\n3,4\n")
    assert ":" not in str(tmp_path)
    found = named_files({"humans": f"{a}|{b}"})
    assert found == {
        str(a): {"a.csv": hashlib.sha256(b"x,y\n1,2\n").hexdigest()},
        str(b): {"b.csv": hashlib.sha256(b"x,y\n3,4\n").hexdigest()},
    }
