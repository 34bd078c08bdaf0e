"""How a scenario spec is told from a path, the file size limit and the keyword-only ``strict``, pinned for the gate.

Expected values from the module's docstrings, worked by hand: a spec is a built-in name,
``generated[:...]`` or the path of an existing ``.toml`` file, and nothing else; a
scenario file may be at most 1 MiB (1024 x 1024 = 1,048,576 bytes); ``strict`` is a
keyword; a file's error names its line where the parser can say it, and a file too
deeply nested is refused in one line. Names come from files and command lines, so they
are compared by value: a name read at run time is an equal string, not the literal the
module was compiled with.
"""

from __future__ import annotations

import re
import sys
from importlib import resources
from pathlib import Path

import pytest

from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import generate_scenario, load_scenario, resolve_scenario

ONE_MIB = 1024 * 1024


def paper_text() -> str:
    return resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text(encoding="utf-8")


def test_a_generated_name_read_from_a_file_is_the_generated_scenario(tmp_path: Path) -> None:
    """``scenario = generated`` in a study file: the name is read at run time, so it is a new string object."""
    line = tmp_path / "study.txt"
    line.write_text("scenario generated\n")
    name = line.read_text().split()[1]
    assert name == "generated"
    assert resolve_scenario(name) == ("generated", "generated")
    assert load_scenario(name) == generate_scenario()  # every parameter at its default


@pytest.mark.parametrize("suffix", [".txt", ".yaml", ".json", ""])
def test_an_existing_file_that_is_not_toml_is_an_unknown_scenario(tmp_path: Path, suffix: str) -> None:
    """A valid scenario's text saved under another suffix is refused: only ``.toml`` paths are files."""
    path = tmp_path / f"paper{suffix}"
    path.write_text(paper_text(), encoding="utf-8")
    with pytest.raises(ScenarioError, match=r"^unknown scenario .*or the path of an existing \.toml file$"):
        resolve_scenario(str(path))
    with pytest.raises(ScenarioError, match=r"^unknown scenario "):
        load_scenario(path)
    assert load_scenario(path.rename(tmp_path / "paper.toml")).name == "paper2015"  # the same text, as .toml


def _padded(path: Path, size: int) -> Path:
    """paper2015's text followed by a comment line, ``size`` bytes in all (ASCII: one byte a character)."""
    head = paper_text() + "\n# "
    assert head.isascii()
    path.write_text(head + "x" * (size - len(head) - 1) + "\n", encoding="utf-8")
    assert path.stat().st_size == size
    return path


def test_a_file_of_exactly_one_mib_loads_and_one_byte_more_is_refused(tmp_path: Path) -> None:
    assert load_scenario(_padded(tmp_path / "limit.toml", ONE_MIB)).name == "paper2015"
    over = _padded(tmp_path / "over.toml", ONE_MIB + 1)
    with pytest.raises(ScenarioError) as info:
        load_scenario(over)
    assert str(info.value) == f"scenario file {over}: larger than 1048576 bytes"


def test_strict_is_given_by_keyword_only() -> None:
    """``load_scenario(spec, True)`` would read as well as ``strict=True`` does not: it is refused."""
    assert load_scenario("paper2015", strict=True).name == "paper2015"
    with pytest.raises(TypeError, match="positional argument"):
        load_scenario("paper2015", True)  # type: ignore[call-arg]


def test_a_number_too_long_to_read_is_refused_naming_its_line(tmp_path: Path) -> None:
    """One more digit than Python converts (its limit, 4,300 unless set otherwise), on the file's last line."""
    digits = (sys.get_int_max_str_digits() or 4300) + 1
    text = paper_text().rstrip("\n") + "\n[extra]\nseed = " + "1" * digits + "\n"
    line = text.count("\n")  # the number is on the last line
    path = tmp_path / "long.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ScenarioError, match=rf"^scenario file {re.escape(str(path))}:{line}: a number of {digits:,} "):
        load_scenario(path)


def test_a_file_nested_deeper_than_the_parser_recurses_is_refused_in_one_line(tmp_path: Path) -> None:
    """5,000 nested arrays: over Python's recursion limit (1,000), refused as a scenario error, not a crash."""
    path = tmp_path / "deep.toml"
    path.write_text("x = " + "[" * 5000 + "]" * 5000 + "\n", encoding="utf-8")
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == f"scenario file {path}: nested too deeply"
