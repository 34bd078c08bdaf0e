"""The values round 78's missed planted bugs changed, pinned after the round.

Round 78 planted 16 bugs in sixteen gated modules, written blind; 14 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the headroom's Python joint model re-draws a table from the scenario's layouts and the
  partner's first answer, a probability distribution: its re-draw probabilities sum to 1,
  and the policy optimal against a partner, played with that partner, reaches the
  oracle's optimum (the oracle builds its model on arrays, another enumeration);
- ``greedy_play`` plays every table for ``seconds`` simulated seconds (as ``ppo_recurrent``'s
  greedy play does): play stops when the slowest table has played them, not the fastest.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.headroom import JointModel
from hg_marl.agents.models.answers import stationary_human
from hg_marl.agents.oracle import oracle_rate
from hg_marl.core import World
from hg_marl.core.scenario import layout_count
from hg_marl.training.baselines import recurrent_ppo_sb3
from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config, greedy_play
from tests.agents.test_oracle import TINY

# one object on spot a or h, two robot starts (near, far): four initial layouts, each of probability 1/4
TWO_STARTS = TINY  # the oracle tests' one-object table, which has two robot starts


@pytest.mark.parametrize("spec", ["cooperative", "random"])
def test_the_python_joint_models_redraw_is_a_probability_distribution(spec: str) -> None:
    world = World(TWO_STARTS)
    assert layout_count(world.scenario) == 4, "the control: more than one layout, each less likely than 1"
    model = JointModel(world, [stationary_human(spec, world)])
    chain = model.chain(0)
    # a table is re-drawn with certainty: the layouts' probabilities times the first answers' sum to 1
    assert float(chain.regen_prob.sum()) == pytest.approx(1.0, abs=1e-12)
    # the policy optimal against the partner, played with it, is the oracle's optimum
    expected = oracle_rate(world, spec, cache=None).rate_per_hour
    assert expected > 0
    assert model.rate(model.optimal_policy(0), 0) == pytest.approx(expected, rel=1e-9)


class _Waits:
    """A stand-in model: the robot waits on every table (the partner plays on)."""

    def __init__(self, wait: int) -> None:
        self.wait = wait

    def predict(self, obs: Any, state: Any, episode_start: Any, deterministic: bool) -> tuple[Any, Any]:
        return np.full(len(obs), self.wait, dtype=np.int64), state


def test_greedy_play_plays_every_table_for_the_seconds_asked(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # Each table's simulated seconds are read from the env's own clock around every step (the
    # clock a table has when its cycle ends, before any re-draw), summed per table. The rule:
    # every table plays at least ``seconds``, and play stops at the first cycle where the last
    # of them gets there (one cycle earlier, some table was still short of it).
    pytest.importorskip("stable_baselines3")  # the SB3 VecEnv adapter greedy_play steps through
    config = RecurrentSb3Config(
        humans=("random",), scenario="forced_coordination", history=0, episode_seconds=40.0, out=tmp_path
    ).check()
    history: list[np.ndarray] = []
    make = recurrent_ppo_sb3.make_vec

    def spying(config: RecurrentSb3Config, num_envs: int) -> Any:
        venv = make(config, num_envs)
        env, step = venv.env, venv.env.step
        played = np.zeros(num_envs)

        def counted(action: Any) -> Any:
            before = env.clock.copy()
            out = step(action)
            played[:] += out[4]["clock"] - before
            history.append(played.copy())
            return out

        env.step = counted
        return venv

    monkeypatch.setattr(recurrent_ppo_sb3, "make_vec", spying)
    wait = World("forced_coordination").table.wait[0]
    seconds = 100.0
    greedy_play(_Waits(wait), config, num_envs=4, seconds=seconds, seed=0)
    assert len(history) >= 2
    assert history[-1].min() >= seconds, "every table played the seconds asked"
    assert history[-2].min() < seconds, "and play stopped as soon as the last one had"
    assert history[-1].max() > history[-1].min(), "the control: the tables' clocks differ"
