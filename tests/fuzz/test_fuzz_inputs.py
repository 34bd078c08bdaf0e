"""Fuzzing what users hand in: scenario TOML, command-line options, trace lines.

The property is the project's rule for bad input: either a valid result, or exactly one
``HgMarlError`` (on the command line: one ``error:`` line and exit 2). Anything else (a
traceback from inside numpy, a hang, a silently wrong result) fails the test. Budgets
are small (short simulated runs, capped sizes), so every example is bounded in time and
memory; ``test_nasty_inputs_stay_within_memory`` also runs the worst cases in a
subprocess under an address-space limit.
"""

from __future__ import annotations

import json
import math
import resource
import subprocess
import sys
import tomllib
from importlib import resources
from pathlib import Path

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from hg_marl.agents.humans.trace import read_trace
from hg_marl.core import Agent, World
from hg_marl.core.errors import HgMarlError
from hg_marl.core.scenario import Scenario, load_scenario
from tests.agents.test_trace_validation import header as trace_header
from tests.agents.test_trace_validation import step as trace_step
from tests.cli_helpers import HANG_GUARD, error_lines, run_main

EXAMPLES = 150
"""Examples per property (hypothesis); the report counts them."""

PAPER = resources.files("hg_marl.core.scenarios").joinpath("paper2015.toml").read_text()
PAPER_LINES = PAPER.splitlines()
KEYS = ["name", "robot_reach", "human_reach", "count", "spots", "colour", "pick", "seed", "bins", "robot_locations"]

toml_scalars = st.one_of(
    st.integers(-(10**12), 10**12).map(str),
    st.sampled_from(["nan", "inf", "-inf", "-0.0", "1e308", "0", "1.5", "true", "false"]),
    st.floats(allow_nan=True, allow_infinity=True).map(lambda x: repr(x).replace("nan", "nan").replace("inf", "inf")),
    st.text(max_size=8).map(json.dumps),
    st.lists(st.sampled_from(['"bin_side"', '"human_side"', '"garden"', "1", '"mat_left"']), max_size=4).map(
        lambda xs: "[" + ", ".join(xs) + "]"
    ),
)


@st.composite
def mutated_toml(draw: st.DrawFn) -> str:
    """paper2015.toml with a few random line edits: replace a value, add a key, drop or duplicate a line."""
    lines = list(PAPER_LINES)
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, len(lines) - 1))
        op = draw(st.sampled_from(["value", "insert", "delete", "duplicate", "table"]))
        if op == "value" and "=" in lines[i]:
            lines[i] = lines[i].split("=", 1)[0] + "= " + draw(toml_scalars)
        elif op == "insert":
            lines.insert(i, f"{draw(st.sampled_from(KEYS))} = {draw(toml_scalars)}")
        elif op == "delete":
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[i])
        elif op == "table":
            lines.insert(
                i, draw(st.sampled_from(["[[bins]]", "[[spots]]", "[[objects]]", "[durations]", "[[layout]]"]))
            )
    return "\n".join(lines) + "\n"


def _check_scenario_or_error(path: Path) -> None:
    try:
        scenario = load_scenario(path)
    except HgMarlError as exc:
        assert "\n" not in str(exc) and str(path) in str(exc)
        event("one-line error")
        return
    event("valid scenario")
    assert isinstance(scenario, Scenario)
    for value in (scenario.durations.pick, scenario.durations.wait):
        assert math.isfinite(value) and value > 0
    world = World(scenario)
    import numpy as np

    state = world.initial_state(np.random.default_rng(0))
    assert world.mask(state, Agent.ROBOT).any()


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=mutated_toml())
def test_fuzz_scenario_toml(tmp_path: Path, text: str) -> None:
    path = tmp_path / "fuzz.toml"
    path.write_text(text, encoding="utf-8")
    _check_scenario_or_error(path)


@settings(max_examples=EXAMPLES // 3, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.binary(max_size=400))
def test_fuzz_scenario_bytes(tmp_path: Path, data: bytes) -> None:
    path = tmp_path / "fuzz.toml"
    path.write_bytes(PAPER.encode()[: len(data)] + data)
    _check_scenario_or_error(path)


# ---- command line ------------------------------------------------------------------------

numbers = st.one_of(
    st.sampled_from(["nan", "inf", "-inf", "0", "-1", "1e400", "abc", "", "1.5", "3", "20"]),
    st.floats(min_value=-100, max_value=30, allow_nan=False).map(lambda x: f"{x:.3g}"),
)
specs = st.one_of(
    st.sampled_from(
        [
            "cooperative",
            "lazy:p_idle=0.5",
            "lazy:p_idle=nan",
            "lazy:p_idle=2",
            "noisy:temperature=-1",
            "random:feasible_only=no",
            "adversarial",
            "replay",
            "learned:path=/nonexistent",
            "switching:at=[5]",
            "switching:at=[nan]",
            "lazy:p_idle=",
            ":",
            "lazy:,",
            'lazy:p_idle="0.1"',
            "nobody",
        ]
    ),
    st.text(alphabet='abcdefghijklmnopqrstuvwxyz_:=,.[]{}"0123456789-', max_size=20),
)
robots = st.sampled_from(
    [
        "planner",
        "habit",
        "hybrid",
        "random",
        "sb3",
        "oracle",
        "hybrid:criterion=vpi",
        "hybrid:learn=no",
        "hybrid:q_config={bad}",
        'hybrid:q_config={"features":"tabular"}',
        "habit:q_config=[1]",
        "hybrid:criterion=vpi:tau=nan",
    ]
)
scenarios = st.sampled_from(
    [
        "paper2015",
        "generated:objects=2,seed=1",
        "generated:objects=10000",
        "generated:bins=1e6",
        "generated:objects=1.5",
        "generated:spots=1,objects=2",
        "generated:human_only=nan",
        "kitchen",
        "generated:objects=3,locations=0",
    ]
)


VALID = {
    "--duration": st.sampled_from(["5", "12.5", "30"]),
    "--scenario": st.sampled_from(["paper2015", "generated:objects=2,seed=1", "roboergosum"]),
    "--robot": st.sampled_from(["planner", "habit", "hybrid", "random", "hybrid:criterion=vpi"]),
    "--human": st.sampled_from(["cooperative", "lazy:p_idle=0.5", "noisy:temperature=0.5", "random"]),
    "--seed": st.sampled_from(["0", "2"]),
}
ANY = {"--duration": numbers, "--scenario": scenarios, "--robot": robots, "--human": specs}
ANY["--seed"] = st.sampled_from(["0", "-3", "x", "2"])


@st.composite
def run_args(draw: st.DrawFn) -> list[str]:
    """Valid options except (usually) one, so valid runs and each kind of bad value both occur."""
    bad = draw(st.sampled_from([None, *VALID]))
    args = ["run"]
    for option, valid in VALID.items():
        args += [option, draw(ANY[option] if option == bad else valid)]
    if draw(st.booleans()):
        args += ["--criterion", draw(st.sampled_from(["vpi", "entropy:rate=2", "nope", "random:p=nan"]))]
    if draw(st.booleans()):
        args += ["--robot-param", draw(st.sampled_from(["learn=false", "q_config={}", "x", "cost=3", "=1"]))]
    return args


@st.composite
def plan_args(draw: st.DrawFn) -> list[str]:
    args = ["plan", "--scenario", draw(scenarios), "--seed", draw(st.sampled_from(["0", "-1", "1.5", "7"]))]
    args += ["--human", draw(st.sampled_from(["cooperative", "lazy", "adversarial", "no_handover", ""]))]
    args += ["--budget", draw(st.sampled_from(["0", "50", "200", "-5", "nan"]))]
    return args


def _check_cli(args: list[str]) -> None:
    code, _, err = run_main(args)
    lines = error_lines(err)
    event(f"exit {code}")
    if code == 0:
        return
    if code == 1 and args[0] == "plan" and not lines:
        return  # plan's own "no plan within the budget" result (printed on stdout)
    assert code == 2, (args, code, err)
    assert len(lines) == 1 and lines[0].startswith("error: "), (args, err)


def _bounded_duration(args: list[str]) -> list[str]:
    """Keep valid durations short (a valid run must stay quick); bad ones are what is fuzzed."""
    out = list(args)
    i = out.index("--duration") + 1
    try:
        if math.isfinite(float(out[i])) and float(out[i]) > 30:
            out[i] = "30"
    except ValueError:
        pass
    return out


@settings(max_examples=EXAMPLES, deadline=None)
@given(args=run_args())
def test_fuzz_run_command(args: list[str]) -> None:
    _check_cli(_bounded_duration(args))


@settings(max_examples=EXAMPLES // 3, deadline=None)
@given(args=plan_args())
def test_fuzz_plan_command(args: list[str]) -> None:
    _check_cli(args)


# ---- trace lines -------------------------------------------------------------------------

HEADER = trace_header()
N_F, N_A = len(HEADER["fact_names"]), len(HEADER["action_names"])
json_values = st.recursive(
    st.one_of(st.none(), st.booleans(), st.integers(-5, 40), st.floats(), st.text(max_size=5)),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=5), children, max_size=3),
    max_leaves=10,
)


@st.composite
def step_line(draw: st.DrawFn) -> str:
    record = trace_step()
    for key in draw(st.lists(st.sampled_from([*record, "extra"]), max_size=3)):
        record[key] = draw(json_values)
    if draw(st.integers(0, 9)) == 0:
        return json.dumps(draw(json_values))  # a line that is not a step object at all
    return json.dumps(record)


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(lines=st.lists(step_line(), min_size=1, max_size=5))
def test_fuzz_trace_lines(tmp_path: Path, lines: list[str]) -> None:
    path = tmp_path / "t.jsonl"
    path.write_text(json.dumps(HEADER) + "\n" + "\n".join(lines) + "\n")
    try:
        episodes = read_trace(path)
    except HgMarlError as exc:
        assert f"{path}:" in str(exc) and "\n" not in str(exc)
        event("one-line error")
        return
    event("valid trace")
    for record in episodes[0].steps:  # accepted: every value fits the header
        assert isinstance(record["action"], int) and 0 <= record["action"] < N_A
        assert len(record["facts"]) == N_F and set(record["facts"]) <= {0, 1}


# ---- memory bound ------------------------------------------------------------------------

NASTY = [
    ["run", "--scenario", "generated:objects=10000", "--duration", "10"],
    ["run", "--scenario", "generated:bins=1000000", "--duration", "10"],
    ["run", "--duration", "nan"],
    # refused at a work budget (never a wall-time one): the layouts, then the exploration
    ["oracle", "--scenario", "generated:objects=12,spots=14", "--max-states", "50"],
    ["oracle", "--scenario", "generated:objects=12,spots=14", "--human", "random", "--max-states", "20000"],
    ["plan", "--scenario", "generated:objects=10000"],
]


def _limit_memory() -> None:
    limit = 4 << 30  # 4 GiB of address space: a GB-sized allocation fails instead of swapping
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


@pytest.mark.parametrize("args", NASTY, ids=[" ".join(a) for a in NASTY])
def test_nasty_inputs_stay_within_memory(args: list[str]) -> None:
    proc = subprocess.run(
        [sys.executable, "-c", "from hg_marl.training.cli import main; main()", *args],
        capture_output=True,
        text=True,
        timeout=HANG_GUARD,
        preexec_fn=_limit_memory,
    )
    lines = error_lines(proc.stderr)
    assert proc.returncode == 2 and len(lines) == 1 and lines[0].startswith("error: "), proc.stderr[-2000:]


def test_builtin_scenario_text_is_the_fuzz_seed() -> None:
    assert tomllib.loads(PAPER)["name"] == "paper2015"


# ---- specs given to the registries ---------------------------------------------------------

spec_text = st.builds(
    lambda name, params: name + (":" + ",".join(f"{k}={v}" for k, v in params) if params else ""),
    st.sampled_from(["lazy", "noisy", "random", "switching", "cooperative", "hybrid", "habit", "vpi", "entropy", "x"]),
    st.lists(
        st.tuples(
            st.sampled_from(["p_idle", "temperature", "feasible_only", "humans", "at", "by", "criterion", "learn",
                             "q_config", "tau", "rate", "kappa", "bogus"]),
            st.one_of(numbers, st.sampled_from(["true", "no", "[1,2]", '{"beta":2}', "{x", "lazy|cooperative", ""])),
        ),
        max_size=3,
    ),
)  # fmt: skip


@settings(max_examples=EXAMPLES, deadline=None)
@given(text=spec_text)
def test_fuzz_registry_specs(text: str) -> None:
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.meta import make_criterion
    from hg_marl.agents.robots import make_robot

    for make in (make_human, make_robot, make_criterion):
        try:
            make(text)
            event(f"{make.__name__}: built")
        except HgMarlError as exc:
            assert "\n" not in str(exc)
            event(f"{make.__name__}: one-line error")
