"""Values that round 149's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans import make_human
from hg_marl.agents.meta.entropy import EntropyCriterion
from hg_marl.agents.partner import PartnerPosterior
from hg_marl.training.baselines.bc import behaviour_clone
from hg_marl.training.io import write_json
from tests.training.test_pinned_baselines_bc_gate import _facts, _mask, _trace


def test_a_bad_entropy_filter_rate_is_refused_naming_the_rate() -> None:
    # The rate is a probability: 1.5 is refused, and the one-line error names the option given.
    with pytest.raises(ValueError, match=r"^entropy\.rate: expected a value in \[0, 1\], got 1\.5$"):
        EntropyCriterion(rate=1.5)


def test_the_posteriors_idling_model_keeps_the_types_p_idle_up_to_its_cap_of_0_9() -> None:
    # One candidate type is the most probable by construction; with idle_in_model its model idles
    # as the type does: lazy's p_idle 0.7 is under the cap (0.9) and kept as is, 0.95 is capped at
    # 0.9; without idle_in_model the model never idles.
    assert PartnerPosterior(types=("lazy:p_idle=0.7",), idle_in_model=True).model().p_idle == 0.7
    assert PartnerPosterior(types=("lazy:p_idle=0.95",), idle_in_model=True).model().p_idle == 0.9
    assert PartnerPosterior(types=("lazy:p_idle=0.7",)).model().p_idle == 0.0


def test_write_json_writes_ascii_only_escaping_other_characters(tmp_path: Path) -> None:
    # Strict JSON with the default escaping: "ë" (U+00EB) is written as the six characters \u00eb,
    # so the file is the same bytes whatever the locale's encoding. Worked by hand: indented by two.
    path = write_json(tmp_path / "r.json", {"who": "Zo\u00eb"})
    assert path.read_bytes() == b'{\n  "who": "Zo\\u00eb"\n}\n'


def test_a_linear_clone_is_saved_with_its_biases(tmp_path: Path) -> None:
    # Every recorded fact vector is all zeros, so the weights get no gradient (x = 0, and the L2
    # term of zero weights is 0): the fit lives in the biases alone. Action 1 was recorded three
    # times out of the mask {0, 1}, so its bias rises above action 0's and the reported accuracy is
    # 1. The policy as loaded back must agree: more than half the probability on action 1 (without
    # the biases every logit is 0 and the two feasible actions would get 0.5 each).
    zeros, mask = _facts(), _mask(0, 1)
    trace = _trace(tmp_path / "t.jsonl", [(zeros, mask, 1)] * 3)
    out, accuracy = behaviour_clone([trace], tmp_path / "policy", kind="linear_softmax")
    assert accuracy == 1.0
    human = make_human("learned", path=str(out))
    p = human.probabilities(np.array(zeros), np.array(mask))
    assert int(np.argmax(p)) == 1
    assert p[1] > 0.5
    assert p[0] + p[1] == pytest.approx(1.0)
