"""Values that round 108's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core import ScenarioError, load_scenario
from hg_marl.core.registry import Entry, Param
from tests.core.test_registry import Toy
from tests.core.test_scenario_validation import line_containing, paper_text, write

# --- hg_marl/core/registry.py ---


def test_a_parameter_without_its_own_line_is_listed_with_an_empty_line() -> None:
    # Entry.param_docs: "a line per parameter (listings); parameters without one are listed with
    # an empty line". The toy entry describes itself and one of its four parameters only.
    entry = Entry("toy", Toy, "a toy that rolls", {"speed": "how fast it rolls"})
    assert entry.params == {
        "speed": Param(1.5, "how fast it rolls"),
        "label": Param("a", ""),
        "tags": Param(["x"], ""),
        "path": Param(None, ""),
    }


# --- hg_marl/core/scenario_file.py ---


@pytest.mark.parametrize(
    ("old", "new", "field", "needle"),
    [
        ('robot_start = ["bin_side"]', 'robot_start = ["bin_side", "bin_side"]', "robot_start[1]", "robot_start ="),
        (
            'spots = ["mat_left", "mat_centre", "mat_right"]',
            'spots = ["mat_left", "mat_left", "mat_right"]',
            "layout[0].spots[1]",
            'spots = ["mat_left", "mat_left"',
        ),
    ],
)
def test_a_name_listed_twice_is_refused_at_its_line(
    tmp_path: Path, old: str, new: str, field: str, needle: str
) -> None:
    # paper2015 with one name repeated: the second mention (index 1) is refused as listed twice,
    # at the line of its key (found by searching the edited text). Accepted, robot_start
    # (0, 0) and a layout pool (0, 0, 2) would count one location or spot twice.
    text = paper_text()
    assert text.count(old) == 1
    text = text.replace(old, new)
    path = write(tmp_path, text)
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    name = new.split('"')[1]
    expected = f"scenario {path}:{line_containing(text, needle)}: field {field!r}: {name!r} listed twice"
    assert str(info.value) == expected


# --- training/play/server_limits.py ---


def test_headers_over_max_header_bytes_are_answered_400_before_they_end(tmp_path: Path) -> None:
    # max_header_bytes=2048: "largest request line plus headers, in bytes". A request line and
    # 3,000 bytes of one header, not yet ended, are over it, so the server answers at once with
    # uvicorn's 400 (h11's buffer limit) instead of waiting for the rest. Under h11's own default
    # limit, 16 KiB, the server would wait for the rest until the 1 s header deadline and then
    # close the connection without a word (b"").
    pytest.importorskip("uvicorn")
    from hg_marl.training.play.server_limits import ServerLimits
    from hg_marl.training.play.session import PlaySession
    from tests.play.test_server_limits import GUARD, _closed_by_server, _connect, _serve

    limits = ServerLimits(idle_timeout=1.0, header_timeout=1.0, body_timeout=1.0, max_header_bytes=2048)
    assert limits.uvicorn_options()["h11_max_incomplete_event_size"] == 2048
    session = PlaySession("planner", seed=0, record=tmp_path, player="limits-test")
    for srv in _serve(session, limits):
        with _connect(srv) as sock:
            sock.settimeout(GUARD)
            sock.sendall(b"GET /board HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: " + b"a" * 3000)
            assert _closed_by_server(sock).startswith(b"HTTP/1.1 400")
