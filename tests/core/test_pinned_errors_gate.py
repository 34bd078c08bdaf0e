"""The error module's checks and messages, pinned for the mutation gate.

Every expected value is read off the module's documented rules, worked by hand: bounds
are inclusive, bools are not numbers, a float with no fraction is an integer, a message
is one line, an OS error a user can fix becomes ``cannot write PATH: REASON`` and any
other stays a bug (None), and a number longer than :data:`MAX_DIGITS` digits is refused
with the line it sits on (the count of newlines before it, plus one).
"""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest

from hg_marl.core.errors import (
    MAX_DIGITS,
    ConfigError,
    HgMarlError,
    HumanError,
    NotRegularFileError,
    OutputError,
    check_bool,
    check_digits,
    check_finite,
    check_int,
    check_probability,
    output_error,
    read_limited,
    where,
)


def test_a_message_with_newlines_and_runs_of_spaces_becomes_one_line_with_single_spaces() -> None:
    """``"a\\nb   c\\t d"`` split on whitespace and joined by one space is ``"a b c d"``."""
    assert str(HgMarlError("a\nb   c\t d")) == "a b c d"
    assert isinstance(HgMarlError("x"), ValueError)


def test_where_names_the_line_only_when_one_is_given_line_zero_included() -> None:
    assert where("f.toml", 3) == "f.toml:3"
    assert where("f.toml", 0) == "f.toml:0"  # 0 is a line number, not "no line"
    assert where("f.toml") == "f.toml"


def test_an_os_error_a_user_fixes_becomes_one_output_error_line() -> None:
    """ENOSPC (a full disk) is in the user's hands: ``cannot write`` the path, then the OS reason."""
    exc = OSError(errno.ENOSPC, "No space left on device", "out/file.csv")
    error = output_error(exc)
    assert isinstance(error, OutputError)
    assert str(error) == "cannot write out/file.csv: No space left on device"
    # A path handed over names the file instead of the OS error's own.
    assert str(output_error(exc, "results.csv")) == "cannot write results.csv: No space left on device"


def test_an_os_error_without_a_reason_names_the_error_itself() -> None:
    """No ``strerror``: the message falls back to the exception's own text."""
    exc = OSError(errno.EACCES, None)
    exc.strerror = None
    error = output_error(exc, "p")
    assert error is not None
    assert str(error) == f"cannot write p: {exc}"


def test_an_os_error_no_user_can_fix_stays_a_bug() -> None:
    """ENOENT and EIO are not in the list of errors a user fixes: None, so the traceback stays."""
    assert output_error(OSError(errno.ENOENT, "No such file", "x")) is None
    assert output_error(OSError(errno.EIO, "I/O error", "x")) is None


@pytest.mark.parametrize("value", [True, False, "1", None, [1]])
def test_check_finite_refuses_what_is_not_a_number_naming_the_field(value: object) -> None:
    with pytest.raises(HumanError, match=r"^p_idle: expected a number, got "):
        check_finite(value, "p_idle", error=HumanError)


def test_check_finite_bounds_are_inclusive_and_positive_is_strict() -> None:
    """``minimum`` and ``maximum`` accept their own value; ``positive`` refuses 0 and accepts 1e-9."""
    assert check_finite(2, "x", minimum=2) == 2.0
    assert isinstance(check_finite(2, "x"), float)
    assert check_finite(5.0, "x", maximum=5) == 5.0
    assert check_finite(1e-9, "x", positive=True) == 1e-9
    with pytest.raises(ConfigError, match=r"^x: expected a number > 0, got 0$"):
        check_finite(0, "x", positive=True)
    with pytest.raises(ConfigError, match=r"^x: expected a number >= 2, got 1.5$"):
        check_finite(1.5, "x", minimum=2)
    with pytest.raises(ConfigError, match=r"^x: expected a number <= 5, got 5.5$"):
        check_finite(5.5, "x", maximum=5)
    with pytest.raises(ConfigError, match=r"^x: expected a finite number, got inf$"):
        check_finite(float("inf"), "x")


def test_a_probability_is_a_number_from_0_to_1_both_included() -> None:
    assert check_probability(0, "p") == 0.0
    assert check_probability(1, "p") == 1.0
    for bad in (-1e-9, 1.0000001):
        with pytest.raises(ConfigError):
            check_probability(bad, "p")


def test_check_int_takes_whole_floats_refuses_fractions_and_bools_and_bounds_inclusively() -> None:
    assert check_int(4.0, "n") == 4
    assert type(check_int(4.0, "n")) is int
    assert check_int(3, "n", minimum=3, maximum=3) == 3
    assert check_int(5, "n", minimum=3, maximum=9) == 5
    with pytest.raises(ConfigError, match=r"^n: expected an integer, got 2.5$"):
        check_int(2.5, "n")
    with pytest.raises(ConfigError, match=r"^n: expected an integer, got True$"):
        check_int(True, "n")
    with pytest.raises(ConfigError, match=r"^n: expected an integer >= 3, got 2$"):
        check_int(2, "n", minimum=3)
    with pytest.raises(ConfigError, match=r"^n: expected an integer <= 3, got 4$"):
        check_int(4, "n", maximum=3)


def test_check_bool_takes_only_true_and_false() -> None:
    assert check_bool(True, "flag") is True
    assert check_bool(False, "flag") is False
    with pytest.raises(ConfigError, match=r"^flag: expected true or false, got 'yes'$"):
        check_bool("yes", "flag")
    with pytest.raises(ConfigError):
        check_bool(1, "flag")


def test_a_number_of_exactly_the_digit_limit_passes_one_more_digit_is_refused() -> None:
    """``MAX_DIGITS`` digits pass; ``MAX_DIGITS + 1`` are refused with the count and the limit, thousands separated."""
    check_digits("x = " + "7" * MAX_DIGITS, "--opt")
    with pytest.raises(ConfigError) as info:
        check_digits("x = " + "7" * (MAX_DIGITS + 1), "--opt")
    assert str(info.value) == f"--opt: a number of {MAX_DIGITS + 1:,} digits, over the limit of {MAX_DIGITS:,} digits"


def test_underscores_in_a_long_number_are_not_counted_as_digits() -> None:
    """``1_1_..._1`` with MAX_DIGITS + 1 ones (and MAX_DIGITS underscores): MAX_DIGITS + 1 digits."""
    text = "_".join(["1"] * (MAX_DIGITS + 1))
    with pytest.raises(HumanError, match=rf"a number of {MAX_DIGITS + 1:,} digits"):
        check_digits(text, "f", HumanError)


def test_a_long_number_in_a_file_is_named_by_its_line() -> None:
    """Three newlines before the number: it is on line 4; without ``lines`` the message names the file alone."""
    text = "a = 1\nb = 2\n\nc = " + "9" * (MAX_DIGITS + 5) + "\nd = 4\n"
    with pytest.raises(ConfigError, match=r"^data\.toml:4: a number of "):
        check_digits(text, "data.toml", lines=True)
    with pytest.raises(ConfigError, match=r"^data\.toml: a number of "):
        check_digits(text, "data.toml")


def _digit_limit_under(setting: int) -> int:
    """``MAX_DIGITS`` as a fresh interpreter started with ``-X int_max_str_digits=setting`` reads it."""
    code = "from hg_marl.core.errors import MAX_DIGITS; print(MAX_DIGITS)"
    proc = subprocess.run(
        [sys.executable, "-X", f"int_max_str_digits={setting}", "-c", code],
        capture_output=True,
        text=True,
        check=True,
        env=dict(os.environ),
    )
    return int(proc.stdout)


def test_the_digit_limit_is_the_interpreters_own_or_pythons_default_when_it_has_none() -> None:
    """Python refuses to convert longer integers than its limit (5000 here), so that is the limit;
    with the interpreter's limit off (0) nothing would stop a huge number, and the module keeps
    Python's documented default, 4300."""
    assert _digit_limit_under(5000) == 5000
    assert _digit_limit_under(0) == 4300


def test_read_limited_reads_up_to_its_limit_and_says_none_past_it(tmp_path: Path) -> None:
    """``limit`` bytes are the file's; one byte more gives None (at most ``limit + 1`` read)."""
    path = tmp_path / "f.txt"
    path.write_bytes(b"abcde")
    assert read_limited(path, 5) == b"abcde"
    assert read_limited(path, 6) == b"abcde"
    assert read_limited(path, 4) is None
    path.write_bytes(b"")
    assert read_limited(path, 0) == b""


def test_read_limited_refuses_a_fifo_and_a_device_unread_and_passes_open_errors_on(tmp_path: Path) -> None:
    """A FIFO (an open would wait for a writer) and ``/dev/zero`` (its size reads 0, its bytes
    never end) are not regular files; a missing file and a folder raise as ``open`` does."""
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(NotRegularFileError) as info:
            read_limited(path, 10)
        assert isinstance(info.value, OSError) and info.value.errno == errno.EINVAL
    with pytest.raises(FileNotFoundError):
        read_limited(tmp_path / "missing", 10)
    with pytest.raises(IsADirectoryError):
        read_limited(tmp_path, 10)
