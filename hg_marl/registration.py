"""Registers the environment ids with PettingZoo and Gymnasium (idempotent)."""

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
        gymnasium.register(ROBOT_VIEW_ID, entry_point="hg_marl.agents.views:RobotView")
        gymnasium.register(HUMAN_VIEW_ID, entry_point="hg_marl.agents.views:HumanView")
