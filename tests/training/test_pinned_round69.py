"""The values round 69's missed planted bugs changed (``mutation/planted.py``, FRESH69), pinned.

Each expected value is worked by hand from the module's documented behaviour, not read off the code.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np
import pytest

from hg_marl.agents.compiled import compile_human
from hg_marl.core import World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import BatchState
from hg_marl.training.baselines.envs import EnvSpec, make_vec_env
from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config
from hg_marl.training.play.session import PlaySession


def test_a_vector_env_asked_for_seed_0_seeds_its_members_0_1_2() -> None:
    # make_vec_env's docstring: the members are "seeded seed, seed + 1, ...", and a view's
    # reset(seed=s) "seeds the table and the partner's own generator from s". So with seed 0
    # member i starts as a view reset by hand with seed i: the same first observation and the
    # same generator state (an unseeded member would draw its generator from fresh entropy).
    spec = EnvSpec()
    vec = make_vec_env(spec, 3, seed=0)
    obs = vec.reset()
    for i in range(3):
        alone = spec.make()
        first, _ = alone.reset(seed=i)
        assert np.array_equal(obs[i], first)
        member = vec.envs[i].unwrapped
        assert member.np_random.bit_generator.state == alone.np_random.bit_generator.state


def test_a_compiled_human_falls_back_to_the_live_human_on_a_key_past_its_last() -> None:
    # The module docstring: "A state outside the table ... falls back to the live human, counted
    # in fallbacks." The human's own offer of the last object (offer_by 1, offer_obj n - 1) is
    # outside a human's table (the human answers mid-cycle, its own offers having lapsed), and
    # its packed key has the two most significant digits at their largest values, so it sorts
    # past every key of the table: each of the three tables is answered by the live lazy human,
    # with an action its live distribution gives weight.
    world = World("paper2015")
    table = compile_human(world, "lazy", cache=None)
    states = [world.initial_state(np.random.default_rng(s)) for s in range(3)]
    batch = BatchState.of(states)
    batch.offer_by[:], batch.offer_obj[:] = 1, world.table.n_objects - 1
    assert (table.packer.pack(batch, np.full(3, -1)) > table.keys.max()).all()  # the premise
    actions = table.act(batch, np.array([3, 5, 7]), np.random.default_rng(0))
    assert table.fallbacks == 3
    for i, action in enumerate(actions.tolist()):
        support = {a for a, p in table.human.distribution(world, batch.state(i), -1) if p > 0}
        assert action in support


def _readings(values: list[float]) -> Callable[[], float]:
    it: Iterator[float] = iter(values)
    return lambda: next(it)


def test_a_sessions_mean_response_time_is_the_mean_not_the_median() -> None:
    # The wall clock is read when the choice is shown (after the robot's turn) and when the
    # person answers. Readings 0 | 1, 1 | 3, 3 | 9 give response times 1, 2 and 6 seconds: by
    # hand their mean is 3.0 (their median would be 2.0).
    session = PlaySession("random", seed=0, player="tester", timer=_readings([0.0, 1.0, 1.0, 3.0, 3.0, 9.0, 9.0]))
    for _ in range(3):
        session.play("wait")
    assert session.response_times == [1.0, 2.0, 6.0]
    assert session.summary()["mean_response_time"] == pytest.approx(3.0)


@pytest.mark.parametrize("field", ["learning_rate", "episode_seconds"])
def test_the_recurrent_sb3_run_refuses_a_zero_learning_rate_or_episode_length(field: str) -> None:
    # RecurrentSb3Config.check's rule: learning_rate and episode_seconds are "a finite positive
    # number"; 0 is not positive, so it is refused with the field's name.
    with pytest.raises(ConfigError, match=f"{field}: expected a finite positive number, got 0"):
        RecurrentSb3Config(**{field: 0}).check()
