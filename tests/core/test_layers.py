"""The layer contract where import-linter cannot see: entry-point strings, and the contract's own order.

``make lint`` runs import-linter on every import (``.ci/lint_layers.py``); an entry point
given as a ``"module:attr"`` string imports nothing until it is called, so this test reads
them from ``hg_marl/registration.py`` and checks each against the layer of the module that
registers it.
"""

from __future__ import annotations

import ast
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LAYERS = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["importlinter"]["contracts"][0][
    "layers"
]

DECLARED_EXCEPTIONS = {
    # The composition root registers the Gymnasium single-seat ids on `import hg_marl` (a
    # promise of the package); their entry points build a scripted partner from a name,
    # which only the agents' registries can do.
    "hg_marl.agents.views:RobotView",
    "hg_marl.agents.vector_envs:robot_vector_env",
    "hg_marl.agents.views:HumanView",
    "hg_marl.agents.vector_envs:human_vector_env",
}


def _layer(module: str) -> int:
    """Index in the contract (0 = top); modules outside every layer rank below them all."""
    for i, layer in enumerate(LAYERS):
        if module == layer or module.startswith(layer + "."):
            return i
    return len(LAYERS)


def _entry_points(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return [
        kw.value.value
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if kw.arg in ("entry_point", "vector_entry_point")
        and isinstance(kw.value, ast.Constant)
        and isinstance(kw.value.value, str)
    ]


def test_the_contract_orders_the_packages_as_the_design_says() -> None:
    assert LAYERS == [
        "hg_marl.training",
        "hg_marl.agents",
        "hg_marl.wrappers",
        "hg_marl.envs",
        "hg_marl.policy",
        "hg_marl.core",
    ]


def test_entry_point_strings_point_no_higher_than_the_envs_but_the_declared_ones() -> None:
    points = _entry_points(ROOT / "hg_marl" / "registration.py")
    assert "hg_marl.envs.table_cleaning:env" in points  # the scan reads them
    upward = {p for p in points if _layer(p.split(":")[0]) < _layer("hg_marl.envs")}
    assert upward == DECLARED_EXCEPTIONS
