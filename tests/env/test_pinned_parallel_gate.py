"""The turn-based parallel view's action check and its options, pinned for the mutation gate.

Expected values from the module's docstring, worked by hand: a step needs exactly one
action per live agent (``robot`` and ``human``); any other set of names, a subset, a
superset or one name swapped for another, is refused with ``AgentMismatchError`` naming
the missing and the unexpected agents sorted, before anything is played; ``parallel_env``
hands its keyword arguments to the AEC environment.
"""

from __future__ import annotations

import pytest

from hg_marl.core import Agent, World
from hg_marl.envs.parallel import AgentMismatchError, TurnBasedParallelEnv, parallel_env


def _waits() -> dict[str, int]:
    """Both agents wait: the robot's last action, the human's ``wait`` (paper2015's names)."""
    world = World("paper2015")
    return {"robot": world.n_actions(Agent.ROBOT) - 1, "human": world.action_names[Agent.HUMAN].index("wait")}


def test_a_swapped_agent_name_of_the_right_count_is_refused_before_anything_is_played() -> None:
    """Two names for two agents, but one unknown: neither a subset nor a superset of the live agents."""
    env = parallel_env()
    env.reset(seed=0)
    with pytest.raises(AgentMismatchError) as info:
        env.step({"robot": 0, "dog": 0})
    assert str(info.value) == (
        "parallel step needs one action for each live agent ['human', 'robot']; missing ['human'], unexpected ['dog']"
    )
    assert env.unwrapped.cycles == 0


def test_a_subset_and_a_superset_are_each_refused_and_the_exact_set_plays() -> None:
    """Missing the human alone, then one agent too many, then exactly the two: only the last plays a cycle."""
    env = parallel_env()
    env.reset(seed=0)
    waits = _waits()
    with pytest.raises(AgentMismatchError, match=r"missing \['human'\], unexpected \[\]$"):
        env.step({"robot": waits["robot"]})
    with pytest.raises(AgentMismatchError, match=r"missing \[\], unexpected \['cat'\]$"):
        env.step({**waits, "cat": 0})
    assert env.unwrapped.cycles == 0
    env.step(dict(waits))
    assert env.unwrapped.cycles == 1


def test_the_error_is_a_key_error_whose_text_has_no_quotes_around_it() -> None:
    """``AgentMismatchError`` is a ``KeyError`` (callers may catch that) but prints its message as is."""
    error = AgentMismatchError("no such agent")
    assert isinstance(error, KeyError)
    assert str(error) == "no such agent"


def test_parallel_env_hands_its_options_to_the_aec_environment() -> None:
    """``max_cycles=2``: two waiting cycles, and the second truncates both agents."""
    env = parallel_env(max_cycles=2)
    assert isinstance(env, TurnBasedParallelEnv)
    env.reset(seed=0)
    _, _, _, truncations, _ = env.step(_waits())
    assert truncations == {"robot": False, "human": False}
    _, _, _, truncations, _ = env.step(_waits())
    assert truncations == {"robot": True, "human": True}
    assert env.agents == []
