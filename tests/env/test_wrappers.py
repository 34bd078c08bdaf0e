"""The library-facing wrappers: PettingZoo's own test suites, and what each wrapper promises."""

from __future__ import annotations

import warnings
from collections.abc import Callable

import numpy as np
import pytest
from pettingzoo import AECEnv
from pettingzoo.test import api_test, parallel_api_test

import hg_marl
from hg_marl.envs import InvalidActionError
from hg_marl.wrappers import audit_v0, flatten_v0, homogenize_v0, to_parallel
from tests.env.seeded_spaces import seeded

N_FACTS = 24  # paper2015: the paper's boolean facts
N_ROBOT, N_HUMAN = 18, 31  # paper2015's action counts

STACKS: dict[str, Callable[[], AECEnv]] = {
    "homogenize-int8": lambda: homogenize_v0(hg_marl.env()),
    "homogenize-float32": lambda: homogenize_v0(hg_marl.env(), dtype=np.float32),
    "flatten-obs": lambda: flatten_v0(hg_marl.env()),
    "flatten-info": lambda: flatten_v0(hg_marl.env(), mask="info"),
    "rllib": lambda: flatten_v0(homogenize_v0(hg_marl.env())),
    "supersuit": lambda: flatten_v0(homogenize_v0(audit_v0(hg_marl.env())), mask="info"),
}


@pytest.mark.parametrize("name", sorted(STACKS))
def test_stack_passes_pettingzoo_api_test(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # naming/style recommendations only
        api_test(seeded(STACKS[name]()), num_cycles=60)


@pytest.mark.parametrize("name", sorted(STACKS))
def test_stack_passes_pettingzoo_parallel_api_test(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        parallel_api_test(seeded(to_parallel(STACKS[name]())), num_cycles=60)


def test_homogenised_spaces_are_shared_and_padded() -> None:
    env = homogenize_v0(hg_marl.env())
    raw = hg_marl.env()
    assert env.action_space("robot") == env.action_space("human")
    assert env.action_space("robot").n == max(N_ROBOT, N_HUMAN)
    assert env.observation_space("robot") == env.observation_space("human")
    env.reset(seed=3)
    raw.reset(seed=3)
    for agent, agent_id in (("robot", [1, 0]), ("human", [0, 1])):
        obs = env.observe(agent)
        real = raw.observe(agent)
        n_real = raw.action_space(agent).n
        assert obs["observation"].shape == (N_FACTS + 2,)
        np.testing.assert_array_equal(obs["observation"][:N_FACTS], real["observation"])
        np.testing.assert_array_equal(obs["observation"][N_FACTS:], agent_id)
        np.testing.assert_array_equal(obs["action_mask"][:n_real], real["action_mask"])
        assert not obs["action_mask"][n_real:].any()


def test_padded_action_acts_as_an_infeasible_action() -> None:
    env = homogenize_v0(hg_marl.env())
    env.reset(seed=0)
    before = env.unwrapped.world_state
    env.step(N_ROBOT)  # first padded index of the robot
    assert env.unwrapped.world_state == before
    assert env.infos["robot"]["failed"] is True


def test_out_of_range_action_is_still_rejected() -> None:
    env = homogenize_v0(hg_marl.env())
    env.reset(seed=0)
    with pytest.raises(InvalidActionError, match="out of range"):
        env.step(N_HUMAN)


def test_flat_view_puts_the_mask_where_asked() -> None:
    raw = hg_marl.env()
    in_obs = flatten_v0(hg_marl.env(), obs_key="obs", mask_key="mask")
    in_info = flatten_v0(hg_marl.env(), mask="info")
    for env in (raw, in_obs, in_info):
        env.reset(seed=5)
    real = raw.observe("human")
    obs = in_obs.observe("human")
    assert set(obs) == {"obs", "mask"} and obs["obs"].dtype == np.float32
    np.testing.assert_array_equal(obs["obs"], real["observation"].astype(np.float32))
    np.testing.assert_array_equal(obs["mask"], real["action_mask"])
    flat = in_info.observe("human")
    assert isinstance(flat, np.ndarray) and flat.shape == (N_FACTS,)
    np.testing.assert_array_equal(in_info.infos["human"]["action_mask"], real["action_mask"])


def test_audit_counts_infeasible_actions_against_the_real_mask() -> None:
    env = audit_v0(hg_marl.env())
    env.reset(seed=0)
    throw = env.unwrapped.action_names("robot").index("throw(tape1)")  # holds nothing yet
    env.step(throw)
    feasible = int(np.flatnonzero(env.observe("human")["action_mask"])[0])
    env.step(feasible)
    assert env.sent == {"robot": 1, "human": 1}
    assert env.infeasible == {"robot": 1, "human": 0}


@pytest.mark.parametrize("bad", [{"dtype": np.int64}, {"mask": "nowhere"}, {"obs_key": "x", "mask_key": "x"}])
def test_bad_wrapper_option_gets_one_line_naming_it(bad: dict) -> None:
    with pytest.raises(ValueError, match=next(iter(bad)).split("_")[0]):
        flatten_v0(hg_marl.env(), **bad)


def test_audit_totals_count_copies_that_vector_builders_make() -> None:
    import copy

    from hg_marl.wrappers import AUDITS, audit_totals

    AUDITS.clear()
    original = audit_v0(hg_marl.env())
    clone = copy.deepcopy(original)  # as SuperSuit's concat_vec_envs_v1 may do
    clone.reset(seed=0)
    clone.step(int(np.flatnonzero(clone.observe("robot")["action_mask"])[0]))
    sent, infeasible = audit_totals()
    assert sent == {"robot": 1, "human": 0} and infeasible == {"robot": 0, "human": 0}
