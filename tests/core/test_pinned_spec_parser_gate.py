"""The spec parser's splitting, signature reading, placeholders, Python values and messages, pinned for the gate.

Expected values are written by hand from the module's docstrings: a factory's *keyword
parameters* are its named ones (``*args``, ``**kwargs`` and ``self`` are not); a parameter
whose default is None takes a placeholder of its annotation's type, here that type's
empty value (what the type builds with no argument), so a listing shows no invented
number; Python objects given as overrides are passed through unchecked, and every other
value given with them is still converted. Splitting, quoting and messages follow the
module docstring (commas inside quotes do not split; a message shows the value as given).
"""

from __future__ import annotations

import dataclasses
import inspect
from pathlib import Path

import pytest

from hg_marl.core.errors import SpecError
from hg_marl.core.spec import PYTHON_ONLY, AgentSpec, _kind, bind, parse_spec, signature_defaults, split_specs


def test_star_parameters_and_self_are_not_keyword_parameters() -> None:
    """A function written like a method: ``self``, ``*rest`` and ``**more`` are left out."""

    def factory(self, a: int = 1, *rest: int, b: str = "x", **more: int) -> None:
        del self, a, rest, b, more

    assert signature_defaults(factory) == {"a": 1, "b": "x"}


def test_a_none_default_takes_the_empty_value_of_its_annotated_type() -> None:
    """``dict | None`` -> ``{}``, ``str | Path | None`` -> ``""``, ``float | None`` -> ``0.0``, ``int | None`` -> ``0``.

    Each expected value is the type called with no argument; a class of the project
    (``Learner | None``) takes only a Python object.
    """

    class Learner:
        """A class of the project: only a Python object can be given."""

    def factory(
        cfg: dict[str, int] | None = None,
        path: str | Path | None = None,
        rate: float | None = None,
        count: int | None = None,
        learner: Learner | None = None,
    ) -> None:
        del cfg, path, rate, count, learner

    types: dict[str, type] = {"cfg": dict, "path": str, "rate": float, "count": int}
    got = signature_defaults(factory)
    assert got == {**{name: kind() for name, kind in types.items()}, "learner": PYTHON_ONLY}
    assert [type(v) for v in got.values()] == [*types.values(), type(PYTHON_ONLY)]


def test_values_given_after_a_python_object_are_still_converted() -> None:
    """Overrides follow the spec's own values: ``p`` from the text, then a Python object, then ``n`` as 4.0 -> 4."""
    learner = object()
    defaults = {"p": 0.5, "learner": PYTHON_ONLY, "n": 3}
    got = bind(parse_spec("x:p=0.25"), defaults, {"learner": learner, "n": 4.0}, what="x")
    assert got == {"p": 0.25, "learner": learner, "n": 4}
    assert type(got["n"]) is int  # converted against the integer default, not passed through


@pytest.mark.parametrize(
    ("default", "name"),
    [
        (True, "true or false"),
        (3, "an integer"),
        (0.5, "a finite number"),
        ([1], "a list"),
        (("a",), "a list"),
        ({"k": 1}, "a JSON object"),
        ("word", "a text"),
    ],
)
def test_each_kind_of_default_is_named_for_messages(default: object, name: str) -> None:
    """The words a message uses for what a parameter expects, one per kind of default."""
    assert _kind(default) == name


def test_an_escaped_quote_ends_its_escape_and_the_closing_quote_still_closes() -> None:
    r"""``a="p\"q"`` is one value: the escaped quote does not close it, the next one does, and ``b`` is split off."""
    spec = parse_spec(r'x:a="p\"q",b=1')
    assert dict(spec.raw) == {"a": r'"p\"q"', "b": "1"}


def test_a_nameless_piece_continues_the_spec_just_before_it() -> None:
    """``j=2`` after ``c:x=1`` belongs to ``c``, not to an earlier spec with parameters."""
    assert split_specs("a:k=1,b,c:x=1,j=2") == ["a:k=1", "b", "c:x=1,j=2"]


def test_a_python_only_parameter_refuses_spec_text_and_takes_any_python_value() -> None:
    defaults = {"learner": PYTHON_ONLY}
    with pytest.raises(SpecError, match=r"^x: parameter 'learner': takes a Python object, not a value in a spec$"):
        bind(parse_spec("x:learner=abc"), defaults, what="x")
    assert bind(parse_spec("x"), defaults, {"learner": 3}, what="x") == {"learner": 3}


def test_a_wrong_value_is_shown_as_the_spec_text_or_as_the_python_value_given() -> None:
    """Spec text is shown as written (``'[1]'``, the text's repr); a Python value as its repr (``[1]``, ``'abc'``)."""
    with pytest.raises(SpecError, match=r"^x: parameter 'n': expected an integer, got '\[1\]'$"):
        bind(parse_spec("x:n=[1]"), {"n": 3}, what="x")
    with pytest.raises(SpecError, match=r"^x: parameter 'n': expected an integer, got \[1\]$"):
        bind(parse_spec("x"), {"n": 3}, {"n": [1]}, what="x")
    with pytest.raises(SpecError, match=r"^x: parameter 'n': expected an integer, got 'abc'$"):
        bind(parse_spec("x"), {"n": 3}, {"n": "abc"}, what="x")


@pytest.mark.parametrize("text", ["x:names=[1, NaN]", "x:names=[[1], [2, Infinity]]", 'x:cfg={"a": [1, -Infinity]}'])
def test_a_non_finite_number_inside_a_list_is_refused(text: str) -> None:
    """JSON's ``NaN``/``Infinity`` read as floats; inside a list (or a list in an object) they are refused too."""
    with pytest.raises(SpecError, match=r"expected finite numbers, got (nan|inf|-inf)$"):
        bind(parse_spec(text), {"names": [], "cfg": {}}, what="x")


def test_a_python_object_or_none_given_for_a_number_is_passed_to_the_constructor_unconverted() -> None:
    """Only text, numbers, lists and dicts are converted; anything else is the constructor's to check."""
    marker = object()
    assert bind(parse_spec("x"), {"p": 0.5}, {"p": None}, what="x") == {"p": None}
    assert bind(parse_spec("x"), {"p": 0.5}, {"p": marker}, what="x")["p"] is marker


@pytest.mark.parametrize("text", ["x:flag=True", "x:flag=TRUE", "x:flag=true"])
def test_true_in_any_case_is_true(text: str) -> None:
    """``true`` is JSON; ``True`` and ``TRUE`` are read case-blind (the docstring: a boolean is ``true``/``false``)."""
    assert bind(parse_spec(text), {"flag": False}, what="x") == {"flag": True}


@pytest.mark.parametrize(
    ("field", "default", "expects"),
    [("flag", False, "true or false"), ("names", ["a"], "a list"), ("cfg", {}, 'a JSON object like {"key": 1}')],
)
def test_a_wrong_value_of_each_kind_is_shown_as_written_or_as_given(field: str, default: object, expects: str) -> None:
    """The spec text ``3`` is shown as text (``'3'``); the Python number 3 as ``3``."""
    defaults = {field: default}
    with pytest.raises(SpecError) as info:
        bind(parse_spec(f"x:{field}=3"), defaults, what="x")
    assert str(info.value) == f"x: parameter '{field}': expected {expects}, got '3'"
    with pytest.raises(SpecError) as info:
        bind(parse_spec("x"), defaults, {field: 3}, what="x")
    assert str(info.value) == f"x: parameter '{field}': expected {expects}, got 3"


def test_a_declared_signatures_self_is_left_out_whatever_string_names_it() -> None:
    """A ``__signature__`` (as wrappers declare one) whose ``self`` is a string built at run time, not the literal."""

    def factory(*args: object, **kwargs: object) -> None:
        del args, kwargs

    self_name = "".join(["se", "lf"])
    keyword = inspect.Parameter.POSITIONAL_OR_KEYWORD
    factory.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [inspect.Parameter(self_name, keyword), inspect.Parameter("a", keyword, default=2)]
    )
    assert signature_defaults(factory) == {"a": 2}


def test_parsed_specs_are_frozen() -> None:
    """A parsed spec is data carried to workers and used as it was read: neither kind can be changed in place."""
    for spec in (parse_spec("x:k=1"), AgentSpec.parse("x:k=1")):
        with pytest.raises(dataclasses.FrozenInstanceError):
            spec.name = "y"  # type: ignore[misc]
