"""Values that round 189's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import tomllib

import pytest

from hg_marl.core import ScenarioError
from hg_marl.core.scenario import _line_of
from hg_marl.core.scenario_file import parse_scenario


def test_a_field_naming_a_whole_table_is_placed_at_its_header_line() -> None:
    # Lines counted from 1: line 1 the name, line 2 blank, line 3 the [durations] header, line 4 its key.
    # A field that names the table as a whole ("durations") is reported at its header, line 3; one of
    # its keys at the key's own line, 4.
    text = 'name = "x"\n\n[durations]\npick = 2.0\n'
    assert text.splitlines()[2] == "[durations]"
    assert _line_of(text, "durations") == 3
    assert _line_of(text, "durations.pick") == 4


def test_an_unknown_table_in_a_scenario_file_is_refused_at_its_header_line() -> None:
    # The unknown top-level table [extra] is the file's line 3 (after the name and a blank line):
    # the refusal names "s.toml:3", the header a user has to delete, not line 2 (the blank line).
    text = 'name = "x"\n\n[extra]\nk = 1\n'
    with pytest.raises(ScenarioError, match=r"^scenario s\.toml:3: field 'extra': unknown key"):
        parse_scenario(tomllib.loads(text), "s.toml", text=text)
