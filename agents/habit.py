"""The habitual expert: a model-free Q-learner over the paper's boolean facts.

Renaudo et al. 2015 describe the habit as "a one layer neural network implementation of
a Qlearning algorithm": input neurons are the boolean facts, output neurons the actions,
and a Boltzmann (softmax) function turns action values into choice probabilities.
:class:`QLearner` is exactly that, ``Q(s, a) = w_a . phi(s) + b_a``, with two choices of
``phi``:

- ``"facts"`` (the paper's): ``phi(s)`` is the int8 fact vector, so what is learnt in one
  state generalises to states sharing facts;
- ``"tabular"``: ``phi(s)`` is a one-hot code of the state, the code being the fact
  vector's bytes mapped to a new index on first sight (the table grows). No bias here,
  so this is textbook tabular Q-learning.

Learning is off-policy Q-learning from every *executed* transition, whoever proposed the
action; this is how the planner bootstraps the habit (the paper's Fig. 5)::

    delta = r + gamma * max_a' Q(s', a') * (1 - done) - Q(s, a)

Step normalisation (why). With the lineage's ``alpha = 0.6`` and some ten active binary
features, the plain linear update ``w_a += alpha * delta * phi`` moves ``Q(s, a)`` by
``alpha * |phi|^2 * delta``, i.e. six times the TD error: it overshoots and diverges.
We therefore scale the step by ``1 / (|phi|^2 + 1)`` (normalised LMS; the ``+ 1`` is the
bias, counted as an always-on feature). ``Q(s, a)`` then moves by exactly
``alpha * delta``, the step a tabular learner with rate ``alpha`` would take, so ``alpha``
keeps its usual meaning and any ``0 < alpha < 2`` is stable on the visited state. In
tabular mode ``|phi|^2 = 1`` and there is no bias, so the step is the classical one.

Uncertainty (for the VPI criterion, Keramati et al. 2011). Keramati et al. keep a
Kalman-style posterior over each Q-value. A linear learner has no such posterior, so we
use the quantity that plays its role: an exponentially weighted running mean of the
squared TD error per ``(state code, action)``, ``v <- (1 - eta) v + eta delta^2``,
started at a prior ``v0`` (the reward scale) so unseen pairs are maximally uncertain.
``sd = sqrt(v)``. It shrinks as the habit's predictions come true and grows again when
the human changes behaviour (a non-stationarity a count-based sd would miss, since counts
never go down). A pair never updated borrows its state's running value (the same mean
over whichever actions were executed there), and only a never-updated state has the
prior: otherwise the actions the habit never tries (once the planner guides it, most of
them) would keep the prior forever and VPI would never hand control to the habit.
State codes are shared with tabular mode and are kept in both modes.
"""

from __future__ import annotations

import json
import logging
import os
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Literal

import numpy as np

from hg_marl.core.atomic import atomic_write

logger = logging.getLogger(__name__)

Features = Literal["facts", "tabular"]
_FEATURES: tuple[str, ...] = ("facts", "tabular")


@dataclass(frozen=True)
class QLearnerConfig:
    """Hyper-parameters of the habitual expert (defaults: the lineage's code)."""

    alpha: float = 0.6
    """Learning rate: the fraction of the TD error by which Q(s, a) moves per update."""
    gamma: float = 0.9
    """Discount factor of the bootstrapped target."""
    beta: float = 50.0
    """Inverse temperature of the Boltzmann policy (higher = greedier)."""
    features: Features = "facts"
    """``"facts"``: linear in the paper's fact vector; ``"tabular"``: one-hot state code."""
    normalise: bool = True
    """Scale the step by ``1/(|phi|^2 + 1)`` (NLMS). Off = plain linear TD, which diverges
    with ``alpha = 0.6`` on the fact features; kept for studying exactly that."""
    uncertainty_rate: float = 0.1
    """``eta``: rate of the running mean of squared TD errors behind :meth:`QLearner.uncertainty`."""
    uncertainty_prior: float = 1.0
    """``v0``: the squared-TD-error assumed for a never-updated pair (reward scale is 1)."""

    def __post_init__(self) -> None:
        if self.features not in _FEATURES:
            raise ValueError(f"QLearnerConfig.features: expected one of {_FEATURES}, got {self.features!r}")
        checks = {
            "alpha": self.alpha > 0,
            "gamma": 0 <= self.gamma <= 1,
            "beta": self.beta >= 0,
            "uncertainty_rate": 0 < self.uncertainty_rate <= 1,
            "uncertainty_prior": self.uncertainty_prior >= 0,
        }
        for name, ok in checks.items():
            if not ok:
                raise ValueError(f"QLearnerConfig.{name}: out of range ({getattr(self, name)!r})")


class QLearner:
    """Linear Q-learner with a Boltzmann policy; see the module docstring for the maths.

    Args:
        n_facts: length of the fact vector (``World.n_facts``).
        n_actions: number of actions (``World.n_actions(Agent.ROBOT)``); the policy ranges
            over all of them, feasible or not, as the paper's habit does.
        config: hyper-parameters.
    """

    def __init__(self, n_facts: int, n_actions: int, config: QLearnerConfig | None = None) -> None:
        self.config = config or QLearnerConfig()
        self.n_facts = int(n_facts)
        self.n_actions = int(n_actions)
        self._tabular = self.config.features == "tabular"
        self._codes: dict[bytes, int] = {}
        self._code_facts: list[np.ndarray] = []
        n_in = 16 if self._tabular else self.n_facts
        self.weights = np.zeros((self.n_actions, n_in))
        """``w``: one row per action (tabular: one column per state code, grown on demand)."""
        self.bias = np.zeros(self.n_actions)
        """``b``: one per action (stays zero in tabular mode)."""
        self._var = np.full((16, self.n_actions), self.config.uncertainty_prior)
        self._state_var = np.full(16, self.config.uncertainty_prior)
        self._tried = np.zeros((16, self.n_actions), dtype=bool)
        self._visits = np.zeros(16, dtype=np.int64)
        self.n_updates = 0
        """TD updates applied so far."""

    # ---- state codes -------------------------------------------------------------
    @property
    def n_states(self) -> int:
        """Distinct fact vectors seen so far."""
        return len(self._codes)

    def state_code(self, facts: np.ndarray) -> int:
        """Index of this fact vector, assigned on first sight (deterministic given the order)."""
        key = facts.tobytes()
        code = self._codes.get(key)
        if code is None:
            code = self._codes[key] = len(self._codes)
            self._code_facts.append(np.array(facts, dtype=np.int8))
            if code >= self._var.shape[0]:
                self._grow(2 * self._var.shape[0])
        return code

    def _grow(self, capacity: int) -> None:
        var = np.full((capacity, self.n_actions), self.config.uncertainty_prior)
        old = self._var.shape[0]
        var[:old] = self._var
        self._var = var
        prior = np.full(capacity - old, self.config.uncertainty_prior)
        self._state_var = np.concatenate([self._state_var, prior])
        self._tried = np.concatenate([self._tried, np.zeros((capacity - old, self.n_actions), dtype=bool)])
        self._visits = np.concatenate([self._visits, np.zeros(capacity - old, dtype=np.int64)])
        if self._tabular:
            w = np.zeros((self.n_actions, capacity))
            w[:, : self.weights.shape[1]] = self.weights
            self.weights = w

    # ---- values and policy -------------------------------------------------------
    def q_values(self, facts: np.ndarray) -> np.ndarray:
        """``Q(s, .)`` for every action (a fresh array)."""
        if self._tabular:
            code = self.state_code(facts)  # first: it may grow (reallocate) the table
            return self.weights[:, code].copy()
        return self.weights @ facts + self.bias

    def policy(self, facts: np.ndarray) -> np.ndarray:
        """Boltzmann probabilities ``softmax(beta * Q(s, .))`` over all actions."""
        return softmax(self.q_values(facts), self.config.beta)

    def act(self, facts: np.ndarray, rng: np.random.Generator) -> int:
        """Sample an action from the Boltzmann policy (one matvec + softmax + one draw)."""
        return sample(self.policy(facts), rng)

    def uncertainty(self, facts: np.ndarray) -> np.ndarray:
        """Per-action sd of ``Q(s, .)``: root of the running mean squared TD error.

        Untried pairs take their state's running value (see the module docstring).
        """
        code = self.state_code(facts)
        return np.sqrt(np.where(self._tried[code], self._var[code], self._state_var[code]))

    def visits(self, facts: np.ndarray) -> int:
        """TD updates made from this state so far: how much the habit has learnt *here*.

        The linear habit's Q-values are defined (and often sharp) in states it never saw;
        this count is what tells a criterion where they rest on experience.
        """
        return int(self._visits[self.state_code(facts)])

    @property
    def weight_amplitude(self) -> float:
        """Sum of absolute connection weights ``sum |w|`` (the paper's Fig. 5; bias excluded)."""
        return float(np.abs(self.weights).sum())

    # ---- learning ----------------------------------------------------------------
    def update(
        self, facts: np.ndarray, action: int, reward: float, next_facts: np.ndarray, done: bool = False
    ) -> float:
        """One Q-learning step on an executed transition; returns the TD error ``delta``.

        Args:
            facts: the state the action was taken in.
            action: the executed action (whichever expert proposed it).
            reward: the reward received between the two states.
            next_facts: the state reached (ignored when ``done``).
            done: the episode terminated: no bootstrap.
        """
        cfg = self.config
        target = float(reward)
        if not done:
            target += cfg.gamma * float(self.q_values(next_facts).max())
        code = self.state_code(facts)
        if self._tabular:
            delta = target - float(self.weights[action, code])
            self.weights[action, code] += cfg.alpha * delta
        else:
            phi = facts.astype(np.float64)
            delta = target - float(self.weights[action] @ phi + self.bias[action])
            step = cfg.alpha * delta
            if cfg.normalise:
                step /= float(phi @ phi) + 1.0
            self.weights[action] += step * phi
            self.bias[action] += step
        eta = cfg.uncertainty_rate
        sq = delta * delta
        self._var[code, action] += eta * (sq - self._var[code, action])
        self._state_var[code] += eta * (sq - self._state_var[code])
        self._tried[code, action] = True
        self._visits[code] += 1
        self.n_updates += 1
        if not np.isfinite(delta):
            logger.warning("Q-learner diverged (delta=%s); try normalise=True or a smaller alpha", delta)
        return delta

    # ---- persistence -------------------------------------------------------------
    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write weights, codes and statistics to an ``.npz`` atomically (the project's
        :func:`~hg_marl.core.atomic.atomic_write`: flushed to disk, mode 0644).

        A crash mid-write leaves the previous file intact, which matters for long runs
        that checkpoint the habit periodically.
        """
        codes = np.array(self._code_facts, dtype=np.int8).reshape(len(self._code_facts), self.n_facts)

        def write(tmp: Path) -> None:
            with tmp.open("wb") as f:  # a file object: np.savez would add ".npz" to a name
                np.savez(
                    f,
                    config=np.array(json.dumps(asdict(self.config))),
                    shape=np.array([self.n_facts, self.n_actions]),
                    weights=self.weights,
                    bias=self.bias,
                    var=self._var,
                    state_var=self._state_var,
                    tried=self._tried,
                    visits=self._visits,
                    codes=codes,
                    n_updates=np.array(self.n_updates),
                )

        return atomic_write(Path(path), write)

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> QLearner:
        """Read a learner written by :meth:`save`."""
        with np.load(Path(path), allow_pickle=False) as data:
            config = QLearnerConfig(**json.loads(str(data["config"])))
            n_facts, n_actions = (int(x) for x in data["shape"])
            out = cls(n_facts, n_actions, config)
            out.weights = data["weights"].copy()
            out.bias = data["bias"].copy()
            out._var = data["var"].copy()
            out._state_var = data["state_var"].copy()
            out._tried = data["tried"].copy()
            # files written before visit counts existed: nothing is known to have been learnt where
            visits = data["visits"] if "visits" in data.files else np.zeros(len(out._tried), dtype=np.int64)
            out._visits = np.array(visits, dtype=np.int64)
            for row in data["codes"]:
                out._codes[row.tobytes()] = len(out._code_facts)
                out._code_facts.append(row.copy())
            out.n_updates = int(data["n_updates"])
        return out


def softmax(values: np.ndarray, beta: float) -> np.ndarray:
    """``exp(beta * v) / sum exp(beta * v)``, shifted by the max for numerical safety."""
    z = values - values.max()
    z *= beta
    np.exp(z, out=z)
    z /= z.sum()
    return z


def sample(probs: np.ndarray, rng: np.random.Generator) -> int:
    """Draw an index from ``probs`` with one uniform draw (inverse CDF).

    Faster than ``rng.choice(len(p), p=p)``, which validates ``p`` on every call, and as exact.
    """
    cdf = probs.cumsum()
    i = int(cdf.searchsorted(rng.random() * cdf[-1], side="right"))
    return min(i, len(probs) - 1)
