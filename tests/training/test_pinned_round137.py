"""Values that round 137's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import numpy as np

from hg_marl.agents.compiled import compile_human
from hg_marl.core import Agent, State, World
from hg_marl.core.spec import split_specs
from hg_marl.envs.batched import BatchedTable
from tests.env.test_pinned_batched import HUMAN_WAIT, ROBOT_WAIT, Always, _flags


def test_a_key_value_piece_after_a_spec_without_parameters_is_a_spec_of_its_own() -> None:
    # A bare "k=v" continues only a spec that has parameters (a ':' in it): after "cooperative"
    # there is no parameter list to continue, so "p_idle=0.5" stays its own piece (the
    # registry then refuses it by name) rather than turning the name into "cooperative,p_idle=0.5".
    assert split_specs("cooperative,p_idle=0.5") == ["cooperative", "p_idle=0.5"]
    assert split_specs("lazy:p_idle=0.5,accept=1,cooperative,k=2") == ["lazy:p_idle=0.5,accept=1", "cooperative", "k=2"]


def test_the_batched_tables_default_cycle_limit_is_500() -> None:
    # The signature's documented default, max_cycles=500. Both seats waiting on paper2015's
    # unfinished first table: no reward ever, each cycle lasts the 1 s wait, so the clock reads k
    # after k cycles and only the cycle limit can end the episode, on cycle 500 exactly.
    env = BatchedTable(Always(HUMAN_WAIT), 1, World("paper2015"))  # type: ignore[arg-type]
    env.reset(seed=0)
    flags = _flags(env, ROBOT_WAIT, 500)
    assert flags[:499] == [(False, False, float(k)) for k in range(1, 500)]
    assert flags[499] == (False, True, 500.0)


def test_a_compiled_partners_robot_masks_are_the_robots_feasible_actions_after_its_answer() -> None:
    # The compiled human's outcome hands the batched env the robot seat's mask at the state after
    # the human's answer; the single-table rules (World.mask for the robot) say what it must be.
    world = World("paper2015")
    partner = compile_human(world, "cooperative", cache=None)
    out = partner.outcome
    rows = np.random.default_rng(0).choice(len(out["mask"]), size=200, replace=False)
    for i in rows:
        after = State(
            tuple(int(p) for p in out["where"][i]),
            int(out["robot_at"][i]),
            int(out["offer_by"][i]),
            int(out["offer_obj"][i]),
        )
        assert out["mask"][i].astype(bool).tolist() == world.mask(after, Agent.ROBOT).astype(bool).tolist()
    # and so does the env that gathers them, step after step
    env = BatchedTable(partner, 8, world)
    env.reset(seed=1)
    rng = np.random.default_rng(1)
    for _ in range(20):
        masks = env.action_masks()
        for t in range(env.num_envs):
            assert masks[t].tolist() == world.mask(env.state.state(t), Agent.ROBOT).astype(bool).tolist()
        env.step(np.array([rng.choice(np.flatnonzero(m)) for m in masks]))
