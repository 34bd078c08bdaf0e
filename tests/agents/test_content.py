"""The one content-key module: what changes a key and what does not.

Code is checked on a copy of the sources (``tests/source_copy.py``): an edited module that
the roots reach changes the key, a comment or docstring does not, a module nothing imports
does not. Files are checked by writing them: a named scenario, a named population file and
a population member's weights each change the key; a file beside them that no loader
reads does not. The store's stored entries still carry their own hash.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents import content
from hg_marl.agents.humans.learned import save_learned_policy
from hg_marl.core import Agent, World
from hg_marl.core.scenario import ScenarioError
from tests.source_copy import REPO, copy_sources, edit_code, edit_docs, write

ROOTS = ("hg_marl.agents.compiled",)
"""A root for the code tests: the compiled partners reach the core, the humans' base, the oracle."""


@pytest.fixture()
def sources(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    return copy_sources(tmp_path / "src", monkeypatch)


def test_an_edited_reached_module_changes_the_code_digest(sources: Path) -> None:
    before = content.code_digest(ROOTS)
    edit_code(sources / "hg_marl/core/table.py")  # imported by the world, which compiled imports
    assert content.code_digest(ROOTS) != before


def test_comments_and_docstrings_change_nothing(sources: Path) -> None:
    before = content.code_digest(ROOTS)
    edit_docs(sources / "hg_marl/core/table.py")
    path = sources / "agents/compiled.py"
    text = path.read_text()
    assert text.startswith('"""Compiled partners:')
    write(path, text.replace('"""Compiled partners:', '"""The compiled partners:', 1))
    assert content.code_digest(ROOTS) == before


def test_a_module_no_root_reaches_changes_nothing(sources: Path) -> None:
    before = content.code_digest(ROOTS)
    modules, _ = content.code_modules(ROOTS)
    assert "hg_marl.training.report" not in modules  # the lower layers never import training
    edit_code(sources / "training/report.py")
    write(sources / "agents/unrelated.py", "x = 1\n")
    assert content.code_digest(ROOTS) == before


def test_the_walk_follows_function_level_imports_and_parent_packages() -> None:
    modules, outside = content.code_modules(ROOTS)
    # compiled imports the model builder's layouts inside a function; their package parents come with them
    assert {"hg_marl.agents.models.layouts", "hg_marl.agents.models", "hg_marl.agents", "hg_marl"} <= set(modules)
    assert "numpy" in outside and "hg_marl.agents.robots.planner" not in modules


def test_a_changed_scenario_file_changes_the_key(tmp_path: Path) -> None:
    scenario = tmp_path / "layout.toml"
    scenario.write_bytes((REPO / "hg_marl/core/scenarios/paper2015.toml").read_bytes())
    fields = {"scenario": str(scenario)}
    before = content.content_key("test", fields, ROOTS)
    assert content.scenario_content(str(scenario)) == hashlib.sha256(scenario.read_bytes()).hexdigest()
    (tmp_path / "notes.txt").write_text("beside it, read by nobody")
    assert content.content_key("test", fields, ROOTS) == before
    scenario.write_text(scenario.read_text().replace("3 tapes", "three tapes"))
    assert content.content_key("test", fields, ROOTS) != before


def test_a_changed_population_file_or_member_changes_the_key(tmp_path: Path) -> None:
    world = World("paper2015")
    member = save_learned_policy(
        tmp_path / "member", world, weights=np.zeros((world.n_actions(Agent.HUMAN), world.n_facts))
    )
    population = tmp_path / "pop.toml"
    population.write_text(f'name = "p"\n[[members]]\nname = "m"\nspec = "learned:path={member}"\n')
    fields = {"population": str(population), "members": [f"learned:path={member}"]}
    first = content.content_key("test", fields, ROOTS)
    population.write_text(population.read_text() + 'split = "train"\n')
    second = content.content_key("test", fields, ROOTS)
    weights = member / "policy.npz"
    weights.write_bytes(weights.read_bytes() + b"\0")  # the member's weights, named inside a spec
    third = content.content_key("test", fields, ROOTS)
    assert len({first, second, third}) == 3
    assert set(content.named_files(fields)) == {str(population), str(member)}


def test_scenario_content_is_what_the_name_denotes() -> None:
    bundled = (REPO / "hg_marl/core/scenarios/roboergosum.toml").read_bytes()
    assert content.scenario_content("roboergosum") == hashlib.sha256(bundled).hexdigest()
    spec = "generated:objects=2,seed=4"
    assert content.scenario_content(spec) == hashlib.sha256(spec.encode()).hexdigest()
    with pytest.raises(ScenarioError, match="unknown scenario"):
        content.scenario_content("no_such_layout")


def test_the_stores_entries_carry_their_hash_and_its_code_digest(tmp_path: Path) -> None:
    from hg_marl.training.store import Job, Store, code_roots, seal
    from hg_marl.training.sweep import run_jobs

    store = Store(tmp_path)
    job = Job(robot="planner", seed=0, duration=30.0)
    run_jobs([job], store)
    record = json.loads((store.entry(job.key()) / "result.json").read_text())
    assert record["sha256"] == seal(record)["sha256"]  # sealed: its own canonical hash
    document = next(v for v in record.values() if isinstance(v, dict) and v.get("kind") == "run")
    assert document["code"] == content.code_digest(code_roots())
    assert {"hg_marl.training.backends", "hg_marl.agents.robots.planner"} <= set(content.code_modules(code_roots())[0])
