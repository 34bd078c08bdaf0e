"""Study files' defaults, refusals with their ``path:line``, groups and narrowing, pinned for the mutation gate.

Expected values are worked by hand from the module's docstring and its messages: the
documented defaults (the study's name is its file's stem, seeds 0..9, 1100 s,
``paper2015``, an oracle budget of 1,500,000 states); each bad field refused in one
``StudyError`` line naming the file, the line the field is on (a table's own ``[[...]]``
header for a table, the line holding a quoted value, else the field's assignment) and
the field; a partner labelled twice kept once, in its first place; a population's
members taken in the splits' fixed order; narrowing by exact label or registry name.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from hg_marl.core.errors import StudyError
from hg_marl.training.study import Actor, Study, load_study

POPULATION = """\
name = "two"
scenario = "paper2015"

[[members]]
name = "m00"
split = "train"
spec = "preference"

[[members]]
name = "m02"
split = "held_out"
spec = "preference:accept=0.5"
"""


def _write(tmp_path: Path, text: str, name: str = "study.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    (tmp_path / "pop.toml").write_text(POPULATION)
    return path


def _refusal(tmp_path: Path, text: str) -> str:
    path = _write(tmp_path, text)
    with pytest.raises(StudyError) as info:
        load_study(path)
    message = str(info.value)
    assert message.startswith(f"{path}:") and "\n" not in message
    return message[len(str(path)) + 1 :]  # "line: field: problem"


def test_a_study_naming_only_its_robots_and_humans_takes_the_documented_defaults(tmp_path: Path) -> None:
    study = load_study(_write(tmp_path, 'robots = ["planner"]\nhumans = ["cooperative"]\n', "defaults.toml"))
    assert study.name == "defaults"
    assert study.seeds == tuple(range(10))
    assert study.duration == 1100.0
    assert study.scenarios == ("paper2015",)
    assert study.oracle_max_states == 1_500_000
    assert (study.train, study.test, study.validation) == ((), (), ())
    assert [(r.name, r.label) for r in study.robots] == [("planner", "planner")]


def test_a_robot_table_is_labelled_by_its_spec_unless_it_has_a_label(tmp_path: Path) -> None:
    """Without a label a table is named by its canonical spec (``name:k=v``, keys sorted, values as
    compact JSON: ``false``); with one, by that label."""
    text = (
        'humans = ["cooperative"]\n'
        "[[robots]]\n"
        'name = "hybrid"\n'
        'params = { criterion = "vpi", share_objects = false }\n'
        "[[robots]]\n"
        'name = "planner"\n'
        'label = "mine"\n'
    )
    study = load_study(_write(tmp_path, text))
    assert [r.label for r in study.robots] == ["hybrid:criterion=vpi,share_objects=false", "mine"]
    assert study.robots[0].params == {"criterion": "vpi", "share_objects": False}
    assert study.robots[0].spec() == "hybrid:criterion=vpi,share_objects=false"
    assert Actor("lazy", {"p_idle": 0.5}).spec() == "lazy:p_idle=0.5"


def test_a_partner_listed_in_humans_and_train_is_one_human_in_the_train_group(tmp_path: Path) -> None:
    """``lazy`` in humans and train: once, in its first place; cooperative is a held-out test partner."""
    text = 'robots = ["planner"]\nhumans = ["lazy", "no_handover"]\ntrain = ["lazy"]\ntest = ["cooperative"]\n'
    study = load_study(_write(tmp_path, text))
    assert [h.label for h in study.humans] == ["lazy", "no_handover", "cooperative"]
    assert (study.train, study.test) == (("lazy",), ("cooperative",))
    assert [study.group(h.label) for h in study.humans] == ["train", "", "test"]


def test_explicit_seeds_are_kept_as_listed(tmp_path: Path) -> None:
    study = load_study(_write(tmp_path, 'seeds = [7, 0, 4]\nrobots = ["planner"]\nhumans = ["lazy"]\n'))
    assert study.seeds == (7, 0, 4)


def test_the_oracle_robot_takes_no_parameters_and_needs_no_registry_entry(tmp_path: Path) -> None:
    """Alone it loads; as a table with params it is refused on its ``[[robots]]`` header (line 2)."""
    study = load_study(_write(tmp_path, 'robots = ["oracle"]\nhumans = ["cooperative"]\n'))
    assert [r.name for r in study.robots] == ["oracle"]
    text = 'humans = ["cooperative"]\n[[robots]]\nname = "oracle"\nparams = { x = 1 }\n'
    assert _refusal(tmp_path, text) == "2: robots[0]: the oracle takes no parameters"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ('robots = "planner"\nhumans = ["lazy"]\n', "1: robots: expected a list"),
        ('robots = []\nhumans = ["lazy"]\n', "1: robots: expected at least one robot"),
        ('humans = ["lazy"]\nrobots = ["planner", 3]\n', "2: robots[1]: expected a spec like 'lazy:p_idle=0.5'"),
        ('robots = ["planner"]\n', " humans: expected at least one human"),  # no such field: no line
        ('robots = ["planner"]\nhumans = ["lazy"]\ncolour = 1\n', "3: unknown field 'colour'"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nname = 3\n', "3: name: expected a text"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nscenarios = []\n', "3: scenarios: expected a non-empty list"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nscenarios = [4]\n', "3: scenarios[0]: expected a scenario name"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nseeds = [1, 1]\n', "3: seeds: expected distinct seeds"),
        ('robots = ["planner"]\nhumans = ["lazy"]\nseeds = []\n', "3: seeds: expected distinct seeds, at least one"),
        ('robots = ["planner"]\nhumans = ["lazy"]\noracle_max_states = 0\n', "3: oracle_max_states"),
        ('robots = ["planner", "planner"]\nhumans = ["lazy"]\n', "1: robots: two robots with the same label"),
        ('robots = ["planner"]\ntrain = ["lazy"]\ntest = ["cooperative", "lazy"]\n', "3: test: lazy also in train"),
        ('robots = ["planner"]\nhumans = ["lazy"]\npopulation = 3\n', "3: population: expected the path"),
        ('robots = ["planner"]\nhumans = ["lazy"]\npopulation = ""\n', "3: population: expected the path"),
        ('robots = ["planner"]\npopulation = "pop.toml"\nsplits = []\n', "3: splits: expected a non-empty list"),
        ('robots = ["planner"]\npopulation = "pop.toml"\nsplits = [1]\n', "3: splits: expected a non-empty list"),
        ('robots = ["planner"]\npopulation = "pop.toml"\nsplits = "train"\n', "3: splits: expected a non-empty"),
        (
            'robots = ["planner"]\npopulation = "pop.toml"\nsplits = ["validation"]\n',
            "3: splits: the population has no members in validation",
        ),
    ],
)
def test_a_bad_field_is_refused_on_its_line(tmp_path: Path, text: str, expected: str) -> None:
    assert _refusal(tmp_path, text).startswith(expected)


@pytest.mark.parametrize(
    ("table", "expected"),
    [
        ('name = "planner"\ncolour = 1\n', "robots[1]: unknown field(s) colour (expected name, params, label)"),
        ('name = ""\n', "robots[1].name: expected a registry name"),
        ("params = {}\n", "robots[1].name: expected a registry name"),
        ('name = "planner"\nparams = 3\n', "robots[1].params: expected a table of parameters"),
        ('name = "planner"\nlabel = 3\n', "robots[1].label: expected a text"),
    ],
)
def test_a_bad_robot_table_is_refused_on_its_own_header(tmp_path: Path, table: str, expected: str) -> None:
    """The second of two ``[[robots]]`` tables: its header is line 5."""
    text = 'humans = ["lazy"]\n[[robots]]\nname = "planner"\nlabel = "first"\n[[robots]]\n' + table
    assert _refusal(tmp_path, text) == f"5: {expected}"


def test_a_bad_human_is_refused_on_the_line_holding_it_after_its_field(tmp_path: Path) -> None:
    """The same quoted spec on line 1 (the study's name) is not the field's: the search starts at ``humans``."""
    text = 'name = "lazy:p_idle=2.0"\nrobots = ["planner"]\nhumans = [\n"cooperative",\n"lazy:p_idle=2.0",\n]\n'
    assert _refusal(tmp_path, text).startswith("5: humans[1]: ")


def test_a_bad_value_on_the_fields_own_first_line_is_refused_there_not_where_it_recurs(tmp_path: Path) -> None:
    """``humans`` is assigned on line 1, which holds the bad spec; the same quoted text on the last
    line (the study's name) comes after it: the refusal names line 1."""
    text = 'humans = ["lazy:p_idle=2.0"]\nrobots = ["planner"]\nname = "lazy:p_idle=2.0"\n'
    assert _refusal(tmp_path, text).startswith("1: humans[0]: ")


@pytest.mark.parametrize("duration", ["0.0", "-5.0"])
def test_a_duration_must_be_positive(tmp_path: Path, duration: str) -> None:
    """No run lasts zero or negative seconds: refused on the duration's line (2)."""
    text = f'robots = ["planner"]\nduration = {duration}\nhumans = ["lazy"]\n'
    assert _refusal(tmp_path, text).startswith("2: duration")


def test_a_study_over_the_run_limit_is_refused_naming_its_number_of_runs(tmp_path: Path) -> None:
    """3 robots x 4 humans x 2 scenarios x 8,400 seeds = 201,600 runs, over the 200,000 of
    ``MAX_RUNS``: refused on the seeds' line (3) with that product, before any run is listed."""
    text = (
        'robots = ["planner", "random", "habit"]\n'
        'humans = ["cooperative", "lazy", "no_handover", "noisy"]\n'
        "seeds = 8400\n"
        'scenarios = ["paper2015", "roboergosum"]\n'
    )
    assert _refusal(tmp_path, text) == (
        "3: robots x humans x scenarios x seeds: 201,600 runs, over the limit of 200,000 runs"
    )


def test_a_bad_table_human_without_an_assignment_is_refused_on_its_header(tmp_path: Path) -> None:
    text = 'robots = ["planner"]\n\n[[test]]\nname = "lazy"\nparams = { p_idle = 2.0 }\n'
    assert _refusal(tmp_path, text).startswith("3: test[0]: ")


def test_an_unreadable_or_malformed_file_is_refused_in_one_line(tmp_path: Path) -> None:
    folder = tmp_path / "folder.toml"
    folder.mkdir()
    with pytest.raises(StudyError, match=r": cannot read the study file \(IsADirectoryError\)$"):
        load_study(folder)
    bad = _write(tmp_path, "robots = [\n")
    with pytest.raises(StudyError) as info:
        load_study(bad)
    assert str(info.value).startswith(f"{bad}: not valid TOML: ")


def test_a_relative_scenario_file_is_read_beside_the_study(tmp_path: Path) -> None:
    layout = Path(__file__).parents[2] / "hg_marl/core/scenarios/forced_coordination.toml"
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "mine.toml").write_text(layout.read_text())
    study = load_study(_write(tmp_path, 'robots = ["planner"]\nhumans = ["lazy"]\nscenarios = ["sub/mine.toml"]\n'))
    assert study.scenarios == (str((tmp_path / "sub" / "mine.toml").resolve()),)


def test_population_members_come_in_the_splits_fixed_order_whatever_the_order_asked(tmp_path: Path) -> None:
    """``splits = ["held_out", "train"]``: train members first (train, validation, held_out order)."""
    study = load_study(
        _write(tmp_path, 'robots = ["planner"]\npopulation = "pop.toml"\nsplits = ["held_out", "train"]\n')
    )
    assert [h.label for h in study.humans] == ["m00", "m02"]
    assert (study.train, study.test, study.validation) == (("m00",), ("m02",), ())
    every = load_study(_write(tmp_path, 'robots = ["planner"]\npopulation = "pop.toml"\n'))
    assert [h.label for h in every.humans] == ["m00", "m02"]


def _study() -> Study:
    robots = (
        Actor("planner", {}, "planner"),
        Actor("planner", {"partner_aware": True}, "planner:partner_aware=true"),
        Actor("hybrid", {"criterion": "vpi"}, "hybrid:criterion=vpi"),
        Actor("hybrid", {"criterion": "entropy"}, "h-entropy"),
    )
    humans = tuple(Actor(h, {}, h) for h in ("cooperative", "lazy", "noisy", "no_handover"))
    return Study(
        name="s",
        path=Path("s.toml"),
        robots=robots,
        humans=humans,
        scenarios=("paper2015", "/x/my_layout.toml"),
        seeds=(0, 1, 2),
        duration=100.0,
        train=("cooperative",),
        test=("lazy",),
        validation=("noisy",),
    )


def test_narrowing_by_an_exact_label_picks_that_actor_and_by_a_registry_name_every_one_of_it() -> None:
    study = _study()
    assert [r.label for r in study.narrowed(robots=["planner"]).robots] == ["planner"]
    assert [r.label for r in study.narrowed(robots=["hybrid"]).robots] == ["hybrid:criterion=vpi", "h-entropy"]
    assert [r.label for r in study.narrowed(robots=["h-entropy", "planner"]).robots] == ["planner", "h-entropy"]
    assert study.narrowed().robots == study.robots


def test_narrowing_keeps_each_group_to_the_chosen_humans() -> None:
    narrowed = _study().narrowed(humans=["noisy", "cooperative"])
    assert [h.label for h in narrowed.humans] == ["cooperative", "noisy"]
    assert (narrowed.train, narrowed.test, narrowed.validation) == (("cooperative",), (), ("noisy",))
    assert narrowed.group("noisy") == "validation" and narrowed.group("lazy") == ""


def test_narrowing_seeds_takes_the_first_ones_and_refuses_fewer_than_one() -> None:
    study = _study()
    assert study.narrowed(seeds=1).seeds == (0,)
    assert study.narrowed(seeds=5).seeds == (0, 1, 2)
    with pytest.raises(StudyError, match=r"^--seeds: expected at least 1, got 0$"):
        study.narrowed(seeds=0)


def test_narrowing_refuses_an_unknown_name_listing_what_the_study_has() -> None:
    study = _study()
    with pytest.raises(StudyError) as info:
        study.narrowed(humans=["lazy", "ghost"])
    assert str(info.value) == "--humans: ghost not in s.toml (it has cooperative, lazy, noisy, no_handover)"
    with pytest.raises(
        StudyError, match=r"^--scenarios: kitchen not in s.toml \(it has paper2015, /x/my_layout.toml\)$"
    ):
        study.narrowed(scenarios=["kitchen"])
    assert study.narrowed(scenarios=["my_layout"]).scenarios == ("/x/my_layout.toml",)
    assert study.narrowed(scenarios=["paper2015"]).scenarios == ("paper2015",)


def test_a_fifo_or_a_device_is_refused_unread(tmp_path: Path) -> None:
    """Opening a FIFO blocks until a writer comes and ``/dev/zero`` never ends: both are
    refused from their file type, before any read (a hang here is the bug)."""
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(StudyError, match=r": cannot read the study file \(not a regular file\)$"):
            load_study(path)


def test_a_study_file_is_read_up_to_one_mebibyte(tmp_path: Path) -> None:
    """1 MiB exactly is read (then refused for what it holds, not its size); a byte more is refused by size."""
    limit = 1 << 20
    body = "robots = [\n"  # not valid TOML: a file read whole is refused by the parser
    exact = tmp_path / "exact.toml"
    exact.write_text(body + "#" * (limit - len(body)))
    assert exact.stat().st_size == limit
    with pytest.raises(StudyError, match=r": not valid TOML: "):
        load_study(exact)
    over = tmp_path / "over.toml"
    over.write_text(body + "#" * (limit - len(body) + 1))
    with pytest.raises(StudyError, match=rf"over\.toml: larger than {limit} bytes \(the limit of a study file\)$"):
        load_study(over)


def test_the_oracle_budget_may_be_a_single_state(tmp_path: Path) -> None:
    """``oracle_max_states`` counts model states: 1 is a budget (every oracle then refused,
    the study falling back to its best robot), 0 is not."""
    text = 'robots = ["planner"]\nhumans = ["cooperative"]\noracle_max_states = {}\n'
    assert load_study(_write(tmp_path, text.format(1))).oracle_max_states == 1
    assert _refusal(tmp_path, text.format(0)).startswith("3: oracle_max_states")


def test_evaluate_refuses_a_fifo_study_in_one_line_and_writes_nothing(tmp_path: Path) -> None:
    from tests.cli_helpers import run_main

    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    out = tmp_path / "out"
    code, _, err = run_main(["evaluate", str(fifo), "--out", str(out)])
    assert code == 2 and err.strip().splitlines() == [f"error: {fifo}: cannot read the study file (not a regular file)"]
    assert not out.exists()
