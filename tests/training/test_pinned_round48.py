"""Round 48 of the fresh planted bugs: the values its missed bug changed, pinned.

The expected values are stated independently of the code under test: ``hg-marl evaluate``
hands ``write_outputs`` one headroom per scenario keyed by the scenario as the study names
it (``training/evaluate.py``: ``{scenario: ... for scenario in study.scenarios}``, a name
or a TOML path), and report.md's BR-Prox table prints each row's scenario by its file name
with that scenario's headroom beside it. So a scenario given as a path shows the headroom
given for that path, and two scenario files of the same name in different folders each
show their own (worked by hand below: the numbers are the ones handed in, to two decimals).
"""

from __future__ import annotations

from hg_marl.training.report import br_prox_section

# --- training/report.py ---


def test_br_prox_headroom_is_the_one_given_for_the_scenario_as_the_study_names_it() -> None:
    """Headrooms keyed by scenario paths (as ``study.scenarios`` holds them) reach their rows:
    the table names each row by its file name, but reads its headroom by the full scenario."""
    rows = [
        {"robot": "A", "scenario": "scenarios/hard/x.toml", "split": "test", "iqm": 0.5, "ci": [0.25, 0.75], "runs": 4},
        {"robot": "A", "scenario": "scenarios/easy/x.toml", "split": "test", "iqm": 1.0, "ci": None, "runs": 4},
        {"robot": "B", "scenario": "paper2015", "split": "all", "iqm": 0.25, "ci": None, "runs": 2},
    ]
    headrooms: dict[str, float | None] = {
        "scenarios/hard/x.toml": 0.4,
        "scenarios/easy/x.toml": 0.05,
        "paper2015": None,
    }
    lines = br_prox_section({"br_prox": rows}, headrooms)
    # By hand: file name | headroom handed in for that scenario (None: "-") | split | robot | IQM | CI | runs.
    assert lines[-4:] == [
        "| x.toml | 0.40 | test | A | 0.50 | [0.25, 0.75] | 4 |",
        "| x.toml | 0.05 | test | A | 1.00 | - | 4 |",
        "| paper2015 | - | all | B | 0.25 | - | 2 |",
        "",
    ]
