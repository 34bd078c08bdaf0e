"""The play server's body reader and replayer, driven directly (no socket, no server).

Each answer is the HTTP rule stated by hand: a body that does not arrive in time is 408,
one over the size limit 413, a client gone before the end 400, and a body in chunks is
their concatenation. The timeout is 0.05 s of a receive that never answers (an asyncio
sleep of an hour), so the test waits 0.05 s whatever the machine's speed.
"""

from __future__ import annotations

import asyncio
from typing import Any

from hg_marl.training.play.server_limits import read_body, replay_body


def _receiver(messages: list[dict[str, Any]]) -> Any:
    queue = list(messages)

    async def receive() -> dict[str, Any]:
        if not queue:
            await asyncio.sleep(3600)  # the client never sends the rest
        return queue.pop(0)

    return receive


def _read(messages: list[dict[str, Any]], max_bytes: int = 10, timeout: float = 0.05) -> Any:
    return asyncio.run(read_body(_receiver(messages), max_bytes, timeout))


def test_a_body_in_chunks_is_their_concatenation() -> None:
    chunks = [
        {"type": "http.request", "body": b"abc", "more_body": True},
        {"type": "http.request", "body": b"", "more_body": True},
        {"type": "http.request", "body": b"defg"},
    ]
    assert _read(chunks) == (b"abcdefg", None)


def test_a_body_exactly_at_the_limit_passes_and_one_byte_more_is_413() -> None:
    assert _read([{"type": "http.request", "body": b"x" * 10}]) == (b"x" * 10, None)
    over = [{"type": "http.request", "body": b"x" * 6, "more_body": True}, {"type": "http.request", "body": b"y" * 5}]
    assert _read(over) == (b"", (413, "body larger than 10 bytes"))


def test_a_body_that_stops_arriving_is_408_after_the_timeout() -> None:
    started = [{"type": "http.request", "body": b"abc", "more_body": True}]
    assert _read(started) == (b"", (408, "request body not received within 0.05 s"))
    assert _read([]) == (b"", (408, "request body not received within 0.05 s"))


def test_a_client_gone_before_the_end_is_400() -> None:
    gone = [{"type": "http.request", "body": b"abc", "more_body": True}, {"type": "http.disconnect"}]
    assert _read(gone) == (b"", (400, "the client went away"))


def test_the_replayed_body_comes_once_then_the_real_receive() -> None:
    async def run() -> list[Any]:
        receive = replay_body(b"read before", _receiver([{"type": "http.disconnect"}]))
        return [await receive(), await receive()]

    first, second = asyncio.run(run())
    assert first == {"type": "http.request", "body": b"read before", "more_body": False}
    assert second == {"type": "http.disconnect"}
