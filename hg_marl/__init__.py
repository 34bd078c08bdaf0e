"""hg-marl: human-robot collaboration as a multi-agent RL environment.

``hg_marl.env()`` is the PettingZoo AEC environment TableCleaning-v0 (see
:mod:`hg_marl.envs.table_cleaning` for its spec sheet); ``hg_marl.parallel_env()`` the
turn-based parallel version. Importing this package registers the PettingZoo id
``hg_marl/TableCleaning-v0`` and the Gymnasium ids ``hg_marl/RobotTableCleaning-v0`` and
``hg_marl/HumanTableCleaning-v0`` (single-agent views with a scripted partner). It
imports neither torch nor any rendering library.
"""

from __future__ import annotations

from hg_marl.core import HgMarlError, Scenario, ScenarioError, World, available_scenarios, load_scenario
from hg_marl.envs import AgentMismatchError, InvalidActionError, env, parallel_env, raw_env
from hg_marl.registration import register_envs

__version__ = "0.1.0"
__all__ = [
    "AgentMismatchError",
    "HgMarlError",
    "InvalidActionError",
    "Scenario",
    "ScenarioError",
    "World",
    "available_scenarios",
    "env",
    "load_scenario",
    "parallel_env",
    "raw_env",
]

register_envs()
