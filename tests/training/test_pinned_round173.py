"""Values that round 173's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
import math
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.content import canonical, content_key
from hg_marl.agents.habit import QLearnerConfig
from hg_marl.agents.robots import HabitRobot
from hg_marl.core import Agent, World
from hg_marl.core.scenario import available_scenarios, load_scenario, resolve_scenario
from hg_marl.training import backends
from hg_marl.training.store import Job


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_a_setting_that_is_not_a_finite_number_gets_no_content_key(bad: float) -> None:
    # "Equal inputs, equal text": NaN is not equal to itself, and JSON has no literal for it or
    # for infinity, so the canonical document refuses them (ValueError) rather than writing
    # NaN / Infinity, whether at the top or inside a list.
    with pytest.raises(ValueError):
        canonical({"rate": bad})
    with pytest.raises(ValueError):
        canonical({"rates": [1.0, bad]})
    with pytest.raises(ValueError):
        content_key("test", {"rate": bad}, ())
    assert canonical({"rate": 1.5}) == '{"rate":1.5}'


def test_the_habits_proposal_is_the_boltzmann_of_its_own_beta() -> None:
    # q_config beta=1 (the default habit's is 50). Q is 0 on every action but one, ln 3 on it:
    # exp(1 * ln 3) = 3 against exp(0) = 1 for each of the N - 1 others, so that action has
    # 3 / (N + 2) and each other 1 / (N + 2). With beta 50 it would have nearly all of it.
    world = World("paper2015")
    robot = HabitRobot(q_config=QLearnerConfig(beta=1.0), learn=False)
    robot.reset(world, Agent.ROBOT, np.random.default_rng(0))
    n = world.n_actions(Agent.ROBOT)
    q = np.zeros(n)
    q[2] = math.log(3.0)
    robot.habit.q_values = lambda facts: q.copy()
    facts = world.facts(world.initial_state(np.random.default_rng(0)))
    values, probs, _, _ = robot._habit_proposal(facts)
    assert np.allclose(values, q)
    expected = np.full(n, 1.0 / (n + 2))
    expected[2] = 3.0 / (n + 2)
    assert np.allclose(probs, expected)


def test_every_bundled_scenario_is_a_built_in_name_that_loads() -> None:
    # The module docstring names four built-ins, one TOML file each in hg_marl.core.scenarios;
    # each name resolves to itself as a built-in, is listed as accepted, and loads under its name.
    bundled = sorted(
        Path(f.name).stem for f in resources.files("hg_marl.core.scenarios").iterdir() if f.name.endswith(".toml")
    )
    assert bundled == ["asymmetric_advantages", "forced_coordination", "paper2015", "roboergosum"]
    for name in bundled:
        assert resolve_scenario(name) == ("builtin", name)
        assert name in available_scenarios()
        assert load_scenario(name).name == name


class _Stop(Exception):
    pass


def oracle_inputs(monkeypatch: pytest.MonkeyPatch, job: Job, path: Path, contents: tuple[bytes, ...]) -> list[str]:
    """The cache inputs a worker's oracle job is solved under, ``path`` holding each of ``contents`` in turn."""
    seen: list[str] = []

    def record(scenario: str, human: Any, inputs: str) -> Any:
        seen.append(inputs)
        raise _Stop

    monkeypatch.setattr(backends, "_oracle_policy", record)
    for content in contents:
        path.write_bytes(content)
        with pytest.raises(_Stop):
            backends.execute(job)
    return seen


def test_an_oracle_job_keys_its_solution_by_the_files_its_humans_parameters_name(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A policy file named by the human's parameters (learned:path=FILE) is part of what the
    # worker's oracle solution is kept by: two contents of the file, two sets of inputs, each
    # holding the SHA-256 of the bytes the file held (worked here with hashlib).
    policy = tmp_path / "policy.npz"
    job = Job(robot="oracle", seed=0, duration=20.0, human="learned", human_params={"path": str(policy)})
    contents = (b"first weights", b"second weights")
    seen = oracle_inputs(monkeypatch, job, policy, contents)
    assert all(hashlib.sha256(c).hexdigest() in inputs for c, inputs in zip(contents, seen, strict=True))
    assert len(seen) == 2 and seen[0] != seen[1]
