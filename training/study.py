"""Study files: which robots meet which humans, where, for how long, from which seeds.

A study is a TOML file::

    name = "crossplay"
    scenarios = ["paper2015"]          # built-in names, generated:..., or .toml paths (relative to this file)
    seeds = 10                         # 0..9, or an explicit list [0, 4, 7]
    duration = 1100.0                  # simulated seconds per run
    oracle_max_states = 1500000        # the oracle's budget (model states); optional
    robots = ["planner", "hybrid:criterion=vpi"]   # specs (name:k=v,...), or tables:
    humans = ["cooperative", "lazy:p_idle=0.5"]

    [[robots]]                         # a table instead of a spec: name, params, optional label
    name = "hybrid"
    params = { criterion = "entropy", q_config = { features = "tabular" } }
    label = "hybrid-entropy"

and, for held-out partners (zero-shot coordination style), ``train = [...]`` and
``test = [...]`` lists of human specs in place of (or besides) ``humans``: every robot
meets every partner, and the report compares its scores on the train partners (those
its settings were chosen with) with those on the held-out test partners.

A partner population (:mod:`hg_marl.agents.humans.population`) adds its members as
humans labelled by member name::

    population = "../populations/paper2015.toml"   # relative to this file
    splits = ["held_out"]              # which members (default: train, validation, held_out)

A member's split is its group in the report: ``train`` members are train partners,
``held_out`` members are the held-out test partners (the generalisation gap compares
the two), ``validation`` members are reported as ``validation``.

:func:`load_study` validates everything before anything runs: each robot and human is
built once, each scenario loaded, each number checked, and a bad field is reported as
one :class:`StudyError` line naming ``path:line`` and the field.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from hg_marl.core.errors import (
    HgMarlError,
    NotRegularFileError,
    StudyError,
    check_digits,
    check_finite,
    check_int,
    read_limited,
    where,
)
from hg_marl.core.spec import AgentSpec, format_spec, parse_spec
from hg_marl.training.limits import MAX_SEED_VALUE, MAX_SEEDS, MAX_STUDY_BYTES, check_count, check_runs

ORACLE = "oracle"
"""Robot name of the oracle's optimal policy (plays only against stationary humans)."""

DEFAULT_ORACLE_MAX_STATES = 1_500_000
"""The oracle's budget when a study names none."""


@dataclass(frozen=True)
class Actor:
    """A robot or a human of a study: registry name, parameters, display label."""

    name: str
    params: Mapping[str, Any] = field(default_factory=dict)
    label: str = ""

    def spec(self) -> str:
        """The canonical ``name:k=v`` text."""
        return format_spec(self.name, self.params)


@dataclass(frozen=True)
class Study:
    """A validated study."""

    name: str
    path: Path
    robots: tuple[Actor, ...]
    humans: tuple[Actor, ...]
    """Every partner, train and test ones included (each once)."""
    scenarios: tuple[str, ...]
    seeds: tuple[int, ...]
    duration: float
    train: tuple[str, ...] = ()
    """Labels of the train partners."""
    test: tuple[str, ...] = ()
    """Labels of the held-out test partners."""
    oracle_max_states: int = DEFAULT_ORACLE_MAX_STATES
    validation: tuple[str, ...] = ()
    """Labels of the validation partners (population members of the ``validation`` split)."""

    def narrowed(
        self,
        seeds: int | None = None,
        robots: Sequence[str] = (),
        humans: Sequence[str] = (),
        scenarios: Sequence[str] = (),
    ) -> Study:
        """The first ``seeds`` seeds, the named robots and humans (by exact label, else registry name) and scenarios.

        Raises:
            StudyError: a name that is in the study under neither label nor registry name, or
                a scenario the study does not name.
        """

        def pick(actors: tuple[Actor, ...], names: Sequence[str], option: str) -> tuple[Actor, ...]:
            if not names:
                return actors
            unknown = [n for n in names if not any(n in (a.label, a.name) for a in actors)]
            if unknown:
                known = ", ".join(a.label for a in actors)
                raise StudyError(f"{option}: {', '.join(unknown)} not in {self.path} (it has {known})")
            # A name that is some actor's exact label picks that actor only ("planner" is
            # the plain planner, not "planner:partner_aware=true"); any other name picks
            # every actor registered under it ("hybrid": all the hybrids).
            labels = {a.label for a in actors}
            return tuple(a for a in actors if a.label in names or (a.name in names and a.name not in labels))

        chosen_humans = pick(self.humans, humans, "--humans")
        labels = {h.label for h in chosen_humans}
        if seeds is not None and seeds < 1:
            raise StudyError(f"--seeds: expected at least 1, got {seeds}")

        # A scenario is named as in the study, or a .toml path by its file stem.
        def named(scenario: str) -> bool:
            return scenario in scenarios or (scenario.endswith(".toml") and Path(scenario).stem in scenarios)

        known_names = set(self.scenarios) | {Path(s).stem for s in self.scenarios if s.endswith(".toml")}
        unknown = [s for s in scenarios if s not in known_names]
        if unknown:
            raise StudyError(
                f"--scenarios: {', '.join(unknown)} not in {self.path} (it has {', '.join(self.scenarios)})"
            )
        return replace(
            self,
            scenarios=tuple(s for s in self.scenarios if named(s)) if scenarios else self.scenarios,
            robots=pick(self.robots, robots, "--robots"),
            humans=chosen_humans,
            seeds=self.seeds[:seeds] if seeds is not None else self.seeds,
            train=tuple(t for t in self.train if t in labels),
            test=tuple(t for t in self.test if t in labels),
            validation=tuple(t for t in self.validation if t in labels),
        )

    def group(self, human_label: str) -> str:
        """``train``, ``test``, ``validation`` or ``""`` for a partner."""
        if human_label in self.train:
            return "train"
        if human_label in self.test:
            return "test"
        return "validation" if human_label in self.validation else ""


class _Source:
    """The study file's text, to name the line of a field in messages."""

    def __init__(self, path: Path, text: str) -> None:
        self.path, self.lines = path, text.splitlines()

    def line(self, key: str, index: int | None = None, value: Any = None) -> int | None:
        """Best line for ``key`` (its ``index``-th table, or the line holding ``value``)."""
        header = re.compile(rf"^\s*\[\[\s*{re.escape(key)}\s*\]\]")
        assign = re.compile(rf"^\s*{re.escape(key)}\s*=")
        start = None
        tables = [i for i, text in enumerate(self.lines) if header.match(text)]
        if index is not None and index < len(tables) and not isinstance(value, str):
            return tables[index] + 1
        for i, text in enumerate(self.lines):
            if assign.match(text):
                start = i
                break
        if isinstance(value, str):
            quoted = [f'"{value}"', f"'{value}'"]
            for i in range(start or 0, len(self.lines)):
                if any(q in self.lines[i] for q in quoted):
                    return i + 1
        if start is not None:
            return start + 1
        return tables[0] + 1 if tables else None

    def error(self, message: str, key: str, index: int | None = None, value: Any = None) -> StudyError:
        return StudyError(f"{where(self.path, self.line(key, index, value))}: {message}")


def _actor(item: Any, key: str, index: int, src: _Source) -> Actor:
    what = f"{key}[{index}]"
    if isinstance(item, str):
        try:
            spec = parse_spec(item, what)
        except HgMarlError as exc:
            raise src.error(str(exc), key, index, item) from None
        typed = AgentSpec.of(spec, what)
        return Actor(typed.name, dict(typed.params), str(typed))
    if isinstance(item, dict):
        unknown = sorted(set(item) - {"name", "params", "label"})
        if unknown:
            raise src.error(f"{what}: unknown field(s) {', '.join(unknown)} (expected name, params, label)", key, index)
        name, params, label = item.get("name"), item.get("params", {}), item.get("label")
        if not isinstance(name, str) or not name:
            raise src.error(f"{what}.name: expected a registry name", key, index)
        if not isinstance(params, dict):
            raise src.error(f"{what}.params: expected a table of parameters", key, index)
        if label is not None and not isinstance(label, str):
            raise src.error(f"{what}.label: expected a text", key, index)
        return Actor(name, dict(params), label or format_spec(name, params))
    raise src.error(f"{what}: expected a spec like 'lazy:p_idle=0.5' or a table with name and params", key, index)


def _actors(data: Mapping[str, Any], key: str, src: _Source) -> list[tuple[Actor, int]]:
    items = data.get(key, [])
    if not isinstance(items, list):
        raise src.error(f"{key}: expected a list", key)
    return [(_actor(item, key, i, src), i) for i, item in enumerate(items)]


def _check_robot(actor: Actor, index: int, src: _Source) -> None:
    from hg_marl.agents.robots import make_robot

    if actor.name == ORACLE:
        if actor.params:
            raise src.error(f"robots[{index}]: the oracle takes no parameters", "robots", index, actor.label)
        return
    try:
        make_robot(actor.name, **actor.params)
    except (HgMarlError, ValueError, TypeError) as exc:
        raise src.error(f"robots[{index}]: {exc}", "robots", index, actor.label) from None


def _check_human(actor: Actor, key: str, index: int, src: _Source) -> None:
    from hg_marl.agents.humans import make_human

    try:
        make_human(actor.name, **actor.params)
    except (HgMarlError, ValueError, TypeError) as exc:
        raise src.error(f"{key}[{index}]: {exc}", key, index, actor.label) from None


def _scenario(value: Any, index: int, src: _Source) -> str:
    from hg_marl.core.scenario import load_scenario

    if not isinstance(value, str):
        raise src.error(f"scenarios[{index}]: expected a scenario name or path", "scenarios")
    text = value
    if value.endswith(".toml") and not Path(value).is_absolute():
        text = str((src.path.parent / value).resolve())
    try:
        load_scenario(text)
    except HgMarlError as exc:
        raise src.error(f"scenarios[{index}]: {exc}", "scenarios", value=value) from None
    return text


_GROUP_OF_SPLIT = {"train": "train", "validation": "validation", "held_out": "test"}
"""A population split's group in the study (held-out members are its test partners)."""


def _population(data: Mapping[str, Any], src: _Source) -> list[tuple[Actor, str]]:
    """The members of the study's population in the chosen splits, as human actors labelled by name."""
    from hg_marl.agents.humans.population import SPLITS, load_population

    if "population" not in data:
        if "splits" in data:
            raise src.error("splits: only with a population", "splits")
        return []
    value = data["population"]
    if not isinstance(value, str) or not value:
        raise src.error("population: expected the path of a population file", "population")
    path = Path(value)
    if not path.is_absolute():
        path = (src.path.parent / path).resolve()
    splits = data.get("splits", list(SPLITS))
    if not isinstance(splits, list) or not splits or not all(isinstance(s, str) for s in splits):
        raise src.error(f"splits: expected a non-empty list of {', '.join(SPLITS)}", "splits")
    bad = [s for s in splits if s not in SPLITS]
    if bad:
        raise src.error(f"splits: unknown split {bad[0]!r} (expected {', '.join(SPLITS)})", "splits", value=bad[0])
    try:
        population = load_population(path)
    except HgMarlError as exc:
        raise src.error(f"population: {exc}", "population") from None
    out = []
    for split in SPLITS:
        if split in splits:
            for member in population.members(split):
                typed = AgentSpec.parse(member.spec, member.name)
                out.append((Actor(typed.name, dict(typed.params), member.name), split))
    if not out:
        raise src.error(f"splits: the population has no members in {', '.join(splits)}", "splits")
    return out


def load_study(path: str | Path) -> Study:
    """Read and validate a study file.

    Raises:
        StudyError: an unreadable file or a bad field (``path:line: field: problem``), a
            count over its limit (:mod:`hg_marl.training.limits`), or a duration no run
            could finish within :data:`~hg_marl.training.runner.MAX_CYCLES` cycles.
    """
    from hg_marl.core.scenario import load_scenario
    from hg_marl.training.runner import check_cycles

    path = Path(path)
    try:
        raw = read_limited(path, MAX_STUDY_BYTES)
        if raw is None:
            raise StudyError(f"{path}: larger than {MAX_STUDY_BYTES} bytes (the limit of a study file)")
        text = raw.decode("utf-8")
    except NotRegularFileError:
        raise StudyError(f"{path}: cannot read the study file (not a regular file)") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise StudyError(f"{path}: cannot read the study file ({exc.__class__.__name__})") from None
    check_digits(text, str(path), StudyError, lines=True)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise StudyError(f"{path}: not valid TOML: {exc}") from None
    src = _Source(path, text)
    known = {
        "name",
        "scenarios",
        "seeds",
        "duration",
        "robots",
        "humans",
        "train",
        "test",
        "oracle_max_states",
        "population",
        "splits",
    }
    for key in data:
        if key not in known:
            raise src.error(f"unknown field {key!r} (expected one of {', '.join(sorted(known))})", key)
    try:
        duration = check_finite(data.get("duration", 1100.0), "duration", positive=True, error=StudyError)
        seeds_field = data.get("seeds", 10)
        if isinstance(seeds_field, list):
            check_count(len(seeds_field), "seeds", MAX_SEEDS, minimum=0, error=StudyError)
            seeds = tuple(
                check_int(s, "seeds", minimum=0, maximum=MAX_SEED_VALUE, error=StudyError) for s in seeds_field
            )
            if len(set(seeds)) != len(seeds) or not seeds:
                raise StudyError("seeds: expected distinct seeds, at least one")
        else:  # the count is checked before the range becomes a tuple
            seeds = tuple(range(check_count(seeds_field, "seeds", MAX_SEEDS, error=StudyError)))
        max_states = check_int(
            data.get("oracle_max_states", DEFAULT_ORACLE_MAX_STATES), "oracle_max_states", minimum=1, error=StudyError
        )
    except StudyError as exc:
        field_name = str(exc).split(":")[0]
        raise src.error(str(exc), field_name) from None
    name = data.get("name", path.stem)
    if not isinstance(name, str):
        raise src.error("name: expected a text", "name")
    scenarios_field = data.get("scenarios", ["paper2015"])
    if not isinstance(scenarios_field, list) or not scenarios_field:
        raise src.error("scenarios: expected a non-empty list", "scenarios")
    scenarios = tuple(_scenario(s, i, src) for i, s in enumerate(scenarios_field))
    for scenario in scenarios:  # a duration no run could finish is refused here, not once the runs start
        try:
            check_cycles(duration, load_scenario(scenario).durations.shortest, "duration")
        except HgMarlError as exc:
            raise src.error(f"{exc} ({scenario})", "duration") from None
    robots = _actors(data, "robots", src)
    if not robots:
        raise src.error("robots: expected at least one robot", "robots")
    for actor, i in robots:
        _check_robot(actor, i, src)
    humans: dict[str, Actor] = {}
    groups: dict[str, list[str]] = {"train": [], "test": []}
    for key in ("humans", "train", "test"):
        for actor, i in _actors(data, key, src):
            _check_human(actor, key, i, src)
            humans.setdefault(actor.label, actor)
            if key in groups:
                groups[key].append(actor.label)
    groups["validation"] = []
    for actor, split in _population(data, src):
        if actor.label in humans:
            raise src.error(f"population: member {actor.label!r} has the label of another human", "population")
        humans[actor.label] = actor
        groups[_GROUP_OF_SPLIT[split]].append(actor.label)
    if not humans:
        raise src.error("humans: expected at least one human (humans, train, test or population)", "humans")
    both = set(groups["train"]) & set(groups["test"])
    if both:
        raise src.error(f"test: {', '.join(sorted(both))} also in train (held-out partners must be new)", "test")
    try:
        check_runs(len(robots) * len(humans) * len(scenarios) * len(seeds), "robots x humans x scenarios x seeds")
    except HgMarlError as exc:
        raise src.error(str(exc), "seeds") from None
    labels = [a.label for a, _ in robots]
    if len(set(labels)) != len(labels):
        raise src.error("robots: two robots with the same label (give them distinct labels)", "robots")
    return Study(
        name=name,
        path=path,
        robots=tuple(a for a, _ in robots),
        humans=tuple(humans.values()),
        scenarios=scenarios,
        seeds=seeds,
        duration=duration,
        train=tuple(groups["train"]),
        test=tuple(groups["test"]),
        oracle_max_states=max_states,
        validation=tuple(groups["validation"]),
    )
