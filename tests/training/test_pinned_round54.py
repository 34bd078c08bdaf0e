"""Round 54's missed planted bugs, pinned (see mutation/README.md, "Fresh planted bugs")."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.content import registry_targets
from hg_marl.core.errors import ConfigError, ScenarioError
from hg_marl.core.registry import Entry, Registry
from hg_marl.core.scenario_file import parse_scenario
from hg_marl.training.baselines import heldout_curve
from hg_marl.training.baselines.heldout_curve import HeldOutCurve
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig

# --- training/baselines/heldout_curve.py ---


def test_checkpoints_fall_at_the_first_update_past_each_multiple_of_the_frequency(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # heldout_curve.py's module docstring: the policy is scored "At each checkpoint
    # (``checkpoint_freq``)", i.e. every 100 steps here: the first update at or past 100,
    # the first at or past 200, and so on, wherever the updates happen to end. Updates
    # ending at 64, 130, 192, 210, 290 and 300 steps: 130 is the first past 100, 210 the
    # first past 200, 300 the first at 300; 64, 192 and 290 are none (worked by hand). What
    # is scored is not the point here: the scoring (greedy_rate) and the tables (make_env)
    # are stubbed, so no network or torch is needed.
    monkeypatch.setattr(heldout_curve, "make_env", lambda config, n: None)
    monkeypatch.setattr(heldout_curve, "greedy_rate", lambda net, env, seconds, seed: 360.0)
    config = RecurrentConfig(humans=("cooperative",), scenario="paper2015", out=tmp_path).check()
    curve = HeldOutCurve(config, ("lazy",), every=100, oracle=False)
    for steps in (64, 130, 192, 210, 290, 300):
        curve(steps, None)
    assert [(r[0], r[1], r[2]) for r in curve.rows] == [
        (130, "train", "cooperative"),
        (130, "held_out", "lazy"),
        (210, "train", "cooperative"),
        (210, "held_out", "lazy"),
        (300, "train", "cooperative"),
        (300, "held_out", "lazy"),
    ]
    assert all(r[3] == 360.0 and r[4] is None and r[5] is None for r in curve.rows)  # no oracle: no BR-Prox


# --- hg_marl/core/scenario_file.py ---


def _coloured(bin_colours: list[str]) -> dict[str, Any]:
    """One red object on one mat, and a bin of each colour in ``bin_colours`` (all reachable)."""
    return {
        "name": "coloured",
        "robot_locations": ["near"],
        "handover_locations": ["near"],
        "objects": [{"name": "cup", "colour": "red"}],
        "bins": [
            {"name": f"bin{i}", "colour": c, "robot_reach": ["near"], "human_reach": True}
            for i, c in enumerate(bin_colours)
        ],
        "spots": [{"name": "mat", "robot_reach": ["near"], "human_reach": True}],
        "layout": [{"count": 1, "spots": ["mat"]}],
    }


def test_a_colourless_bin_accepts_a_coloured_object() -> None:
    # scenario_model.Bin.colour: "Objects of this colour go here; empty accepts objects of
    # any colour". So a red object with only a colourless bin loads, and goes to that bin
    # (bin_of: "the first bin that accepts its colour"); with a blue bin first and a
    # colourless one second it goes to the second; with only a blue bin nothing accepts it,
    # and the file is refused naming the object's colour field.
    assert parse_scenario(_coloured([""]), "one.toml", strict=True).bin_of == (0,)
    assert parse_scenario(_coloured(["blue", ""]), "two.toml", strict=True).bin_of == (1,)
    assert parse_scenario(_coloured(["red"]), "red.toml", strict=True).bin_of == (0,)
    with pytest.raises(ScenarioError, match=r"field 'objects\[0\]\.colour': no bin accepts colour 'red'"):
        parse_scenario(_coloured(["blue"]), "blue.toml", strict=True)


# --- agents/content.py ---


def test_registry_targets_of_named_entries_are_those_entries_modules_only() -> None:
    # content.py's registry_targets: "The modules the ``registries`` build their entries from
    # (only the entries ``names`` when given)". Two entries named by "module:attr" texts
    # (Entry.module reads the module part without importing it): asking for "clock" gives
    # clock's module only, for "check" check's only, for both (or all, names=None) the two,
    # sorted; for none of them nothing.
    widgets = Registry(
        "widget",
        ConfigError,
        [Entry("clock", "hg_marl.core.cycle:Clock"), Entry("check", "hg_marl.core.errors:check_int")],
    )
    assert registry_targets(widgets, names=["clock"]) == ("hg_marl.core.cycle",)
    assert registry_targets(widgets, names=["check"]) == ("hg_marl.core.errors",)
    assert registry_targets(widgets, names=["check", "clock"]) == ("hg_marl.core.cycle", "hg_marl.core.errors")
    assert registry_targets(widgets) == ("hg_marl.core.cycle", "hg_marl.core.errors")
    assert registry_targets(widgets, names=[]) == ()
