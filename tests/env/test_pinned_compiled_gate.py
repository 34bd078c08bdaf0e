"""The compiled humans' disk cache names and the code their keys cover, pinned for the mutation gate.

Expected values by hand: a scenario spec ``family:k=v,...`` names its table file after the
family, the part before the first colon (``generated``), never after its parameters; the
code a human table is keyed by is every module its compiler and the registry's humans
import, and no robot's (the cheap counterpart of ``test_pinned_compiled.py``'s edits of a
copy of the sources: the same module lists, read from the import walk, without copying).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hg_marl.agents import compiled, content
from hg_marl.agents.compiled import cache_key, compile_human
from hg_marl.core import World
from tests.content_keys import record_content_keys


def test_a_family_scenarios_table_file_is_named_after_the_family(tmp_path: Path) -> None:
    world = World("generated:objects=1,seed=0")
    assert world.scenario.name.startswith("generated:objects=1,")
    compile_human(world, "lazy", cache=tmp_path)
    names = [p.name for p in tmp_path.iterdir()]
    assert len(names) == 1 and re.fullmatch(r"generated-[0-9a-f]{24}\.npz", names[0]), names
    assert names[0] == f"generated-{cache_key(world, 'lazy')[:24]}.npz"


def test_a_human_tables_key_covers_its_compiler_and_the_humans_code_only(monkeypatch: pytest.MonkeyPatch) -> None:
    world = World("paper2015")
    asked = record_content_keys(monkeypatch)
    cache_key(world, "lazy", ("cooperative",))
    [(kind, fields, roots)] = asked
    assert kind == "compiled human"
    assert fields == {
        "scenario": repr(world.scenario),
        "durations": repr(world.durations),
        "spec": "lazy",
        "closure": ["cooperative"],
    }
    keyed, _ = content.code_modules(roots)
    shared = ["hg_marl.core.world", "hg_marl.agents.planner.costs", "hg_marl.agents.compiled"]
    shared += ["hg_marl.agents.models.builder", "hg_marl.agents.content"]
    humans = ["hg_marl.agents.humans.lazy", "hg_marl.agents.humans.cooperative", "hg_marl.agents.humans.learned"]
    robots = ["hg_marl.agents.compiled_robot", "hg_marl.agents.robots.planner", "hg_marl.agents.robots.base"]
    robots += ["hg_marl.agents.partner"]
    assert set(shared + humans) <= set(keyed)
    assert not set(robots) & set(keyed)
    assert compiled.__name__ in roots
