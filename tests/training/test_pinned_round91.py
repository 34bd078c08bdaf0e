"""The values round 91's missed planted bugs changed, pinned after the round.

Round 91 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. The
value below is stated from the rule the training commands document (or a simpler
reference written here), not read from the code under test:

- ``hg-marl train --algo ppo_recurrent`` without ``--checkpoint-freq`` checkpoints every
  tenth of its step budget, as the SB3 path does ("a tenth of the budget",
  ``training/baselines/train.py``); a frequency given is kept as given.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hg_marl.training.baselines import ppo_recurrent
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig


def _checkpoint_freq(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, steps: int | None, checkpoint_freq: int | None
) -> int:
    """The checkpoint frequency of the config ``train_from_options`` trains with (nothing is trained)."""
    seen: list[RecurrentConfig] = []

    def fake_train(config: RecurrentConfig, **kwargs: Any) -> RecurrentConfig:
        seen.append(config)
        return config

    monkeypatch.setattr(ppo_recurrent, "train_recurrent", fake_train)
    monkeypatch.setattr(ppo_recurrent, "summary", lambda result, config: [])
    ppo_recurrent.train_from_options(
        humans=("cooperative",),
        scenario="paper2015",
        recipe="members",
        steps=steps,
        seed=0,
        out=tmp_path / "run",
        checkpoint_freq=checkpoint_freq,
        progress=False,
    )
    assert len(seen) == 1
    return seen[0].checkpoint_freq


def test_without_a_checkpoint_frequency_a_recurrent_run_checkpoints_every_tenth_of_its_steps(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    # Worked by hand: a tenth of 1,000 steps is 100, of 45,000 is 4,500; without --steps the
    # budget is the config's default (2,000,000 steps: RecurrentConfig.steps), a tenth 200,000.
    assert _checkpoint_freq(monkeypatch, tmp_path, 1000, None) == 100
    assert _checkpoint_freq(monkeypatch, tmp_path, 45_000, None) == 4500
    assert _checkpoint_freq(monkeypatch, tmp_path, None, None) == RecurrentConfig.steps / 10
    # Control: a frequency given is the one used, 0 (no checkpoints) included.
    assert _checkpoint_freq(monkeypatch, tmp_path, 1000, 70) == 70
    assert _checkpoint_freq(monkeypatch, tmp_path, 1000, 0) == 0
