"""Values that round 142's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import gymnasium

from hg_marl.agents.views import HumanView
from hg_marl.core import Agent, World
from hg_marl.training.baselines.envs import EnvSpec


def test_the_human_seat_observes_as_the_spec_says() -> None:
    # The spec's observation mode reaches the human seat's view as it does the robot seat's. On
    # paper2015, "flat" is the facts followed by the human's action mask: one int8 vector of
    # n_facts + n_actions(HUMAN) entries (the world's own counts, not the view's); "dict" is the
    # AEC environment's Dict of observation and action_mask. A view left at "facts" has n_facts.
    world = World("paper2015")
    flat = EnvSpec(seat="human", partners=("planner",), observation="flat").make()
    assert isinstance(flat, HumanView) and flat.observation_mode == "flat"
    assert flat.observation_space.shape == (world.n_facts + world.n_actions(Agent.HUMAN),)
    obs, _ = flat.reset(seed=3)
    assert obs.shape == (world.n_facts + world.n_actions(Agent.HUMAN),)
    as_dict = EnvSpec(seat="human", partners=("planner",), observation="dict").make()
    assert as_dict.observation_mode == "dict"
    assert isinstance(as_dict.observation_space, gymnasium.spaces.Dict)
    assert set(as_dict.observation_space.spaces) == {"observation", "action_mask"}
    assert HumanView("paper2015", robot="planner").observation_space.shape == (world.n_facts,)
