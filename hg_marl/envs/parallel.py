"""The turn-based parallel view: one ``step`` plays a whole cycle (robot, then human).

Built on PettingZoo's ``aec_to_parallel`` (valid because every agent acts exactly once
per cycle and episodes end only at cycle boundaries), with a check that the actions
dict names exactly the live agents, so a missing or unknown agent gets a clear error.
"""

from __future__ import annotations

from typing import Any

from pettingzoo.utils.conversions import aec_to_parallel_wrapper

from hg_marl.envs.table_cleaning import env as aec_env


class AgentMismatchError(KeyError):
    """The actions dict of a parallel step does not name exactly the live agents."""

    def __str__(self) -> str:  # KeyError would repr() the message
        return str(self.args[0])


class TurnBasedParallelEnv(aec_to_parallel_wrapper):
    """``ParallelEnv`` over TableCleaning-v0: the human acts after seeing the robot's effect."""

    def step(self, actions: dict[str, Any]) -> tuple[dict, dict, dict, dict, dict]:
        live = set(self.aec_env.agents)
        if set(actions) != live:
            missing, extra = sorted(live - set(actions)), sorted(set(actions) - live)
            raise AgentMismatchError(
                f"parallel step needs one action for each live agent {sorted(live)}; "
                f"missing {missing}, unexpected {extra}"
            )
        return super().step(actions)


def parallel_env(**kwargs: Any) -> TurnBasedParallelEnv:
    """The parallel (one cycle per step) version of :func:`hg_marl.env`."""
    return TurnBasedParallelEnv(aec_env(**kwargs))
