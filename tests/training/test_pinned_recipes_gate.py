"""Each recipe builds its partner from the recipe's name however the name was made.

The names are built at run time (as a command line or a file gives them), not written
as literals, so the choice depends on the text, not on which string object it is.
Expected partners from the module's definitions: ``fcp`` mixes random actions at the
three checkpoint levels 0, 0.3 and 0.6, ``e3t`` at 0.3, ``coverage`` moves the tables
after each reset, ``members`` is the compiled members themselves.
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.core import World
from hg_marl.training.baselines.recipes import CoveragePartner, NoisyPartner, recipe_partner


def _name(text: str) -> str:
    return "".join(list(text))  # a new string object with the same text


@pytest.mark.parametrize(
    ("recipe", "kind", "levels"),
    [("fcp", NoisyPartner, [0.0, 0.3, 0.6]), ("e3t", NoisyPartner, [0.3]), ("coverage", CoveragePartner, None)],
)
def test_a_recipe_named_at_run_time_builds_its_partner(recipe: str, kind: type, levels: list[float] | None) -> None:
    world = World("paper2015")
    partner = recipe_partner(world, ("cooperative", "lazy"), _name(recipe), cache=None)
    assert type(partner) is kind
    if levels is not None:
        assert np.asarray(partner.levels).tolist() == levels
    members = recipe_partner(world, ("cooperative", "lazy"), _name("members"), cache=None)
    assert not isinstance(members, NoisyPartner | CoveragePartner)


def test_the_eps_table_grows_to_the_highest_row_reset() -> None:
    world = World("paper2015")
    partner = recipe_partner(world, ("cooperative",), "fcp", cache=None)
    rng = np.random.default_rng(0)
    partner.reset_rows(np.array([], dtype=np.int64), rng)
    assert len(partner.eps) == 0
    partner.reset_rows(np.array([4, 1]), rng)
    assert len(partner.eps) == 5
    assert set(partner.eps[[1, 4]].tolist()) <= {0.0, 0.3, 0.6}
    partner.reset_rows(np.array([6]), rng)  # grown again: by two rows, to the highest row reset
    assert len(partner.eps) == 7
    partner.reset_rows(np.array([3]), rng)  # a row it has: no growth
    assert len(partner.eps) == 7


def test_every_training_member_is_in_the_partner_and_one_is_itself() -> None:
    world = World("paper2015")
    both = recipe_partner(world, ("cooperative", "lazy"), "members", cache=None)
    assert [m.name for m in both.members] == ["cooperative", "lazy"]
    one = recipe_partner(world, ("lazy",), "members", cache=None)
    assert one.name == "lazy" and not hasattr(one, "members")


class _Bare:
    """An inner partner without a fallback count."""

    name = "bare"


def test_a_partner_without_fallbacks_counts_none() -> None:
    world = World("paper2015")
    assert NoisyPartner(world, _Bare(), (0.3,)).fallbacks == 0
    assert CoveragePartner(world, _Bare()).fallbacks == 0
