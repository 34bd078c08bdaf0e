"""The population recipes' partners: which checkpoints ``fcp_init`` draws and how its first one plays."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("torch")

from hg_marl.core import Agent, World
from hg_marl.core.batch import BatchedRules
from hg_marl.training.baselines.recipes import recipe_partner


def test_fcp_init_adds_the_first_checkpoint_a_uniformly_random_partner(tmp_path: Path) -> None:
    world = World("asymmetric_advantages")
    partner = recipe_partner(world, ("preference",), "fcp_init", tmp_path)
    rng = np.random.default_rng(0)
    n = 8000
    partner.reset_rows(np.arange(n), rng)
    # FCP's pool: the final member (eps 0), two less skilled versions (0.3, 0.6) and the
    # first checkpoint, a random policy (eps 1); each table draws one of the four uniformly
    levels, counts = np.unique(partner.eps, return_counts=True)
    assert levels.tolist() == [0.0, 0.3, 0.6, 1.0]
    sd = np.sqrt(n * 0.25 * 0.75)
    assert np.all(np.abs(counts - n / 4) < 4 * sd)

    rules = BatchedRules(world)
    batch = rules.initial(rng, n)
    mask = rules.masks(batch, Agent.HUMAN)
    # At every reset: a tape on each mat and two in the middle. The human reaches its mat and
    # both middle spots, so it may pick any of those three tapes or wait: 4 feasible actions.
    assert np.all(mask.sum(axis=1) == 4)
    wait = world.table.wait[Agent.HUMAN]
    answers = partner.act(batch, np.full(n, -1), rng)
    assert np.all(mask[np.arange(n), answers])
    first = partner.eps == 1.0
    # the random checkpoint waits a quarter of the time (1 of its 4 feasible actions) ...
    share = np.mean(answers[first] == wait)
    assert abs(share - 0.25) < 4 * np.sqrt(0.25 * 0.75 / first.sum())
    # ... where the member itself (eps 0) starts on a tape every time
    assert np.all(answers[partner.eps == 0.0] != wait)


@pytest.mark.parametrize(
    ("population", "scenario"),
    [("hard_layouts", "asymmetric_advantages"), ("paper2015", "paper2015"), ("roboergosum", "roboergosum")],
)
def test_hsp_partners_are_drawn_apart_from_every_bundled_population(population: str, scenario: str) -> None:
    from hg_marl.agents.humans.population import load_population
    from hg_marl.training.baselines.recipes import HSP_PARTNERS, hsp_partners

    drawn = hsp_partners(World(scenario))
    assert len(set(drawn)) == HSP_PARTNERS == 8
    assert all(spec.startswith("preference:") for spec in drawn)
    # the bundled populations were drawn from the generator's seed 0: had the recipe drawn
    # from it too, their held-out members would be among its training partners
    path = Path(__file__).parents[2] / "populations" / f"{population}.toml"
    members = {str(m.spec) for m in load_population(path).members()}
    assert not members & set(drawn)


def test_hsp_recipe_plays_the_members_and_the_drawn_partners(tmp_path: Path) -> None:
    world = World("asymmetric_advantages")
    members = ("preference", "preference:handover=1.0,shared=-0.5")
    partner = recipe_partner(world, members, "hsp", tmp_path)
    # two members and eight drawn partners, one compiled table each, drawn per table at reset
    assert len(partner.members) == 2 + 8
    rng = np.random.default_rng(0)
    n = 5000
    partner.reset_rows(np.arange(n), rng)
    counts = np.bincount(partner.member[:n], minlength=10)
    sd = np.sqrt(n * 0.1 * 0.9)
    assert np.all(np.abs(counts - n / 10) < 4 * sd)
