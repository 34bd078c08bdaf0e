"""Values that round 153's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import pytest

from hg_marl.agents.humans.switching import SwitchingHuman
from hg_marl.core.scenario import _line_of


def test_a_fractional_switching_threshold_is_kept_as_given() -> None:
    # at=[600.5] seconds: the cooperative human plays until the clock reaches 600.5 s, so at
    # 600.2 s it is still phase 0 and at 600.5 s (the threshold itself) phase 1. Read as whole
    # seconds (600) the switch would come at 600.2 s already.
    human = SwitchingHuman(humans=["cooperative", "lazy"], at=[600.5])
    assert human.at == [600.5]
    assert human.phase_at(600.2, 0) == 0
    assert human.phase_at(600.5, 0) == 1
    # by tasks: at=[2.5] switches on the 3rd task solved, not on the 2nd.
    by_tasks = SwitchingHuman(humans=["cooperative", "lazy"], at=[2.5], by="tasks")
    assert [by_tasks.phase_at(0.0, n) for n in (2, 3)] == [0, 1]


def test_a_whole_array_of_tables_entry_is_placed_at_its_own_header_line() -> None:
    # Lines counted from 1: the second [[spots]] header is line 5, its name line 6. A field that
    # names the entry as a whole (spots[1]) is reported at the header; one of its keys at the key.
    text = 'name = "x"\n\n[[spots]]\nname = "a"\n[[spots]]\nname = "b"\n'
    assert text.splitlines()[4] == "[[spots]]"
    assert _line_of(text, "spots[1]") == 5
    assert _line_of(text, "spots[0]") == 3
    assert _line_of(text, "spots[1].name") == 6


def test_head_bytes_counts_a_percent_encoded_path_as_sent() -> None:
    pytest.importorskip("uvicorn")
    from hg_marl.training.play.server_limits import head_bytes

    # The request as it came over the wire: "GET /a%20b HTTP/1.1\r\n" (3 + 1 + 6 + 11 = 21 bytes),
    # "host: x\r\n" (9) and the blank line (2): 32 bytes. ASGI's decoded path "/a b" is 2 shorter.
    sent = b"GET /a%20b HTTP/1.1\r\nhost: x\r\n\r\n"
    scope = {"method": "GET", "path": "/a b", "raw_path": b"/a%20b", "query_string": b"", "headers": [(b"host", b"x")]}
    assert head_bytes(scope) == len(sent) == 32
