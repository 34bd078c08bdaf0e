"""Helpers shared by the subcommands: ``key=value`` options as specs, checked values, clean errors.

Bad input raises an :class:`~hg_marl.core.errors.HgMarlError` whose message names the
user's option; ``training/cli.py:main`` prints it as one line and exits 2.
"""

from __future__ import annotations

import dataclasses
import os
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, TypeVar

from hg_marl.core.errors import ConfigError, HgMarlError, check_finite
from hg_marl.core.spec import Spec, collect_params, parse_spec
from hg_marl.training.outputs import check_output
from hg_marl_start import SCRIPT, stop_startup_timer

T = TypeVar("T")

MAX_DURATION = 10_000_000.0
"""Longest simulated run accepted from the command line (about 116 simulated days)."""


def parse_params(items: Iterable[str] | None, option: str) -> dict[str, str]:
    """Repeated ``key=value`` options as raw spec texts (converted later by the registry, by type).

    Raises:
        ConfigError: an item without ``=`` or a key given twice, naming ``option``.
    """
    return collect_params(items or (), option, ConfigError)


def spec_with(text: str, items: Iterable[str] | None, option: str, params_option: str) -> Spec:
    """The spec ``text`` (``--robot hybrid:criterion=vpi``) with ``--robot-param`` items added."""
    try:
        spec = parse_spec(text, option)
    except HgMarlError as exc:
        raise ConfigError(str(exc)) from None
    extra = parse_params(items, params_option)
    clash = sorted(set(spec.raw) & set(extra))
    if clash:
        raise ConfigError(f"{option} and {params_option} both set {', '.join(clash)}")
    return Spec(spec.name, {**spec.raw, **extra})


def check_duration(value: float, option: str = "--duration", scenario: str | None = None) -> float:
    """A simulated duration: finite, positive, at most :data:`MAX_DURATION`.

    With ``scenario``, also within :data:`~hg_marl.training.runner.MAX_CYCLES` cycles of
    its shortest action, so a sweep is refused before it claims its first run.
    """
    duration = check_finite(value, option, positive=True, maximum=MAX_DURATION)
    if scenario is not None:
        from hg_marl.core.scenario import load_scenario
        from hg_marl.training.runner import check_cycles

        check_cycles(duration, load_scenario(scenario).durations.shortest, option)
    return duration


def check_out_file(path: Path | None, option: str, suffixes: tuple[str, ...] = ()) -> Path | None:
    """An output file (None: not asked for), checked by :func:`~hg_marl.training.outputs.check_output`.

    Checked before any work is done, so a typo does not cost a run.
    """
    if path is None:
        return None
    return check_output(path, option, suffixes=suffixes)


def check_out_dir(path: Path, option: str) -> Path:
    """An output folder, checked by :func:`~hg_marl.training.outputs.check_output` (created later if missing)."""
    return check_output(path, option, folder=True)


def default_workers() -> int:
    """The commands' default ``--workers``: two processes, one on a one-CPU machine (a second would only compete)."""
    return min(2, os.cpu_count() or 1)


def check_workers(value: int) -> int:
    """A ``--workers`` the backends accept: the limit has one home, :func:`hg_marl.training.backends.check_workers`.

    Imported when called, so ``--help`` does not load the backends.
    """
    from hg_marl.training.backends import check_workers as accepted

    return accepted(value)


def name_list(text: str | None, option: str) -> tuple[str, ...]:
    """A comma list of names (``--robots a,b``); given but empty is an error, not 'all'."""
    if text is None:
        return ()
    names = tuple(x.strip() for x in text.split(",") if x.strip())
    if not names:
        raise ConfigError(f"{option} {text!r}: expected a comma list of names (omit the option for all)")
    return names


def default(config: type, name: str) -> Any:
    """The default of field ``name`` of a config dataclass (CLI defaults come from there, not restated)."""
    for f in dataclasses.fields(config):
        if f.name == name:
            if f.default is not dataclasses.MISSING:
                return f.default
            if f.default_factory is not dataclasses.MISSING:
                return f.default_factory()
    raise KeyError(f"{config.__name__} has no field {name!r}")


def checked(build: Callable[[], T]) -> T:
    """Run ``build``; turn a ValueError/KeyError (unknown name, bad parameter) into a CLI error.

    HgMarlErrors pass through to ``main``; the ValueErrors caught here come from code not
    yet on the error hierarchy.
    """
    try:
        return build()
    except HgMarlError:
        raise
    except (ValueError, KeyError, FileNotFoundError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        raise ConfigError(str(message)) from exc


def counting_bar(total: int, desc: str) -> tuple[Any, Callable[..., None]]:
    """A tqdm bar of ``total`` runs and its per-run callback, which closes the bar at the last run.

    So the bar's elapsed time and rate are those of the runs (what follows, aggregation
    and figures, is not counted in them) and the next line prints below a finished bar.
    """
    from tqdm import tqdm

    bar = tqdm(total=total, unit="run", desc=desc)

    def update(*_: Any) -> None:
        bar.update(1)
        if bar.n >= total:
            bar.close()

    if total == 0:
        bar.close()
    return bar, update


def command_start() -> float:
    """When a command's time budget began, on :func:`time.perf_counter`'s scale.

    Under the ``hg-marl`` script, the process's start: a person who typed
    ``--max-seconds 5`` waits from then, the interpreter's start-up and imports included.
    Called in-process (a test, a notebook), now: the process may have run for hours.
    From here the command's own budget reads the clock, so the start-up's timer
    (:func:`hg_marl_start.arm_startup_budget`) is stopped.
    """
    started = SCRIPT["started"]
    if started is None:
        return time.perf_counter()
    stop_startup_timer()
    return float(started)


def over_budget() -> None:
    """Note that the command was refused over its budget (the script then leaves at once)."""
    SCRIPT["over_budget"] = True
