"""Values that round 199's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hg_marl.agents.observed_partner import ObservedPartner
from hg_marl.core import World
from tests.agents.test_observed_partner import first_state
from tests.training.test_pinned_round37 import train_clocked


def test_the_observed_partner_forgets_a_keys_counts_by_0_8_per_visit_by_default() -> None:
    # docs/adaptation.md: the observed partner's counts forget 0.8 per visit of their key, and a
    # seen key's predictive is (n_a + 0.5 * base(a)) / (N + 0.5). No base: uniform over the n
    # feasible answers. Worked by hand: answer a, then b at the same key; a's count is forgotten
    # to 0.8, b's is 1, N = 1.8: p(a) = (0.8 + 0.5 / n) / 2.3, p(b) = (1 + 0.5 / n) / 2.3.
    world = World("forced_coordination")
    mid, wait, feasible = first_state(world)
    n = len(feasible)
    a, b = feasible[0], feasible[1]
    model = ObservedPartner()  # the defaults
    model.update(world, mid, wait, a)
    model.update(world, mid, wait, b)
    assert model.counts[(mid, wait)] == pytest.approx({a: 0.8, b: 1.0})
    assert model.predict(world, mid, wait, a) == pytest.approx((0.8 + 0.5 / n) / 2.3)
    assert model.predict(world, mid, wait, b) == pytest.approx((1 + 0.5 / n) / 2.3)


def test_a_recurrent_model_file_names_the_recipe_it_was_trained_with(tmp_path: Path) -> None:
    # Trained with the hsp recipe on paper2015, the header's recipe is "hsp" (its scenario is
    # another field): what the run was asked, not another option's value.
    result = train_clocked(tmp_path, recipe="hsp")
    header = json.loads(result.path.read_text())
    assert header["recipe"] == "hsp"
