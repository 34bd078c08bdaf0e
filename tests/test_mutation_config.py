"""The mutation stage's configuration stays valid as modules move (checked by ``make test``)."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def mutation():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("mutation_run", ROOT / "mutation" / "run.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["mutation_run"] = module
    spec.loader.exec_module(module)
    return module


def test_every_module_and_test_file_exists(mutation) -> None:  # type: ignore[no-untyped-def]
    modules, defaults = mutation.load_modules()
    assert 0.0 <= defaults["target"] <= 1.0 and defaults["sample"] >= 1
    for m in modules.values():
        assert (ROOT / m.path).is_file(), f"mutation/modules.toml: modules.{m.key}.path"
        for t in m.tests:
            assert (ROOT / t.split("::")[0]).exists(), f"mutation/modules.toml: modules.{m.key}.tests: {t}"


def test_a_renamed_module_is_named_in_one_line(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    config = tmp_path / "modules.toml"
    config.write_text(
        '[defaults]\nsample = 2\nseed = 0\nfail_under = 0.0\ntarget = 0.9\n[modules.gone]\npath = "agents/gone.py"\n'
        'tests = ["tests/agents/test_meta.py"]\n'
    )
    with pytest.raises(mutation.ConfigError, match=r"modules\.gone\.path'.*renamed\? update this entry"):
        mutation.load_modules(config)


def test_equivalents_parse_and_match_by_operator_or_line(mutation) -> None:  # type: ignore[no-untyped-def]
    equivalents = mutation.load_equivalents()
    assert equivalents and all(e.why for e in equivalents)
    by_operator = mutation.Equivalent("*", "why", operator="core/ReplaceComparisonOperator_Is_Eq")
    assert by_operator.matches("vpi", "core/ReplaceComparisonOperator_Is_Eq", "a is b", "a == b")
    assert not by_operator.matches("vpi", "core/NumberReplacer", "x = 1", "x = 2")
    by_line = mutation.Equivalent("world", "why", removed="if a > b:")
    assert by_line.matches("world", "any", "if a > b:", "if a >= b:")
    assert not by_line.matches("oracle", "any", "if a > b:", "if a >= b:")


def load_planted() -> Any:
    """``mutation/planted.py`` as a module (it imports ``run`` from its own folder)."""
    sys.path.insert(0, str(ROOT / "mutation"))
    try:
        spec = importlib.util.spec_from_file_location("mutation_planted", ROOT / "mutation" / "planted.py")
        assert spec is not None and spec.loader is not None
        planted = importlib.util.module_from_spec(spec)
        sys.modules["mutation_planted"] = planted  # dataclasses look their module up there
        spec.loader.exec_module(planted)
    finally:
        sys.path.remove(str(ROOT / "mutation"))
    return planted


def test_every_planted_bug_still_applies() -> None:
    """Each bug of ``mutation/planted.py`` finds its line once, so the script cannot rot unnoticed."""
    planted = load_planted()
    assert len(planted.BUGS) == 6
    for bug in planted.BUGS:
        text = (ROOT / bug.path).read_text()
        assert text.count(bug.old) == 1, f"mutation/planted.py: {bug.name}: not found once in {bug.path}"
        assert bug.old != bug.new
        assert all((ROOT / t).exists() for t in bug.tests), bug.name


def test_every_fresh_bug_still_applies() -> None:
    """Every bug of every round (``planted.ALL``) finds its code once and names tests that exist.

    Only ``BUGS`` was checked before, and 27 bugs of the fresh rounds rotted unnoticed as the
    code moved on (``python mutation/planted.py`` stops at the first such bug).
    """
    planted = load_planted()
    names = [bug.name for bug in planted.ALL]
    assert len(names) == len(set(names)), "mutation/planted.py: two bugs share a name"
    retired = {name for name, _ in getattr(planted, "RETIRED", ())}
    assert all(why for _, why in getattr(planted, "RETIRED", ()))
    assert not retired & set(names), "mutation/planted.py: a retired bug is still planted"
    for bug in planted.ALL:
        text = (ROOT / bug.path).read_text()
        assert text.count(bug.old) == 1, f"mutation/planted.py: {bug.name}: not found once in {bug.path}"
        assert bug.old != bug.new, bug.name
        for test in bug.tests:
            assert (ROOT / test.split("::")[0]).exists(), f"mutation/planted.py: {bug.name}: {test}"


def test_annotation_mutants_are_left_out_of_the_sample_but_code_mutants_are_not(mutation) -> None:  # type: ignore[no-untyped-def]
    equivalents = mutation.load_equivalents()
    op = "core/ReplaceBinaryOperator_BitOr_Sub"
    signature = "    def get(self, job: Job, key: str | None = None) -> StoredRun | None:"
    code = "        flags = a | b"
    assert any(e.judges_line("store", op, signature) for e in equivalents)
    assert not any(e.judges_line("store", op, code) for e in equivalents)
    # an entry that names the mutated text cannot judge a line before the mutant exists
    by_text = mutation.Equivalent("store", "why", removed="x = 1", added="x = 2")
    assert by_text.matches("store", "any", "x = 1", "x = 2") and not by_text.judges_line("store", "any", "x = 1")


def test_a_module_its_package_shadows_is_found_in_the_scratch_copy(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    """``agents/models/__init__.py`` re-exports the function ``solve`` under the name of
    its module: the layout check must still find the module file in the scratch copy."""
    modules, _ = mutation.load_modules()
    scratch = mutation.scratch_copy(tmp_path / "copy")
    assert mutation._check_layout(scratch, [modules["model_solve"], modules["world"]]) == {}
    # and a module found elsewhere (the standard library's) or nowhere is named, with where it was found
    elsewhere = mutation.Module("json_decoder", "json/decoder.py", ("tests",), 1, 0.0)
    missing = mutation.Module("gone", "agents/gone.py", ("tests",), 1, 0.0)
    wrong = mutation._check_layout(scratch, [modules["world"], elsewhere, missing])
    assert sorted(wrong) == ["gone", "json_decoder"]
    assert "not the scratch copy" in wrong["json_decoder"] and "decoder.py" in wrong["json_decoder"]
    assert "ModuleNotFoundError" in wrong["gone"]


def test_the_warm_runner_sees_each_edit_on_disk_and_stops_a_hung_run(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    """Each test run is a child forked from the warm server: it must import the package
    as it is on disk now (a mutant written after the server started), report pytest's
    status, and be killed when its time is up (a mutant that loops forever)."""
    package = tmp_path / "hg_marl"
    package.mkdir()
    (package / "__init__.py").write_text("VALUE = 1\n")
    (tmp_path / "test_value.py").write_text("import hg_marl\n\n\ndef test_value():\n    assert hg_marl.VALUE == 1\n")
    args = ["-q", "-p", "no:cacheprovider", "test_value.py"]
    warm = mutation.WarmRunner(mutation._env(None))
    try:
        assert warm.run(args, 600, tmp_path)[:2] == (0, False)
        (package / "__init__.py").write_text("VALUE = 2\n")  # the mutant
        code, timed_out, output = warm.run(args, 600, tmp_path)
        assert (code, timed_out) == (1, False) and "assert 2 == 1" in output
        (package / "__init__.py").write_text("import time\n\nwhile True:\n    time.sleep(1)\n")
        assert warm.run(args, 1, tmp_path)[1] is True  # never ends by itself: stopped at its limit
        (package / "__init__.py").write_text("VALUE = 1\n")  # and the server still answers afterwards
        assert warm.run(args, 600, tmp_path)[:2] == (0, False)
    finally:
        warm.close()
    assert warm.proc.returncode == 0


def test_a_child_starts_with_the_servers_heap_frozen_and_collects_its_own_garbage(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    """The server freezes what it imported before forking (a child's full collections then
    skip torch's objects); what the child itself makes is still collected."""
    (tmp_path / "hg_marl").mkdir()
    (tmp_path / "hg_marl" / "__init__.py").write_text("")
    (tmp_path / "test_heap.py").write_text(
        "import gc\n\n\n"
        "def test_heap():\n"
        "    assert gc.get_freeze_count() > 10_000  # numpy, pytest, torch... imported by the server\n"
        "    cycle = []\n"
        "    cycle.append(cycle)\n"
        "    del cycle\n"
        "    assert gc.collect() >= 1  # the child's own cycle\n"
    )
    warm = mutation.WarmRunner(mutation._env(None))
    try:
        code, timed_out, output = warm.run(["-q", "-p", "no:cacheprovider", "test_heap.py"], 600, tmp_path)
    finally:
        warm.close()
    assert (code, timed_out) == (0, False), output


def test_one_warm_server_tests_each_scratch_copy_in_its_own_folder(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    """The pool keeps a server for every module a worker mutates, each module in its own
    copy: a run must import the copy its request names, work in it, and hand that copy
    to the subprocesses its tests start (the CLI tests run ``python -m hg_marl...``)."""
    test = (
        "import os, subprocess, sys\n\nimport hg_marl\n\n\n"
        "def test_value():\n"
        "    child = subprocess.run([sys.executable, '-c', 'import hg_marl; print(hg_marl.VALUE)'],\n"
        "                           cwd=os.path.dirname(os.getcwd()), capture_output=True, text=True, check=True)\n"
        "    assert (hg_marl.VALUE, int(child.stdout), os.getcwd()) == (EXPECTED, EXPECTED, FOLDER)\n"
    )
    copies = {}
    for value in (1, 2):
        root = tmp_path / f"copy{value}"
        (root / "hg_marl").mkdir(parents=True)
        (root / "hg_marl" / "__init__.py").write_text(f"VALUE = {value}\n")
        body = test.replace("EXPECTED", str(value)).replace("FOLDER", repr(str(root)))
        (root / "test_value.py").write_text(body)
        copies[value] = root
    args = ["-q", "-p", "no:cacheprovider", "test_value.py"]
    with mutation.WarmPool() as pool:
        warm = pool.get()
        assert pool.get() is warm  # the same thread gets the same server back
        for root in (copies[1], copies[2], copies[1]):
            code, timed_out, output = warm.run(args, 600, root)
            assert (code, timed_out) == (0, False), output
        (copies[2] / "hg_marl" / "__init__.py").write_text("VALUE = 3\n")  # a mutant in one copy only
        assert warm.run(args, 600, copies[2])[0] == 1
        assert warm.run(args, 600, copies[1])[0] == 0
    assert warm.proc.returncode == 0


def _report_line(node: str, when: str, outcome: str, duration: float) -> str:
    """One line as ``pytest --report-log`` writes it (the fields the stage reads)."""
    fields = {"nodeid": node, "when": when, "outcome": outcome, "duration": duration}
    return json.dumps({"$report_type": "TestReport", **fields})


def test_a_report_stands_for_the_baselines_of_modules_whose_tests_all_passed(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    report = tmp_path / "report.jsonl"
    lines = [json.dumps({"pytest_version": "9", "$report_type": "SessionStart"})]
    for node, call, seconds in [
        ("tests/a.py::test_x[1]", "passed", 2.0),
        ("tests/a.py::test_x[2]", "passed", 1.0),
        ("tests/a.py::test_xy", "passed", 4.0),
        ("tests/sub/test_b.py::test_b", "failed", 8.0),
        ("tests/sub/test_c.py::TestC::test_c", "passed", 16.0),
    ]:
        lines += [_report_line(node, "setup", "passed", 0.5), _report_line(node, "call", call, seconds)]
        lines.append(_report_line(node, "teardown", "passed", 0.25))
    report.write_text("\n".join(lines) + "\n")
    (tmp_path / "report.key").write_text(mutation.content_key() + "\n")
    baselines = mutation.Baselines.load(report)
    # worked by hand: each test's setup 0.5 s and teardown 0.25 s beside its call
    assert baselines.seconds_for(("tests/a.py::test_x",)) == 2.0 + 1.0 + 2 * 0.75  # both cases, not test_xy
    assert baselines.seconds_for(("tests/a.py",)) == 2.0 + 1.0 + 4.0 + 3 * 0.75
    assert baselines.seconds_for(("tests/sub/test_c.py",)) == 16.75  # a class's tests under their file
    assert baselines.seconds_for(("tests/a.py", "tests/sub/test_c.py")) == 7.0 + 2.25 + 16.75
    assert baselines.seconds_for(("tests/sub",)) is None  # one test of the folder failed: run the baseline
    assert baselines.seconds_for(("tests/a.p",)) is None  # a prefix that is not the file names nothing
    assert baselines.seconds_for(("tests/other.py",)) is None  # not in the report: run the baseline


def test_a_report_without_its_key_is_refused_and_one_of_other_files_set_aside(
    mutation, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:  # type: ignore[no-untyped-def]
    report = tmp_path / "report.jsonl"
    report.write_text(_report_line("tests/a.py::t", "call", "passed", 1.0) + "\n")
    assert mutation.main(["--baseline-from", str(report), "--list"]) == 2  # no key beside it
    assert "--baseline-from" in capsys.readouterr().err
    assert mutation.main(["--write-key", str(tmp_path / "report.key")]) == 0
    assert mutation.main(["--baseline-from", str(report), "--list"]) == 0
    (tmp_path / "report.key").write_text("0" * 64 + "\n")  # the key of files as they were before an edit
    assert mutation.Baselines.load(report) is None  # every module runs its own baseline, with a warning
    assert "tested other files" in capsys.readouterr().err
    report.write_text('{"$report_type": "TestReport", "nodeid": "tests/a.py::t", "duration": NaN}\n')
    assert mutation.main(["--write-key", str(tmp_path / "report.key")]) == 0
    assert mutation.main(["--baseline-from", str(report), "--list"]) == 2
    assert f"{report}:1" in capsys.readouterr().err


def test_the_key_covers_sources_and_tests_but_not_caches(mutation, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_a.py").write_text("def test_a():\n    pass\n")
    (tmp_path / "pyproject.toml").write_text("[project]\n")
    before = mutation.content_key(tmp_path)
    (tmp_path / "tests" / "__pycache__").mkdir()
    (tmp_path / "tests" / "__pycache__" / "test_a.cpython-311.pyc").write_bytes(b"\0")
    (tmp_path / "notes.txt").write_text("not copied")  # outside what a scratch copy holds
    assert mutation.content_key(tmp_path) == before
    (tmp_path / "tests" / "test_a.py").write_text("def test_a():\n    assert False\n")
    assert mutation.content_key(tmp_path) != before
    (tmp_path / "tests" / "test_a.py").write_text("def test_a():\n    pass\n")
    assert mutation.content_key(tmp_path) == before
    (tmp_path / "tests" / "test_a.py").rename(tmp_path / "tests" / "test_b.py")  # same bytes, another name
    assert mutation.content_key(tmp_path) != before
