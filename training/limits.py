"""How much work one command or file may ask for, checked before anything is allocated.

A count a user types (``--seeds``, ``seeds = ...`` in a study, ``--train`` of a
population) becomes a list of jobs, a ``range`` turned into a tuple, a list of members:
memory in proportion to the count. Each is checked against its limit here, before that
list exists, and the refusal names the option or field and the limit. The limits sit far
above any real study (the paper uses 10 seeds) and far below what exhausts a machine.
docs/inputs.md lists them with the other input limits (cycles per run, array sizes in
model files).
"""

from __future__ import annotations

from hg_marl.agents.humans.population import MAX_MEMBERS
from hg_marl.core.errors import ConfigError, HgMarlError, check_int

MAX_SEEDS = 10_000
"""Most seeds per condition (a study's ``seeds``, ``--seeds`` of every command)."""

MAX_RUNS = 200_000
"""Most runs one study or sweep may ask for (robots x humans x scenarios x seeds)."""

MAX_SEED_VALUE = 2**63 - 1
"""Largest seed value (what a trace header and the store's keys accept)."""

MAX_STUDY_BYTES = 1 << 20
"""A study file may be at most 1 MiB (as scenario and population files)."""

__all__ = [
    "MAX_MEMBERS",
    "MAX_RUNS",
    "MAX_SEEDS",
    "MAX_SEED_VALUE",
    "MAX_STUDY_BYTES",
    "check_count",
    "check_runs",
]


def check_count(
    value: object, what: str, limit: int, *, minimum: int = 1, error: type[HgMarlError] = ConfigError
) -> int:
    """An integer count in ``[minimum, limit]``; over the limit, the message names it.

    Args:
        value: the count as given (an int; a bool or ``1.5`` is refused).
        what: the option or field (``--seeds``, ``path:line: seeds``).
        limit: the largest count accepted (one of this module's limits).
        minimum: the smallest count accepted.
        error: the caller's error type.
    """
    count = check_int(value, what, minimum=minimum, error=error)
    if count > limit:
        raise error(f"{what}: {count:,} is over the limit of {limit:,}")
    return count


def check_runs(runs: int, what: str, error: type[HgMarlError] = ConfigError) -> int:
    """A number of runs (a product of counts, computed before the jobs are listed) within :data:`MAX_RUNS`."""
    if runs > MAX_RUNS:
        raise error(f"{what}: {runs:,} runs, over the limit of {MAX_RUNS:,} runs")
    return runs
