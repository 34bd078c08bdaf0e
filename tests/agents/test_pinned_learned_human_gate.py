"""The ``learned`` human's file checks and numpy policies, pinned for the mutation gate.

Expected values come from the module's documented rules, worked by hand on paper2015's
human seat: a ``linear_softmax`` policy plays ``p(a) ∝ exp((W facts + b)_a / temperature)``
over the feasible actions, weights lie in ``[-1e6, 1e6]`` and the temperature in
``[1e-3, 1e3]`` (both inclusive); a ``table`` holds 0/1 facts and action indices in
``[0, n_actions)``, and an unseen observation waits (the seat's last action) or, with
``fallback="random"``, picks uniformly among the feasible actions.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.humans.learned import LearnedHuman, _numpy_policy, save_learned_policy
from hg_marl.agents.model_format import ModelFile, save_model_file, world_fields
from hg_marl.core import Agent, World
from hg_marl.core.errors import HumanError, ModelFileError

WORLD = World("paper2015")
N_A, N_F = WORLD.n_actions(Agent.HUMAN), WORLD.n_facts


def _write(folder: Path, kind: str, arrays: dict[str, np.ndarray], **extra: Any) -> Path:
    """A model file of ``kind`` for paper2015's human seat holding exactly ``arrays``."""
    folder.mkdir(parents=True, exist_ok=True)
    save_model_file(folder / "policy.json", {**world_fields(WORLD, Agent.HUMAN), "kind": kind, **extra}, arrays)
    return folder


def _linear(folder: Path, w: np.ndarray | None = None, b: np.ndarray | None = None, temperature: float = 1.0) -> Path:
    w = np.zeros((N_A, N_F)) if w is None else w
    b = np.zeros(N_A) if b is None else b
    return _write(folder, "linear_softmax", {"W": w, "b": b}, temperature=temperature)


def test_saving_takes_exactly_one_of_weights_and_table(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="exactly one"):
        save_learned_policy(tmp_path / "a", WORLD)
    with pytest.raises(ValueError, match="exactly one"):
        save_learned_policy(tmp_path / "b", WORLD, weights=np.zeros((N_A, N_F)), table={})


def test_saved_weights_must_fit_the_seat_and_the_bias_defaults_to_zeros(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=rf"weights must be \({N_A}, {N_F}\)"):
        save_learned_policy(tmp_path / "a", WORLD, weights=np.zeros((N_A, N_F + 1)))
    with pytest.raises(ValueError, match=rf"bias \({N_A},\)"):
        save_learned_policy(tmp_path / "b", WORLD, weights=np.zeros((N_A, N_F)), bias=np.zeros(N_A - 1))
    with pytest.raises(HumanError, match="temperature"):
        save_learned_policy(tmp_path / "c", WORLD, weights=np.zeros((N_A, N_F)), temperature=0.0)
    folder = save_learned_policy(tmp_path / "d", "paper2015", weights=np.ones((N_A, N_F)), temperature=0.5)
    human = LearnedHuman(folder)
    assert human.kind == "linear_softmax" and human.header["temperature"] == 0.5
    np.testing.assert_array_equal(human.file.arrays["b"], np.zeros(N_A))


def test_a_saved_table_holds_action_indices_from_0_to_the_last(tmp_path: Path) -> None:
    row = np.zeros(N_F, dtype=np.int8).tobytes()
    for bad in (N_A, -1):
        with pytest.raises(ValueError, match=rf"indices in \[0, {N_A}\)"):
            save_learned_policy(tmp_path / f"t{bad}", WORLD, table={row: bad})
    human = LearnedHuman(save_learned_policy(tmp_path / "ok", WORLD, table={row: N_A - 1}))
    assert human.kind == "table"
    assert human.probabilities(np.zeros(N_F), np.ones(N_A))[N_A - 1] == 1.0


def test_an_empty_table_loads_and_waits_everywhere(tmp_path: Path) -> None:
    human = LearnedHuman(save_learned_policy(tmp_path / "t", WORLD, table={}))
    expected = np.zeros(N_A)
    expected[-1] = 1.0
    np.testing.assert_array_equal(human.probabilities(np.ones(N_F), np.ones(N_A)), expected)


@pytest.mark.parametrize("name", ["W", "b"])
def test_weights_up_to_a_million_in_size_load_and_past_it_are_refused(tmp_path: Path, name: str) -> None:
    ok_w, ok_b = np.zeros((N_A, N_F)), np.zeros(N_A)
    (ok_w if name == "W" else ok_b).flat[0] = -1e6
    LearnedHuman(_linear(tmp_path / "ok", ok_w, ok_b))
    bad_w, bad_b = np.zeros((N_A, N_F)), np.zeros(N_A)
    (bad_w if name == "W" else bad_b).flat[0] = -1_000_000.5
    with pytest.raises(ModelFileError, match=r"W and b must lie in \[-1e\+06, 1e\+06\]"):
        LearnedHuman(_linear(tmp_path / "bad", bad_w, bad_b))


@pytest.mark.parametrize(("temperature", "ok"), [(1e-3, True), (1e3, True), (0.9e-3, False), (1000.5, False)])
def test_a_temperature_from_a_thousandth_to_a_thousand_loads(tmp_path: Path, temperature: float, ok: bool) -> None:
    folder = _linear(tmp_path / "p", temperature=temperature)
    if ok:
        assert LearnedHuman(folder).header["temperature"] == temperature
    else:
        with pytest.raises(ModelFileError, match="field 'temperature'"):
            LearnedHuman(folder)


@pytest.mark.parametrize("missing", ["W", "b"])
def test_a_linear_policy_without_both_arrays_is_refused(tmp_path: Path, missing: str) -> None:
    arrays = {"W": np.zeros((N_A, N_F)), "b": np.zeros(N_A)}
    del arrays[missing]
    with pytest.raises(ModelFileError, match=r"linear_softmax needs arrays W"):
        LearnedHuman(_write(tmp_path / "p", "linear_softmax", arrays, temperature=1.0))


@pytest.mark.parametrize(
    ("arrays", "message"),
    [
        ({"facts": np.zeros((2, N_F), dtype=np.int8)}, "table needs arrays"),
        ({"actions": np.zeros(2, dtype=np.int64)}, "table needs arrays"),
        ({"facts": np.zeros((2, N_F), dtype=np.int8), "actions": np.zeros(3, dtype=np.int64)}, "table needs arrays"),
        ({"facts": np.zeros((3, N_F), dtype=np.int8), "actions": np.zeros(2, dtype=np.int64)}, "table needs arrays"),
        ({"facts": np.zeros((2, N_F), dtype=np.int8), "actions": np.zeros(2)}, "must be integers"),
        ({"facts": np.zeros((2, N_F)), "actions": np.zeros(2, dtype=np.int64)}, "must be integers"),
        ({"facts": np.full((2, N_F), 2, dtype=np.int8), "actions": np.zeros(2, dtype=np.int64)}, "0 or 1"),
        ({"facts": np.zeros((1, N_F), dtype=np.int8), "actions": np.array([N_A])}, rf"indices in \[0, {N_A}\)"),
        ({"facts": np.zeros((1, N_F), dtype=np.int8), "actions": np.array([-1])}, rf"indices in \[0, {N_A}\)"),
    ],
    ids=[
        "no-actions",
        "no-facts",
        "more-actions",
        "fewer-actions",
        "float-actions",
        "float-facts",
        "fact-2",
        "action-n",
        "action-neg",
    ],
)
def test_a_malformed_table_is_refused_naming_what_is_wrong(
    tmp_path: Path, arrays: dict[str, np.ndarray], message: str
) -> None:
    with pytest.raises(ModelFileError, match=message):
        LearnedHuman(_write(tmp_path / "p", "table", arrays))


def test_a_table_of_booleans_and_unsigned_actions_loads(tmp_path: Path) -> None:
    """Bool facts are 0/1 and unsigned actions are integers: both kinds the check lets through."""
    facts = np.zeros((1, N_F), dtype=bool)
    human = LearnedHuman(_write(tmp_path / "p", "table", {"facts": facts, "actions": np.array([2], dtype=np.uint8)}))
    assert human.probabilities(np.zeros(N_F), np.ones(N_A))[2] == 1.0


def test_a_learned_human_needs_a_path_and_a_known_fallback(tmp_path: Path) -> None:
    with pytest.raises(HumanError, match="needs a policy"):
        LearnedHuman()
    folder = _linear(tmp_path / "p")
    with pytest.raises(HumanError, match="fallback must be 'wait' or 'random', got 'stay'"):
        LearnedHuman(folder, fallback="stay")
    assert LearnedHuman(folder, deterministic=1).deterministic is True


def test_an_unseen_observation_with_the_random_fallback_is_uniform_over_the_feasible(tmp_path: Path) -> None:
    human = LearnedHuman(save_learned_policy(tmp_path / "t", WORLD, table={}), fallback="random")
    mask = np.zeros(N_A, dtype=np.int8)
    mask[[0, 3, N_A - 1]] = 1
    expected = np.zeros(N_A)
    expected[[0, 3, N_A - 1]] = 1 / 3
    np.testing.assert_allclose(human.probabilities(np.zeros(N_F), mask), expected)


def test_the_distribution_lists_the_feasible_actions_and_a_deterministic_one_the_likeliest(tmp_path: Path) -> None:
    """Bias 1 on the first feasible action of a start state, 0 elsewhere, weights 0: over its
    k feasible actions p = e / (e + k - 1) for that one and 1 / (e + k - 1) for the others."""
    state = WORLD.initial_state(np.random.default_rng(0))
    feasible = [int(i) for i in np.flatnonzero(WORLD.mask(state, Agent.HUMAN))]
    favoured, k = feasible[0], len(feasible)
    assert k >= 2
    bias = np.zeros(N_A)
    bias[favoured] = 1.0
    folder = _linear(tmp_path / "p", b=bias)
    dist = dict(LearnedHuman(folder).distribution(WORLD, state))
    assert sorted(dist) == feasible
    assert dist[favoured] == pytest.approx(np.e / (np.e + k - 1))
    assert dist[feasible[1]] == pytest.approx(1 / (np.e + k - 1))
    assert LearnedHuman(folder, deterministic=True).distribution(WORLD, state) == [(favoured, 1.0)]


def test_saving_creates_the_missing_parent_folders(tmp_path: Path) -> None:
    folder = save_learned_policy(tmp_path / "deep" / "er" / "p", WORLD, table={})
    assert (folder / "policy.json").is_file()


def test_huge_logits_do_not_overflow_the_softmax(tmp_path: Path) -> None:
    """Bias 1000 on action 0 (exp(1000) overflows a float): the softmax is taken after
    subtracting the largest logit, so action 0 gets probability 1 and the others 0."""
    bias = np.zeros(N_A)
    bias[0] = 1000.0
    human = LearnedHuman(_linear(tmp_path / "p", b=bias))
    mask = np.zeros(N_A, dtype=bool)
    mask[[0, 1]] = True
    p = human.probabilities(np.zeros(N_F), mask)
    assert p[0] == 1.0 and p[1] == 0.0 and np.isfinite(p).all()


def _file(kind: str, arrays: dict[str, np.ndarray]) -> ModelFile:
    """A model file as handed to the array check, bypassing the loader's own shape checks."""
    header = {**world_fields(WORLD, Agent.HUMAN), "kind": kind, "temperature": 1.0}
    return ModelFile(Path("policy.json"), header, arrays)


@pytest.mark.parametrize(
    "arrays",
    [
        {"W": np.zeros((N_A, N_F - 1)), "b": np.zeros(N_A)},
        {"W": np.zeros((N_A, N_F + 1)), "b": np.zeros(N_A)},
        {"W": np.zeros((N_A - 1, N_F)), "b": np.zeros(N_A)},
        {"W": np.zeros((N_A, N_F)), "b": np.zeros(N_A - 1)},
        {"W": np.zeros((N_A, N_F)), "b": np.zeros(N_A + 1)},
    ],
    ids=["narrow-W", "wide-W", "short-W", "short-b", "long-b"],
)
def test_the_array_check_itself_refuses_linear_arrays_of_the_wrong_shape(arrays: dict[str, np.ndarray]) -> None:
    """Defence in depth: the check holds on its own, whatever the loader let through."""
    with pytest.raises(ModelFileError, match=rf"linear_softmax needs arrays W \({N_A}, {N_F}\) and b \({N_A},\)"):
        _numpy_policy(_file("linear_softmax", arrays))


def test_the_array_check_itself_refuses_non_finite_weights() -> None:
    w = np.zeros((N_A, N_F))
    w[1, 2] = np.inf
    with pytest.raises(ModelFileError, match="W and b must be finite"):
        _numpy_policy(_file("linear_softmax", {"W": w, "b": np.zeros(N_A)}))
    b = np.zeros(N_A)
    b[0] = np.nan
    with pytest.raises(ModelFileError, match="W and b must be finite"):
        _numpy_policy(_file("linear_softmax", {"W": np.zeros((N_A, N_F)), "b": b}))


@pytest.mark.parametrize(
    "facts",
    [np.zeros(N_F, dtype=np.int8), np.zeros((2, N_F - 1), dtype=np.int8), np.zeros((2, N_F + 1), dtype=np.int8)],
    ids=["one-dimension", "narrow", "wide"],
)
def test_the_array_check_itself_refuses_table_facts_of_the_wrong_shape(facts: np.ndarray) -> None:
    with pytest.raises(ModelFileError, match=rf"table needs arrays facts \(rows, {N_F}\) and actions \(rows,\)"):
        _numpy_policy(_file("table", {"facts": facts, "actions": np.zeros(len(facts), dtype=np.int64)}))


def test_the_array_check_passes_well_formed_arrays_as_float64_and_int8_int64() -> None:
    w, b = _numpy_policy(_file("linear_softmax", {"W": np.ones((N_A, N_F), dtype=np.float32), "b": np.zeros(N_A)}))
    assert w.dtype == np.float64 and b.dtype == np.float64 and w.shape == (N_A, N_F)
    facts, actions = _numpy_policy(
        _file("table", {"facts": np.ones((2, N_F), dtype=np.int64), "actions": np.array([0, 1], dtype=np.int32)})
    )
    assert facts.dtype == np.int8 and actions.dtype == np.int64


def test_the_array_check_compares_fact_counts_by_value_past_the_small_int_cache() -> None:
    """A table over 300 facts (above CPython's cached small ints, 256): 300 columns are the
    header's 300 names, so the arrays pass."""
    names = [f"f{i}" for i in range(300)]
    header = {"kind": "table", "fact_names": names, "action_names": ["a", "wait"]}
    arrays = {"facts": np.zeros((2, int("300")), dtype=np.int8), "actions": np.zeros(2, dtype=np.int64)}
    facts, actions = _numpy_policy(ModelFile(Path("policy.json"), header, arrays))
    assert facts.shape == (2, 300) and actions.tolist() == [0, 0]
