"""PettingZoo adapters over the task core."""

from hg_marl.envs.parallel import AgentMismatchError, parallel_env
from hg_marl.envs.table_cleaning import InvalidActionError, env, raw_env

__all__ = ["AgentMismatchError", "InvalidActionError", "env", "parallel_env", "raw_env"]
