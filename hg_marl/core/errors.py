"""The project's one error hierarchy: bad input a user can fix, as opposed to bugs.

Every error a user can cause by what they type or hand over (an option, a scenario file,
a model file, a study file, a trace) derives from :class:`HgMarlError`. Its message is a
single line that names the user's option or file field (and ``path:line`` for files),
so the command line can catch it once in ``main`` and exit 2 with that line. Any other
exception is a bug and keeps its traceback.

The subclasses also derive from ``ValueError`` (and ``FileNotFoundError`` where a file is
missing) so code written against the builtin types keeps working.
"""

from __future__ import annotations

import errno
import math
import re
import sys
from pathlib import Path
from typing import Any


class HgMarlError(ValueError):
    """Base of every user-facing error: the message is one line naming what to fix."""

    def __init__(self, message: str) -> None:
        # One line, always: a newline inside a value (a file name, a TOML string)
        # would otherwise split the CLI's single error line.
        super().__init__(" ".join(str(message).split()))


class ScenarioError(HgMarlError):
    """A scenario could not be found or is malformed; the message names the field."""


class HumanError(HgMarlError):
    """An unknown human name, a bad parameter, or a human used where it cannot be."""


class RobotError(HgMarlError):
    """An unknown robot name or a bad robot parameter."""


class CriterionError(HgMarlError):
    """An unknown MetaController criterion or a bad criterion parameter."""


class ModelFileError(HgMarlError):
    """A learned-policy, trace or checkpoint file that is missing, corrupt or unsafe."""


class StudyError(HgMarlError):
    """A malformed study file or results store entry."""


class PopulationError(HgMarlError):
    """A malformed partner-population file (``path:line`` and the field named)."""


class ConfigError(HgMarlError):
    """A bad value in a run, training or command-line configuration."""


class OutputError(HgMarlError):
    """A result that could not be written: a full disk, a read-only or forbidden folder."""


WRITE_ERRNOS = frozenset(
    getattr(errno, name)
    for name in ("ENOSPC", "EDQUOT", "EACCES", "EPERM", "EROFS", "EFBIG", "EISDIR", "ENOTDIR", "ENAMETOOLONG")
    if hasattr(errno, name)
)
"""OS errors a user fixes (free space, permissions, a path that names the wrong thing)."""


def output_error(exc: OSError, path: object | None = None) -> OutputError | None:
    """The one-line error for an OS error a user can fix, else None (a bug keeps its traceback)."""
    if exc.errno not in WRITE_ERRNOS:
        return None
    target = path if path is not None else exc.filename
    return OutputError(f"cannot write {target}: {exc.strerror or exc}")


class SpecError(HgMarlError):
    """A malformed ``name:k=v,...`` spec (the parser's own errors; callers re-raise as their area's type)."""


def where(path: object, line: int | None = None) -> str:
    """``path:line`` (or just ``path``) for messages about a file."""
    return f"{path}:{line}" if line is not None else str(path)


def check_finite(
    value: Any,
    what: str,
    *,
    minimum: float | None = None,
    positive: bool = False,
    maximum: float | None = None,
    error: type[HgMarlError] = ConfigError,
) -> float:
    """Return ``value`` as a float after checking it is a finite number in range.

    Args:
        value: the candidate (bools are refused: ``True`` is not a duration).
        what: the option or field name used in the message (``--duration``, ``durations.pick``).
        minimum: inclusive lower bound, if any.
        positive: require ``value > 0``.
        maximum: inclusive upper bound, if any.
        error: the error type to raise (the caller's area).
    """
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise error(f"{what}: expected a number, got {value!r}")
    number = float(value)
    if not math.isfinite(number):
        raise error(f"{what}: expected a finite number, got {value!r}")
    if positive and number <= 0:
        raise error(f"{what}: expected a number > 0, got {value!r}")
    if minimum is not None and number < minimum:
        raise error(f"{what}: expected a number >= {minimum:g}, got {value!r}")
    if maximum is not None and number > maximum:
        raise error(f"{what}: expected a number <= {maximum:g}, got {value!r}")
    return number


def check_probability(value: Any, what: str, error: type[HgMarlError] = ConfigError) -> float:
    """A finite number in [0, 1]."""
    return check_finite(value, what, minimum=0.0, maximum=1.0, error=error)


def check_int(
    value: Any,
    what: str,
    *,
    minimum: int | None = None,
    maximum: int | None = None,
    error: type[HgMarlError] = ConfigError,
) -> int:
    """Return ``value`` if it is an integer (not a bool, not ``1.5``) in range."""
    if isinstance(value, bool) or not isinstance(value, int):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise error(f"{what}: expected an integer, got {value!r}")
    if minimum is not None and value < minimum:
        raise error(f"{what}: expected an integer >= {minimum}, got {value!r}")
    if maximum is not None and value > maximum:
        raise error(f"{what}: expected an integer <= {maximum}, got {value!r}")
    return int(value)


def check_bool(value: Any, what: str, error: type[HgMarlError] = ConfigError) -> bool:
    """Return ``value`` if it is a bool; the strings ``'no'``/``'yes'`` are not booleans."""
    if not isinstance(value, bool):
        raise error(f"{what}: expected true or false, got {value!r}")
    return value


MAX_DIGITS = sys.get_int_max_str_digits() or 4300
"""Longest run of digits a file or option may hold: Python refuses to convert a longer
integer (its own message names an interpreter setting, not the field)."""

_LONG_NUMBER = re.compile(rf"\d[\d_]{{{MAX_DIGITS},}}")


def check_digits(text: str, what: str, error: type[HgMarlError] = ConfigError, *, lines: bool = False) -> None:
    """Refuse ``text`` if it holds a number of more than :data:`MAX_DIGITS` digits.

    Checked on the raw text before a parser (TOML, JSON, YAML) meets the number, so the
    message names the option or ``file:line`` instead of Python's digit limit.

    Args:
        text: the raw text of an option value or a whole file.
        what: the option or the file's path.
        error: the caller's error type.
        lines: ``what`` is a file: name the line (``path:line``) of the number.
    """
    found = _LONG_NUMBER.search(text)
    if found is None:
        return
    at = f"{what}:{text.count(chr(10), 0, found.start()) + 1}" if lines else what
    digits = sum(c.isdigit() for c in found.group())
    raise error(f"{at}: a number of {digits:,} digits, over the limit of {MAX_DIGITS:,} digits")


class NotRegularFileError(OSError):
    """A path that names a FIFO, a device or a socket where a user's file was expected."""


def read_limited(path: Path, limit: int) -> bytes | None:
    """The bytes of a user's file, or None where it holds more than ``limit`` bytes.

    A file is read only if it is a regular file: opening a FIFO blocks until some writer
    comes, and a device (``/dev/zero``) never ends, where a size from ``stat`` reads 0.
    At most ``limit + 1`` bytes are read, so a file that grows meanwhile is refused too.

    Raises:
        NotRegularFileError: the path names neither a regular file nor a folder.
        OSError: as ``open`` raises it (a missing file, a folder, no permission).
    """
    if path.exists() and not (path.is_file() or path.is_dir()):
        raise NotRegularFileError(errno.EINVAL, "not a regular file", str(path))
    with open(path, "rb") as handle:
        data = handle.read(limit + 1)
    return None if len(data) > limit else data
