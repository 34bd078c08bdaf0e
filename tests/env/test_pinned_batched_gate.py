"""The batch's memory refusal names its limit in MB, pinned for the mutation gate.

Expected by hand: a limit of 2**20 bytes is "1 MB"; 3 * 2**20 is "3 MB".
"""

from __future__ import annotations

import pytest

from hg_marl.core import World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import check_batch


@pytest.mark.parametrize(("limit", "text"), [(2**20, "1 MB limit"), (3 * 2**20, "3 MB limit")])
def test_the_refusal_names_the_limit_in_mb(limit: int, text: str) -> None:
    with pytest.raises(ConfigError, match=f"over the {text} \\(memory_limit\\)"):
        check_batch(World("paper2015"), 10**6, memory_limit=limit)
