"""Registers the environment ids with PettingZoo and Gymnasium (idempotent).

Importing ``hg_marl`` calls :func:`register_envs`. Without that import, Gymnasium finds the
ids through its ``"module:id"`` form, which imports the module first:
``gymnasium.make("hg_marl:hg_marl/RobotTableCleaning-v0")`` (and ``gymnasium.make_vec``).
Gymnasium 1.x has no entry-point plugin discovery, and PettingZoo's registry (1.27+) does
not import modules by id, so ``pettingzoo.make("aec", "hg_marl/TableCleaning-v0")`` needs
``import hg_marl`` first (PettingZoo before 1.27 has no registry; 1.27 is the lowest
version the project declares).
"""

from __future__ import annotations

AEC_ID = "hg_marl/TableCleaning-v0"
ROBOT_VIEW_ID = "hg_marl/RobotTableCleaning-v0"
HUMAN_VIEW_ID = "hg_marl/HumanTableCleaning-v0"


def register_envs() -> None:
    """Register once; entry points are strings, so nothing heavy is imported here."""
    import gymnasium
    import pettingzoo

    if AEC_ID not in pettingzoo.aec_registry:
        pettingzoo.register("aec", AEC_ID, entry_point="hg_marl.envs.table_cleaning:env")
        pettingzoo.register("parallel", AEC_ID, entry_point="hg_marl.envs.parallel:parallel_env")
    if ROBOT_VIEW_ID not in gymnasium.registry:
        gymnasium.register(
            ROBOT_VIEW_ID,
            entry_point="hg_marl.agents.views:RobotView",
            vector_entry_point="hg_marl.agents.vector_envs:robot_vector_env",
        )
        gymnasium.register(
            HUMAN_VIEW_ID,
            entry_point="hg_marl.agents.views:HumanView",
            vector_entry_point="hg_marl.agents.vector_envs:human_vector_env",
        )
