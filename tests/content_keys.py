"""Record what a cache asks the content-key module to key, without computing the key."""

from __future__ import annotations

from typing import Any

import pytest

from hg_marl.agents import content

Asked = list[tuple[str, dict[str, Any], tuple[str, ...]]]


def record_content_keys(monkeypatch: pytest.MonkeyPatch) -> Asked:
    """Replace ``content.content_key`` by a recorder; the list fills with each call's (kind, fields, roots)."""
    asked: Asked = []

    def recording(kind: str, fields: dict[str, Any], roots: tuple[str, ...]) -> str:
        asked.append((kind, dict(fields), tuple(roots)))
        return "0" * 64

    monkeypatch.setattr(content, "content_key", recording)
    return asked
