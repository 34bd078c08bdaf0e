"""Values that round 216's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training.play.server_limits import ServerLimits


def test_max_header_bytes_is_accepted_up_to_one_mebibyte() -> None:
    # the head limit runs from 1 KiB to 1 MiB (2**20 = 1,048,576 bytes): a 100,000-byte head
    # (over 64 KiB = 65,536) and the full mebibyte are accepted and handed to uvicorn's h11 as
    # its incomplete-event size; one byte more than the mebibyte is refused, naming the bound
    for size in (100_000, 1_048_576):
        limits = ServerLimits(max_header_bytes=size)
        assert limits.max_header_bytes == size
        assert limits.uvicorn_options()["h11_max_incomplete_event_size"] == size
    with pytest.raises(ConfigError, match=r"^max_header_bytes: expected an integer <= 1048576, got 1048577$"):
        ServerLimits(max_header_bytes=1_048_577)
