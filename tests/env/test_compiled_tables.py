"""The compiled partners' tables, built by the model builder, equal the Python enumeration's.

Expected values: ``tests/agents/reference_compiled.py`` (the compiler before it used the
builder: one state at a time, one live answer per key, ``cum`` per key with numpy).
"""

from __future__ import annotations

import numpy as np
import pytest

from hg_marl.agents.compiled import CompiledHuman, answer_table, compile_human
from hg_marl.agents.humans.registry import make_human
from hg_marl.core import Agent, World
from tests.agents.reference_compiled import enumerate_answers, reference_arrays


def live(spec: str, world: World):  # type: ignore[no-untyped-def]
    human = make_human(spec)
    human.reset(world, Agent.HUMAN, np.random.default_rng(0))
    return human


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination"])
@pytest.mark.parametrize(
    ("spec", "closure"),
    [
        ("cooperative", ()),
        ("lazy", ()),
        ("random", ()),
        ("noisy", ()),
        ("preference:accept=0.5,p_idle=0.3", ()),
        ("cooperative:p_idle=0.2", ()),
        ("lazy", ("no_handover", "adversarial")),
    ],
)
def test_the_builders_table_is_the_python_enumerations(scenario: str, spec: str, closure: tuple[str, ...]) -> None:
    world = World(scenario)
    expected = reference_arrays(
        world, enumerate_answers(world, live(spec, world), closure=[live(c, world) for c in closure])
    )
    got = CompiledHuman.arrays_of(
        world, answer_table(world, live(spec, world), closure=[live(c, world) for c in closure])
    )
    for field in ("keys", "starts", "actions", "cum"):
        assert np.array_equal(got[field], expected[field]), field


def test_a_table_over_the_key_budget_is_refused_in_one_line() -> None:
    from hg_marl.agents.compiled import CompileError

    world = World("paper2015")
    n = len(enumerate_answers(world, live("random", world)))
    with pytest.raises(CompileError, match="budget of"):
        compile_human(world, "random", cache=None, max_keys=n - 1)
    assert len(compile_human(world, "random", cache=None, max_keys=n)) == n


def test_a_machine_short_of_memory_is_named_not_blamed_on_the_key_budget(monkeypatch: pytest.MonkeyPatch) -> None:
    """The builder stopped because the machine had too little memory left: the refusal says so.

    Blaming the compiler's ``max_keys`` would have the user shrink a table that fits.
    """
    import hg_marl.agents.models as models
    from hg_marl.agents.compiled import CompileError

    real = models.build_model

    def short_of_memory(*args, budget, **kwargs):
        budget.free_memory = lambda: 0  # the machine reports no memory left
        return real(*args, budget=budget, **kwargs)

    monkeypatch.setattr(models, "build_model", short_of_memory)
    world = World("paper2015")
    with pytest.raises(CompileError) as refused:
        answer_table(world, live("random", world))
    message = str(refused.value)
    assert message.startswith(
        "scenario: 'paper2015' against 'random' is over its budget of the machine: less than 512 MB of memory left"
    )
    assert "max_keys" not in message and "\n" not in message


@pytest.mark.parametrize("scenario", ["paper2015", "forced_coordination", "generated:objects=2,seed=4,human_only=0.8"])
def test_the_compiled_robots_states_are_the_python_enumerations(scenario: str) -> None:
    from hg_marl.agents.compiled_robot import robot_states
    from hg_marl.agents.models import StatePacker
    from tests.agents.reference_compiled import reference_robot_states

    world = World(scenario)
    keys = robot_states(world)
    b, _ = StatePacker(world).unpack(keys)
    assert {b.state(i) for i in range(len(b))} == reference_robot_states(world)
    assert len(set(keys.tolist())) == len(keys)


def test_the_compiled_robots_table_is_the_cold_planners_answer_on_sampled_states() -> None:
    from hg_marl.agents.compiled_robot import compile_robot, planner_action
    from hg_marl.envs.batched import BatchState

    world = World("paper2015")
    robot = compile_robot(world, cache=None)
    rng = np.random.default_rng(3)
    from hg_marl.agents.models import StatePacker

    b, _ = StatePacker(world).unpack(robot.keys[rng.choice(len(robot.keys), size=40, replace=False)])
    states = [b.state(i) for i in range(len(b))]
    actions, found = robot.plan(BatchState.of(states))
    assert found.all() and actions.tolist() == [planner_action(world, s) for s in states]


class _Draws:
    """Stands in for the generator: every draw is ``u``."""

    def __init__(self, u: float) -> None:
        self.u = u

    def random(self, n: int) -> np.ndarray:
        return np.full(n, self.u)


def test_a_draw_just_under_one_is_the_last_answer_of_its_own_state() -> None:
    """The largest float under 1 picks each state's last answer, never the next state's first.

    ``q = index + u`` rounds up to ``index + 1`` for an index of 1 or more, equal to the last
    entry's cumulative sum: only the segment's own end keeps the draw in it. Expected: the live
    random human's last possible answer (the table keeps its order); a draw of 0 its first.
    """
    from hg_marl.envs.batched import BatchedRules

    world = World("paper2015")
    compiled = compile_human(world, "random", cache=None)
    human = live("random", world)
    batch = BatchedRules(world).initial(np.random.default_rng(5), 64)
    seen = np.full(64, -1)
    idx, found = compiled.lookup(batch, seen)
    sizes = compiled.starts[idx + 1] - compiled.starts[idx]
    assert found.all() and ((idx >= 1) & (sizes < compiled.widest)).any()  # the case the end guards
    for u, pick in ((np.nextafter(1.0, 0.0), -1), (0.0, 0)):
        pos, _ = compiled.answer(batch, seen, _Draws(u))
        for i in range(64):
            answers = [a for a, p in human.distribution(world, batch.state(i), -1) if p > 0]
            assert compiled.actions[pos[i]] == answers[pick]
            assert compiled.starts[idx[i]] <= pos[i] < compiled.starts[idx[i] + 1]
