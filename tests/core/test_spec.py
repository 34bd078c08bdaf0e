"""The one ``name:k=v`` parser and the finite/int/bool checks of the error module."""

from __future__ import annotations

import math
import re

import pytest

from hg_marl.core.errors import ConfigError, HgMarlError, HumanError, check_bool, check_finite, check_int
from hg_marl.core.spec import REQUIRED, AgentSpec, SpecError, bind, format_spec, parse_spec


def test_parse_keeps_name_and_raw_texts() -> None:
    spec = parse_spec("lazy:p_idle=0.5, fallback=wait")
    assert spec.name == "lazy"
    assert dict(spec.raw) == {"p_idle": "0.5", "fallback": "wait"}


def test_commas_inside_json_do_not_split() -> None:
    spec = parse_spec('hybrid:q_config={"features":"tabular","alpha":0.3},criterion=vpi')
    assert dict(spec.raw) == {"q_config": '{"features":"tabular","alpha":0.3}', "criterion": "vpi"}


@pytest.mark.parametrize("text", ["", ":p=1", "lazy:p_idle", "lazy:=3", "lazy:p=1,p=2"])
def test_malformed_specs_are_refused(text: str) -> None:
    with pytest.raises(SpecError):
        parse_spec(text)


@pytest.mark.parametrize(("text", "closer"), [("a:x=]y,b=1", "]"), ("a:x=1},b=1", "}"), ("a:x=(1)),b=1", ")")])
def test_a_closing_bracket_that_closes_nothing_is_refused_naming_it(text: str, closer: str) -> None:
    """Past an unmatched closer no top-level comma would split again: ``x`` would silently
    read ``]y,b=1`` and ``b`` would be lost. Refused in one line naming the spec and the closer."""
    with pytest.raises(SpecError, match=re.escape(f"{text!r}: an unmatched {closer!r}")):
        parse_spec(text)
    # A closer inside quotes is text, not a bracket.
    assert dict(parse_spec('a:x="]",b=1').raw) == {"x": '"]"', "b": "1"}


DEFAULTS = {"p": 0.5, "n": 3, "flag": False, "mode": "wait", "names": ["a"], "cfg": {}, "path": REQUIRED}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("x:p=1", {"p": 1.0}),
        ("x:n=4", {"n": 4}),
        ("x:n=4.0", {"n": 4}),
        ("x:flag=true", {"flag": True}),
        ("x:flag=False", {"flag": False}),
        ("x:mode=random", {"mode": "random"}),
        ("x:mode=1", {"mode": "1"}),
        ("x:names=a|b", {"names": ["a", "b"]}),
        ('x:names=["a","b"]', {"names": ["a", "b"]}),
        ('x:cfg={"k":1}', {"cfg": {"k": 1}}),
        ("x:path=dir/file.json", {"path": "dir/file.json"}),
    ],
)
def test_values_take_the_type_of_their_default(text: str, expected: dict) -> None:
    assert bind(parse_spec(text), DEFAULTS, what="x") == expected


@pytest.mark.parametrize(
    "text",
    [
        "x:p=nan",
        "x:p=NaN",
        "x:p=Infinity",
        "x:p=abc",
        "x:p=true",
        "x:n=1.5",
        "x:flag=no",
        "x:flag=1",
        "x:cfg={bad json}",
        "x:cfg=[1]",
        "x:unknown=1",
    ],
)
def test_bad_values_raise_the_callers_error_naming_the_parameter(text: str) -> None:
    with pytest.raises(HumanError) as info:
        bind(parse_spec(text), DEFAULTS, what="human 'x'", error=HumanError)
    assert "human 'x'" in str(info.value)
    assert "\n" not in str(info.value)


def test_python_overrides_win_and_are_checked() -> None:
    assert bind(parse_spec("x:p=0.1"), DEFAULTS, {"p": 0.9}, what="x") == {"p": 0.9}
    with pytest.raises(SpecError):
        bind(parse_spec("x"), DEFAULTS, {"p": math.nan}, what="x")
    with pytest.raises(SpecError):
        bind(parse_spec("x"), DEFAULTS, {"flag": "no"}, what="x")


def test_format_is_canonical_and_round_trips() -> None:
    text = format_spec("hybrid", {"criterion": "vpi", "q_config": {"features": "tabular"}})
    assert text == 'hybrid:criterion=vpi,q_config={"features":"tabular"}'
    assert bind(parse_spec(text), {"criterion": "random", "q_config": {}}, what="r") == {
        "criterion": "vpi",
        "q_config": {"features": "tabular"},
    }


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, True, "1", None])
def test_check_finite_refuses_non_finite_and_non_numbers(value: object) -> None:
    with pytest.raises(ConfigError, match="--duration"):
        check_finite(value, "--duration")


def test_check_finite_bounds() -> None:
    assert check_finite(3, "--d", positive=True) == 3.0
    with pytest.raises(ConfigError, match="> 0"):
        check_finite(0, "--d", positive=True)
    with pytest.raises(ConfigError, match="<= 1"):
        check_finite(1.5, "p", maximum=1)


def test_check_int_and_bool() -> None:
    assert check_int(4.0, "max_cycles") == 4
    with pytest.raises(ConfigError, match="max_cycles"):
        check_int(1.5, "max_cycles")
    with pytest.raises(ConfigError):
        check_int(True, "max_cycles")
    with pytest.raises(ConfigError, match="continuing"):
        check_bool("no", "continuing")
    assert check_bool(False, "continuing") is False


def test_messages_are_one_line() -> None:
    assert str(HgMarlError("a\nb  c")) == "a b c"


def test_split_specs_keeps_a_specs_parameters_together() -> None:
    from hg_marl.core.spec import split_specs

    assert split_specs("a,b:k=1,j=2,c") == ["a", "b:k=1,j=2", "c"]
    assert split_specs(" lazy:p_idle=0.5 , ,cooperative") == ["lazy:p_idle=0.5", "cooperative"]
    assert split_specs("") == []


def test_an_agent_spec_is_parsed_once_and_typed_as_json_reads_it() -> None:
    spec = AgentSpec.parse('belief:population=pop.toml,k=3,p=0.5,on=true,names=["a","b"]', "--robots")
    assert spec.name == "belief"
    assert dict(spec.params) == {"population": "pop.toml", "k": 3, "p": 0.5, "on": True, "names": ["a", "b"]}
    assert AgentSpec.parse(spec) is spec  # already parsed: carried as it is
    assert str(spec) == 'belief:k=3,names=["a","b"],on=true,p=0.5,population=pop.toml'  # keys sorted, compact JSON
    assert AgentSpec.parse("planner") == AgentSpec("planner", {})


def test_an_agent_spec_names_the_option_and_the_item_in_its_messages() -> None:
    with pytest.raises(SpecError, match=r"^--robots 'planner:k': expected key=value"):
        AgentSpec.parse("planner:k", "--robots")
    with pytest.raises(SpecError, match=r"^--robots planner:x=\[1 x: not valid JSON: \[1$"):
        AgentSpec.parse("planner:x=[1", "--robots", "--robots planner:x=[1")
