"""The history features' names, pinned for the mutation gate.

Expected by hand: ``kind[-1]`` is the last cycle, ``kind[-2]`` the one before; the last
count bucket (``cap``) is the only one marked ``+`` (it holds cap and more).
"""

from __future__ import annotations

from hg_marl.envs.history import history_names, history_size


def test_names_count_cycles_back_from_one_and_mark_the_last_bucket_only() -> None:
    names = history_names(2, cap=3)
    assert len(names) == history_size(2, cap=3)
    partner = [n for n in names if n.startswith("partner_kind[")]
    assert {n.split("]")[0] + "]" for n in partner} == {"partner_kind[-1]", "partner_kind[-2]"}
    assert [n for n in names if n.startswith("own_failed")] == ["own_failed[-1]", "own_failed[-2]"]
    assert [n for n in names if n.startswith("partner_since")] == [
        "partner_since_progress=0",
        "partner_since_progress=1",
        "partner_since_progress=2",
        "partner_since_progress=3+",
    ]
