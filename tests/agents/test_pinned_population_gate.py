"""Population files: the refusals of the loader's less travelled fields, pinned for the mutation gate.

Each case edits one field of a valid two-member file (``GOOD``) and expects the
refusal the module docstring promises: ``path:line: field: problem`` for a bad field, a
``path: problem`` line for a file that cannot be read at all (too large, not UTF-8, nested
past Python's recursion limit). The limits are the module's documented ones: 1 MiB.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from test_population import GOOD

from hg_marl.agents.humans.population import MAX_FILE_BYTES, load_population
from hg_marl.core.errors import PopulationError


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "p.toml"
    path.write_text(text)
    return path


def test_the_base_file_loads(tmp_path: Path) -> None:
    """Every refusal below is its edit's doing."""
    assert [m.name for m in load_population(write(tmp_path, GOOD)).members()] == ["m00", "m01"]


def test_of_two_unknown_member_fields_the_first_in_sorted_order_is_named(tmp_path: Path) -> None:
    """``weight`` and ``colour`` (in that order in the file): sorted, ``colour`` comes first, line 8."""
    text = GOOD.replace('split = "train"\n', 'split = "train"\nweight = 1\ncolour = "red"\n', 1)
    with pytest.raises(PopulationError) as info:
        load_population(write(tmp_path, text))
    assert str(info.value).startswith(f"{tmp_path / 'p.toml'}:8: members[0].colour: unknown field")


def test_a_file_over_one_mib_is_refused_and_one_of_exactly_one_mib_is_read(tmp_path: Path) -> None:
    """The limit is ``st_size > 1 MiB``: a comment pads the valid file to exactly 1 MiB (read)
    and to one byte more (refused before it is parsed)."""
    assert MAX_FILE_BYTES == 1 << 20
    pad = MAX_FILE_BYTES - len(GOOD.encode()) - 2  # "#" and the newline
    exact = write(tmp_path, GOOD + "#" + "x" * pad + "\n")
    assert exact.stat().st_size == MAX_FILE_BYTES
    assert load_population(exact).name == "tiny"
    over = write(tmp_path, GOOD + "#" + "x" * (pad + 1) + "\n")
    with pytest.raises(PopulationError, match=rf"^{re.escape(str(over))}: larger than 1048576 bytes$"):
        load_population(over)


def test_a_file_that_is_not_utf8_is_refused_as_unreadable(tmp_path: Path) -> None:
    path = tmp_path / "p.toml"
    path.write_bytes(GOOD.encode() + b"# \xff\xfe\n")
    with pytest.raises(PopulationError, match=r"cannot read the population file \(UnicodeDecodeError\)"):
        load_population(path)


def test_a_file_nested_past_the_recursion_limit_is_refused(tmp_path: Path) -> None:
    """Python's TOML reader recurses once per bracket: 5,000 nested arrays exhaust it."""
    path = write(tmp_path, "x = " + "[" * 5000 + "]" * 5000 + "\n" + GOOD)
    with pytest.raises(PopulationError, match=rf"^{re.escape(str(path))}: nested too deeply$"):
        load_population(path)


def test_an_unknown_generator_field_is_refused_with_its_line(tmp_path: Path) -> None:
    text = GOOD.replace("[[members]]", "[generator]\nseed = 0\ntemperature = 2\n\n[[members]]", 1)
    with pytest.raises(PopulationError) as info:
        load_population(write(tmp_path, text))
    assert str(info.value).startswith(f"{tmp_path / 'p.toml'}:6: generator.temperature: unknown field")


def test_a_spread_value_other_than_selected_and_random_is_refused(tmp_path: Path) -> None:
    """A finite ``median`` is still not one of the two values a split's spread holds."""
    text = GOOD.replace("[[members]]", "[spread.held_out]\nselected = 2.0\nmedian = 1.0\n\n[[members]]", 1)
    with pytest.raises(PopulationError, match=r"spread\.held_out: expected selected and random"):
        load_population(write(tmp_path, text))
    accepted = GOOD.replace("[[members]]", "[spread.held_out]\nselected = 2.0\nrandom = 1.0\n\n[[members]]", 1)
    assert load_population(write(tmp_path, accepted)).spread == {"held_out": {"selected": 2.0, "random": 1.0}}


def test_an_empty_list_of_members_is_refused(tmp_path: Path) -> None:
    path = write(tmp_path, 'name = "x"\nmembers = []\n')
    with pytest.raises(PopulationError, match=rf"^{re.escape(str(path))}:2: members: expected at least one"):
        load_population(path)
