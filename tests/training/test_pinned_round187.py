"""Values that round 187's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from hg_marl.agents.meta.vpi import expected_gain, vpi
from hg_marl.agents.models.chains import reached_rate
from tests.agents.test_reached_rate import DONE, _asked, _redraw


def _gain_by_quadrature(gap: float, sd: float) -> float:
    # E[max(gap + sd Z, 0)] as an integral over the standard normal density, independent of the
    # closed form: the integrand is 0 below z = -gap / sd
    def integrand(z: float) -> float:
        return (gap + sd * z) * math.exp(-0.5 * z * z) / math.sqrt(2.0 * math.pi)

    value, _ = integrate.quad(integrand, -gap / sd, math.inf)
    return float(value)


def test_the_expected_gain_standardises_the_gap_by_the_sd_not_the_variance() -> None:
    # gap -1, sd 2: z = -0.5, Phi(-0.5) = 0.308538, phi(0.5) = 0.352065, so
    # E = -1 * 0.308538 + 2 * 0.352065 = 0.395593 (by the variance, z = -0.25, it would be 0.372042)
    assert expected_gain(-1.0, 2.0) == pytest.approx(0.395593, abs=1e-6)
    for gap, sd in ((-1.0, 2.0), (0.5, 3.0), (-2.0, 0.5)):
        assert expected_gain(gap, sd) == pytest.approx(_gain_by_quadrature(gap, sd), rel=1e-9, abs=1e-12)
    # Keramati's VPI of the best action: q = (1, 0), sd = (2, 2): g(0 - 1, 2) = 0.395593, and the
    # other action's g(0 - 1, 2) the same
    assert vpi(np.array([1.0, 0.0]), np.array([2.0, 2.0])) == pytest.approx([0.395593, 0.395593], abs=1e-6)


def test_a_redraw_onto_a_completing_state_is_rated_by_its_seconds() -> None:
    # The re-draw lands on state 2, which completes (V(2) = 0): the only state reached, one certain
    # state; a task takes the re-draw's 4 s, 3600 / 4 = 900 tasks an hour
    log: list[list[int]] = []
    assert reached_rate(_redraw((2, 1.0, 4.0)), DONE, _asked(log)) == pytest.approx(900.0, rel=1e-12)
