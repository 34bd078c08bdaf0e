"""The partner monitor's smallest settings and the posterior's prior and likelihood, pinned for the mutation gate.

Expected values worked by hand from ``agents/partner.py``'s docstrings: ``stall_after=1``
is a valid setting (one unmet expectation stalls the robot); the default prior puts
``prior_cooperative`` on the first type and shares the rest equally among the others
(0.7, then 0.1 each of three); a prior needs exactly one positive probability per type;
a single type is certain; an observation's likelihood under a type is
``(1 - epsilon) * p(action) + epsilon / n`` with ``n`` the feasible human actions, so with
one feasible action a type that expected another still gives it ``epsilon``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from hg_marl.agents.partner import PartnerMonitor, PartnerPosterior
from hg_marl.core import WAIT, Agent, Kind, World


def test_a_monitor_stalled_by_one_unmet_expectation_is_a_valid_setting() -> None:
    world = World("paper2015")
    give = next(i for i, a in enumerate(world.actions(Agent.HUMAN)) if a.kind is Kind.GIVE)
    monitor = PartnerMonitor(block_after=1, stall_after=1)
    assert not monitor.stalled
    monitor.observe(world, give, world.index(Agent.HUMAN, WAIT), solved=False)
    assert monitor.stalled


@pytest.mark.parametrize(
    ("types", "expected"),
    [
        (("cooperative", "lazy", "no_handover", "noisy"), [0.7, 0.1, 0.1, 0.1]),
        (("cooperative", "lazy", "noisy"), [0.7, 0.15, 0.15]),
        (("lazy", "cooperative"), [0.7, 0.3]),
    ],
)
def test_the_default_prior_shares_the_rest_equally_among_the_other_types(
    types: tuple[str, ...], expected: list[float]
) -> None:
    posterior = PartnerPosterior(types=types).posterior()
    assert [posterior[t] for t in types] == pytest.approx(expected)


@pytest.mark.parametrize("prior", [None, (2.0,)])
def test_a_single_type_is_certain(prior: tuple[float, ...] | None) -> None:
    assert PartnerPosterior(types=("lazy",), prior=prior).posterior() == {"lazy": 1.0}


@pytest.mark.parametrize("prior", [(0.5,), (0.2, 0.3, 0.5)])
def test_a_prior_of_another_length_than_the_types_is_refused(prior: tuple[float, ...]) -> None:
    with pytest.raises(ValueError, match="one positive probability per type"):
        PartnerPosterior(types=("cooperative", "lazy"), prior=prior)


class _OneAction:
    """A stand-in world where the human has exactly one feasible action, index 3."""

    def feasible_indices(self, state: Any, agent: Agent) -> list[int]:
        return [3]


class _Expects:
    """A type that does ``action`` for sure (feasible or not)."""

    uses_robot_action = False

    def __init__(self, action: int) -> None:
        self.action = action

    def distribution(self, world: Any, state: Any, robot_action: int) -> list[tuple[int, float]]:
        return [(self.action, 1.0)]


def test_with_one_feasible_action_the_random_part_gives_it_all_of_epsilon() -> None:
    """Likelihoods of action 3: 0.9 * 1 + 0.1 / 1 = 1.0 for the type doing it, 0.1 / 1 for the other: P = 10/11."""
    post = PartnerPosterior(types=("cooperative", "lazy"), prior=(0.5, 0.5), decay=1.0, epsilon=0.1)
    post.humans = [_Expects(3), _Expects(5)]
    post.observe(_OneAction(), np.zeros(1), -1, 3)
    assert post.posterior()["cooperative"] == pytest.approx(1.0 / 1.1)
