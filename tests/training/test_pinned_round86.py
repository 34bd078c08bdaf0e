"""The values round 86's missed planted bugs changed, pinned after the round.

Round 86 planted 16 bugs in sixteen gated modules, written blind; 14 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- the parallel view's actions dict must name exactly the *live* agents: once an episode
  is over (PettingZoo empties ``agents``), an empty dict is exactly right and steps to
  five empty dicts (PettingZoo's parallel API), while a dict naming both seats names two
  agents that are no longer live and is refused naming them as unexpected;
- a robot given as an object must be an ``Actor``, which the protocol defines as having
  both ``reset`` and ``act``: an object with ``act`` alone is refused with the one-line
  ``ValueError`` every other non-Actor gets.
"""

from __future__ import annotations

from typing import Any

import pytest

from hg_marl.agents.partner_specs import make_robot_actor
from hg_marl.envs.parallel import AgentMismatchError, parallel_env


def _finished_parallel_env() -> Any:
    """A parallel view played to its end: ``max_cycles=1`` truncates after one cycle (one step)."""
    env = parallel_env(max_cycles=1)
    obs, _ = env.reset(seed=0)
    assert sorted(env.agents) == ["human", "robot"]
    # wait is always feasible; the last action of each seat's mask is taken, whatever it is
    actions = {a: int(obs[a]["action_mask"].nonzero()[0][-1]) for a in env.agents}
    env.step(actions)
    assert env.agents == []  # the episode is over: no agent is live
    return env


def test_a_finished_parallel_episode_steps_an_empty_dict_to_empty_dicts() -> None:
    # By the rule (the dict names exactly the live agents, and none is live), {} is accepted;
    # PettingZoo's parallel step then answers five dicts over the live agents: all empty.
    env = _finished_parallel_env()
    observations, rewards, terminations, truncations, infos = env.step({})
    assert [dict(d) for d in (observations, rewards, terminations, truncations, infos)] == [{}, {}, {}, {}, {}]


def test_a_finished_parallel_episode_refuses_actions_for_agents_no_longer_live() -> None:
    # Both seats are named but neither is live: nothing is missing, both are unexpected.
    env = _finished_parallel_env()
    with pytest.raises(AgentMismatchError, match=r"missing \[\], unexpected \['human', 'robot'\]"):
        env.step({"robot": 0, "human": 0})


class _ActOnly:
    """Has ``act`` but no ``reset``: not an Actor (the protocol requires both)."""

    def act(self, turn: Any) -> int:
        return 0


def test_a_robot_object_with_act_but_no_reset_is_refused() -> None:
    with pytest.raises(ValueError, match="expected a robot name or an Actor"):
        make_robot_actor(_ActOnly())
