"""The values round 94's missed planted bugs changed, pinned after the round.

Round 94 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- a PPO-like rollout needs ``n_steps x n_envs >= 2`` (a rollout of one step has no
  advantage to normalise); recurrent PPO is PPO with an LSTM policy, so the rule holds for
  ``recurrent_ppo`` as for ``ppo`` and ``maskable_ppo``: 1 x 1 refused, 1 x 2 and 2 x 1 kept.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.training.baselines.hyperparams import HyperparamError, load_hyperparams


def _yaml(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "recurrent_ppo.yml"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_recurrent_ppo_rollout_of_one_step_is_refused(tmp_path: Path) -> None:
    """``n_steps x n_envs`` of 1 x 1 refused for recurrent PPO (worked by hand from the rule above)."""
    with pytest.raises(HyperparamError, match=r"recurrent_ppo: n_steps x n_envs must be at least 2"):
        load_hyperparams("recurrent_ppo", path=_yaml(tmp_path, "default:\n  n_steps: 1\n  n_envs: 1\n"))
    # the controls: a product of 2 either way is a rollout of two steps, kept
    two_envs = load_hyperparams("recurrent_ppo", path=_yaml(tmp_path, "default:\n  n_steps: 1\n  n_envs: 2\n"))
    assert (two_envs.n_envs, two_envs.kwargs["n_steps"]) == (2, 1)
    two_steps = load_hyperparams("recurrent_ppo", path=_yaml(tmp_path, "default:\n  n_steps: 2\n"))
    assert (two_steps.n_envs, two_steps.kwargs["n_steps"]) == (1, 2)
