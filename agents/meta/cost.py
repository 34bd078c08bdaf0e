"""Decision cost of each expert: a deterministic model (default) or measured wall time.

The paper's experiments last a fixed *simulated* duration, so a runner may charge each
robot decision to the clock. Measured wall time depends on the machine and its load, so
results would not reproduce; the default is a model:

- habit: a constant ``habit`` seconds (one matvec, a softmax and a draw, cheaper in
  Python than the charge: ``benchmarks/decision_latency.py`` measures it, the figures
  are in docs/benchmarks.md; the charge is the order an implementation in the robot's
  supervision loop would cost, whatever the machine running the simulation);
- planner: ``planner_base + planner_per_node * nodes`` seconds. The base stands for a
  HATP call's fixed overhead (state serialisation, domain set-up, plan extraction),
  the per-node term for its search. With the defaults a plan of a few hundred nodes
  costs a fraction of one action's duration on ``paper2015``, negligible as the paper
  reports, and growing with the domain as HATP does. A plan served from the
  planner's cache reports 0 nodes and is charged the base only (replaying a stored plan
  is what HATP's supervisor does between replans).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

CostMode = Literal["model", "wall"]


@dataclass(frozen=True)
class CostModel:
    """How a decision's cost in simulated seconds is computed."""

    mode: CostMode = "model"
    """``"model"``: the constants below (reproducible); ``"wall"``: measured wall time."""
    habit: float = 1e-3
    """Seconds charged per habit decision."""
    planner_base: float = 0.05
    """Seconds charged per planner call, whatever its size."""
    planner_per_node: float = 5e-4
    """Seconds charged per search node the planner expands."""

    def __post_init__(self) -> None:
        if self.mode not in ("model", "wall"):
            raise ValueError(f"CostModel.mode: expected 'model' or 'wall', got {self.mode!r}")
        for name in ("habit", "planner_base", "planner_per_node"):
            value = getattr(self, name)
            if not math.isfinite(value) or value < 0:  # NaN passes `value < 0`; infinity would charge forever
                raise ValueError(f"CostModel.{name}: expected a finite non-negative number, got {value!r}")

    def habit_cost(self, wall_time: float = 0.0) -> float:
        """Cost of one habit decision."""
        return wall_time if self.mode == "wall" else self.habit

    def planner_cost(self, nodes: int, wall_time: float = 0.0) -> float:
        """Cost of one planner call that expanded ``nodes`` nodes."""
        return wall_time if self.mode == "wall" else self.planner_base + self.planner_per_node * nodes
