"""The CI's own wiring: every nox session is run by ``make test-integrations``.

The Makefile names the sessions (to run them two at a time, longest first); a session
added to ``noxfile.py`` but not to that list would never run in CI.
"""

from __future__ import annotations

import ast
import importlib.util
import re
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]


def _nox_sessions() -> set[str]:
    tree = ast.parse((ROOT / "noxfile.py").read_text())
    return {
        node.name
        for node in tree.body
        if isinstance(node, ast.FunctionDef)
        and any(ast.unparse(d).startswith("nox.session") for d in node.decorator_list)
    }


def test_every_nox_session_is_run_by_make_test_integrations() -> None:
    line = re.search(r"^NOX_SESSIONS := (.+)$", (ROOT / "Makefile").read_text(), re.MULTILINE)
    assert line is not None
    named = line.group(1).split()
    assert len(named) == len(set(named))
    assert set(named) == _nox_sessions() == {"cleanrl", "supersuit", "tianshou", "rllib", "core_lowest"}


def _uv_flags() -> Any:
    spec = importlib.util.spec_from_file_location("ci_uv_flags", ROOT / ".ci" / "uv_flags.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.uv_flags


def test_uv_gets_the_package_sources_pip_is_configured_with() -> None:
    """``pip config list`` as pip prints it (a file's values and ``PIP_*`` variables): uv's flags by hand."""
    listed = "\n".join(
        [
            "global.cert='/etc/ssl/certs/ca-certificates.crt'",
            "global.constraint='/etc/pins.txt'",
            "global.extra-index-url='file:///mirror/a/simple file:///mirror/b/simple'",
            "global.find-links='/wheels'",
            ":env:.find-links='/wheels /more-wheels'",
            ":env:.default-timeout='180'",
        ]
    )
    assert _uv_flags()(listed) == [
        "--find-links", "/wheels", "--find-links", "/more-wheels",
        "--extra-index-url", "file:///mirror/a/simple", "--extra-index-url", "file:///mirror/b/simple",
        "--constraint", "/etc/pins.txt",
        "--index-strategy", "unsafe-best-match",
    ]  # fmt: skip


def test_uv_gets_no_flags_where_pip_has_no_sources_configured() -> None:
    assert _uv_flags()("") == []
    assert _uv_flags()("global.cert='/etc/ssl/certs/ca.crt'\n") == []
    assert _uv_flags()("global.index-url='https://a/simple'\n:env:.index-url='https://b/simple'\n") == [
        "--index-url",
        "https://b/simple",
    ]
    assert _uv_flags()("global.no-index='true'\nglobal.find-links='/w'\n") == ["--find-links", "/w", "--no-index"]


def test_every_install_in_the_makefile_goes_through_uv_with_pips_sources() -> None:
    """Only uv itself is installed with pip; every other install uses ``UV_PIP`` (pip's sources as uv flags)."""
    makefile = (ROOT / "Makefile").read_text()
    assert "UV_PIP = $(BIN)/uv pip install --compile-bytecode $$($(BIN)/python .ci/uv_flags.py)" in makefile
    recipes = [line.strip() for line in makefile.splitlines() if line.startswith("\t")]
    pip_installs = [line for line in recipes if "pip install" in line and "UV_PIP" not in line]
    assert sum("$(UV_PIP)" in line for line in recipes) == 5  # set-up, browser, mutation, Ray, docs
    assert pip_installs == ['$(BIN)/python -m pip install --progress-bar on "uv>=0.5"']


def test_the_mutation_stage_reads_the_report_of_the_test_stage_keyed_before_it_ran() -> None:
    """The key is the files' content before the tests run, beside the report the test stage
    writes; the mutation stage reads that report (a key written after would hide an edit)."""
    lines = [ln for ln in (ROOT / ".ci" / "run").read_text().splitlines() if not ln.lstrip().startswith("#")]
    key_line = next(i for i, ln in enumerate(lines) if "--write-key" in ln)
    test_line = next(i for i, ln in enumerate(lines) if re.search(r"\bmake test PYTEST_ARGS=", ln))
    mutation_line = next(i for i, ln in enumerate(lines) if "make test-mutation" in ln)
    key = Path(re.search(r"--write-key (\S+)", lines[key_line]).group(1))  # type: ignore[union-attr]
    report = Path(re.search(r"--report-log=(\S+?)\"", lines[test_line]).group(1))  # type: ignore[union-attr]
    read = Path(re.search(r"--baseline-from (\S+?)\"", lines[mutation_line]).group(1))  # type: ignore[union-attr]
    assert key_line < test_line < mutation_line
    assert read == report and report.with_suffix(".key") == key
