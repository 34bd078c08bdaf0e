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
