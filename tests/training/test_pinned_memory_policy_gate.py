"""The memory policy's mask: an infeasible action gets no probability, however large its logit."""

from __future__ import annotations

import torch

from hg_marl.agents.memory_policy import MemoryNet


def test_masked_actions_get_zero_probability_and_the_rest_keep_their_softmax() -> None:
    # Logits (5, 0, ln 3, 0) with actions 0 and 3 ruled out: the feasible pair (0, ln 3)
    # has softmax (1/4, 3/4) and the infeasible ones 0, even action 0's top logit.
    logits = torch.tensor([[5.0, 0.0, float(torch.log(torch.tensor(3.0))), 0.0]])
    mask = torch.tensor([[False, True, True, False]])
    probs = MemoryNet.masked(logits, mask).probs
    torch.testing.assert_close(probs, torch.tensor([[0.0, 0.25, 0.75, 0.0]]), atol=1e-6, rtol=0.0)
