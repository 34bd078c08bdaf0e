"""The comparison's summary: intervals over training seeds and rliable aggregates over humans (no training here)."""

from __future__ import annotations

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.baselines.comparison import CompareConfig, aggregates, format_table, summarise

ORACLE = 100.0
REFERENCES = {h: {"oracle": ORACLE, "planner": 96.0, "hybrid": 97.0} for h in ("lazy", "no_handover")}


def cell(algo: str, human: str, seed: int, final: float) -> dict:
    """A finished cell whose learning curve ends at ``final`` tasks/h."""
    return {"algo": algo, "human": human, "seed": seed, "curve": [[0, 0.0], [1000, final / 2], [2000, final]]}


def config(seeds: int) -> CompareConfig:
    return CompareConfig(algos=("ppo", "dqn"), humans=("lazy", "no_handover"), seeds=seeds)


def test_one_seed_has_no_interval() -> None:
    rows = summarise(config(1), [cell("ppo", "lazy", 0, 80.0)], REFERENCES)
    (ppo,) = [r for r in rows if r["agent"] == "ppo"]
    assert ppo["fraction"] == pytest.approx(0.8) and ppo["fraction_ci"] is None
    assert aggregates(config(1), [cell("ppo", "lazy", 0, 80.0)], {"lazy": ORACLE}) == {}


def test_equal_seeds_give_a_point_interval_and_spread_seeds_a_real_one() -> None:
    cells = [cell("ppo", "lazy", s, 80.0) for s in range(3)] + [
        cell("dqn", "lazy", s, rate) for s, rate in enumerate((20.0, 40.0, 60.0))
    ]
    rows = {r["agent"]: r for r in summarise(config(3), cells, REFERENCES) if r["human"] == "lazy"}
    assert rows["ppo"]["fraction_ci"] == pytest.approx([0.8, 0.8])
    low, high = rows["dqn"]["fraction_ci"]
    assert rows["dqn"]["fraction"] == pytest.approx(0.4)  # (0.2 + 0.4 + 0.6) / 3
    assert 0.2 <= low < 0.4 < high <= 0.6  # a mean of resampled seeds lies between the extremes
    assert rows["planner"]["fraction"] == pytest.approx(0.96) and rows["planner"]["fraction_ci"] is None
    assert "[0.80, 0.80]" in format_table(list(rows.values()))


def test_aggregates_rank_a_uniformly_better_algorithm_first() -> None:
    cells = [cell("ppo", h, s, 90.0) for h in ("lazy", "no_handover") for s in range(2)]
    cells += [cell("dqn", h, s, 10.0) for h in ("lazy", "no_handover") for s in range(2)]
    result = aggregates(config(2), cells, {"lazy": ORACLE, "no_handover": ORACLE})
    assert result["robots"]["ppo"]["iqm"] == pytest.approx(0.9)
    assert result["robots"]["ppo"]["iqm_ci"] == pytest.approx([0.9, 0.9])
    assert result["robots"]["dqn"]["mean"] == pytest.approx(0.1)
    assert result["improvement"]["ppo>dqn"]["p"] == pytest.approx(1.0)  # every ppo run beats every dqn run


def test_a_human_without_an_oracle_rate_is_left_out_of_the_aggregate() -> None:
    cells = [cell("ppo", "lazy", s, 50.0) for s in range(2)] + [cell("ppo", "switching", s, 5.0) for s in range(2)]
    result = aggregates(config(2), cells, {"lazy": ORACLE, "switching": None})
    assert result["robots"]["ppo"]["runs"] == 2 and result["robots"]["ppo"]["mean"] == pytest.approx(0.5)


@pytest.mark.parametrize(
    ("field", "value", "option"),
    [
        ("seeds", 0, "--seeds"),
        ("steps", 1.5, "--steps"),
        ("duration", float("nan"), "--duration"),
        ("eval_seeds", (), "--eval-seeds"),
    ],
)
def test_bad_settings_name_their_option(field: str, value: object, option: str) -> None:
    with pytest.raises(ConfigError, match=option):
        CompareConfig(**{field: value})  # type: ignore[arg-type]


def test_steps_to_a_level_need_every_seed_to_reach_it() -> None:
    # curves (0, 0), (1000, final / 2), (2000, final) against an oracle of 100: final 100 reaches
    # 50 at 1000 steps and 90 at 2000; final 80 reaches 50 at 2000 and never 90. Both seeds reach
    # 50 (median of 1000 and 2000: 1500); one seed never reaches 90: no figure, not the other's 2000
    cells = [cell("ppo", "lazy", 0, 100.0), cell("ppo", "lazy", 1, 80.0)]
    (ppo,) = [r for r in summarise(config(2), cells, REFERENCES) if r["agent"] == "ppo" and r["human"] == "lazy"]
    assert ppo["steps_to_50"] == pytest.approx(1500.0)
    assert ppo["steps_to_90"] is None
