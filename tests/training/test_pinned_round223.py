"""Values that round 223's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

from hg_marl.training.baselines.hyperparams import load_hyperparams
from tests.training.test_pinned_baselines_hyperparams_gate import _yaml


def test_a_dotted_override_creates_the_mapping_the_entry_lacks(tmp_path: Path) -> None:
    # The entry has no ``policy_kwargs`` at all: the module's docstring says dotted keys nest,
    # so ``policy_kwargs.net_arch=[8, 8]`` makes the mapping {"net_arch": [8, 8]} and
    # ``policy_kwargs.ortho_init=false`` adds to that same new mapping; ``gamma`` is kept.
    path = _yaml(tmp_path, "default:\n  gamma: 0.9\n")
    hp = load_hyperparams(
        "ppo", path=path, overrides=["policy_kwargs.net_arch=[8, 8]", "policy_kwargs.ortho_init=false"]
    )
    assert hp.kwargs == {"gamma": 0.9, "policy_kwargs": {"net_arch": [8, 8], "ortho_init": False}}
