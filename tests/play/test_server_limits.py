"""The play server closes idle and slowly-trickled connections and caps how many are open.

Each test opens raw sockets on the loopback to the real server (uvicorn on a free port)
with short limits, misbehaves as a slowloris client would, and waits on the socket for
the server to close it (``recv`` returning ``b""``). No assertion is about elapsed time:
the only clock is :data:`GUARD`, a generous socket timeout that turns a server which
never closes into a failure instead of a hang, and the trickles are bounded by a count
of bytes (a trickle that ends before the server closes its connection fails the test).
"""

from __future__ import annotations

import socket
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("uvicorn")

from hg_marl.core.errors import ConfigError
from hg_marl.training.play.server_limits import ServerLimits, head_bytes
from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.web import TOKEN_HEADER, Server

SHORT = 0.5
"""Every timeout of the server under test, in seconds."""

GUARD = 120.0
"""Seconds a socket waits for the server before the test fails (a hang guard, far above SHORT)."""

TRICKLE = 0.05
"""Seconds between two trickled bytes (well under SHORT, so uvicorn's idle timer never fires first)."""


@pytest.fixture
def session(tmp_path: Path) -> PlaySession:
    return PlaySession("planner", seed=0, record=tmp_path, player="limits-test")


def _serve(session: PlaySession, limits: ServerLimits) -> Iterator[Server]:
    srv = Server(session, 0, limits=limits)
    srv.start_in_thread()
    yield srv
    srv.stop()


@pytest.fixture
def server(session: PlaySession) -> Iterator[Server]:
    yield from _serve(session, ServerLimits(idle_timeout=SHORT, header_timeout=SHORT, body_timeout=SHORT))


def _connect(server: Server) -> socket.socket:
    sock = socket.create_connection(("127.0.0.1", server.port), timeout=GUARD)
    sock.settimeout(GUARD)
    return sock


def _closed_by_server(sock: socket.socket) -> bytes:
    """Everything the server sends until it closes the connection (fails after GUARD seconds)."""
    received = b""
    while True:
        try:
            chunk = sock.recv(4096)
        except ConnectionResetError:
            return received
        if not chunk:
            return received
        received += chunk


def _trickle(sock: socket.socket, data: bytes) -> int:
    """Send ``data`` a byte at a time; return how many bytes went before the server closed the socket."""
    for sent in range(len(data)):
        try:
            sock.send(data[sent : sent + 1])
        except (BrokenPipeError, ConnectionResetError):
            return sent
        time.sleep(TRICKLE)
        sock.setblocking(False)
        try:
            if sock.recv(4096, socket.MSG_PEEK) == b"":
                return sent + 1
        except BlockingIOError:
            pass
        except ConnectionResetError:
            return sent + 1
        finally:
            sock.setblocking(True)
    return len(data)


def test_a_connection_that_sends_nothing_is_closed(server: Server) -> None:
    with _connect(server) as sock:
        assert _closed_by_server(sock) == b""


def test_headers_trickled_a_byte_at_a_time_are_cut_off(server: Server, session: PlaySession) -> None:
    request = (f"GET /?token={server.token} HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\n").encode()
    request += b"X-Slow: " + b"a" * 4000  # never finished: no blank line
    with _connect(server) as sock:
        sent = _trickle(sock, request)
        assert sent < len(request), "the server kept a trickled request open to the end"
        assert _closed_by_server(sock) == b""  # closed without an answer


def test_a_body_trickled_a_byte_at_a_time_is_cut_off(server: Server, session: PlaySession) -> None:
    body = b'{"action": 0' + b" " * 3000 + b"}"
    head = (
        f"POST /act HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\nOrigin: http://127.0.0.1:{server.port}\r\n"
        f"{TOKEN_HEADER}: {server.token}\r\nContent-Type: application/json\r\nContent-Length: {len(body)}\r\n\r\n"
    ).encode()
    with _connect(server) as sock:
        sock.sendall(head)
        sent = _trickle(sock, body)
        assert sent < len(body), "the server waited for the whole trickled body"
        answer = _closed_by_server(sock)
    assert answer == b"" or answer.startswith(b"HTTP/1.1 408"), answer[:200]
    assert session.summary()["moves"] == 0  # the move was never played


def test_a_kept_alive_connection_is_closed_once_idle(server: Server) -> None:
    """A real page load still works, and its keep-alive connection does not outstay the idle timeout."""
    with _connect(server) as sock:
        sock.sendall(f"GET /board?token={server.token} HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\n\r\n".encode())
        answer = _closed_by_server(sock)
    assert answer.startswith(b"HTTP/1.1 200") and b"<svg" in answer


def test_connections_over_the_cap_are_closed_at_once(session: PlaySession) -> None:
    limits = ServerLimits(idle_timeout=GUARD * 2, header_timeout=GUARD * 2, max_connections=3)
    for srv in _serve(session, limits):
        held = [_connect(srv) for _ in range(limits.max_connections)]
        try:
            # the server has accepted the held ones once it has answered a request on one of them
            held[0].sendall(f"GET /board?token={srv.token} HTTP/1.1\r\nHost: 127.0.0.1:{srv.port}\r\n\r\n".encode())
            status = b""
            while len(status) < 12:  # the status line may come in pieces
                chunk = held[0].recv(12 - len(status))
                assert chunk, "the server closed a connection within the cap"
                status += chunk
            assert status == b"HTTP/1.1 200"
            with _connect(srv) as extra:
                assert _closed_by_server(extra) == b""
        finally:
            for sock in held:
                sock.close()


@pytest.mark.parametrize(
    "fields",
    [{"idle_timeout": 0.0}, {"header_timeout": float("nan")}, {"body_timeout": 1e9}, {"max_connections": 0}],
)
def test_limits_are_checked(fields: dict[str, float]) -> None:
    with pytest.raises(ConfigError):
        ServerLimits(**fields)  # type: ignore[arg-type]


def _status(sock: socket.socket, srv: Server) -> bytes:
    """Ask for the board on ``sock``; the status line's first 12 bytes (``b""`` if the server closed it)."""
    sock.sendall(f"GET /board?token={srv.token} HTTP/1.1\r\nHost: 127.0.0.1:{srv.port}\r\n\r\n".encode())
    status = b""
    while len(status) < 12:  # the status line may come in pieces
        chunk = sock.recv(12 - len(status))
        if not chunk:
            break
        status += chunk
    return status


def test_every_connection_within_the_cap_is_served_when_the_cap_is_full(session: PlaySession) -> None:
    """At the cap, each of the ``max_connections`` open connections still gets its answer.

    uvicorn refuses a request with 503 once its count of open connections reaches its
    concurrency limit, and that count includes the asking connection: so with
    ``max_connections`` open (the one over the cap was closed at once, which also shows
    that all the held ones were accepted) every request must be 200, not 503.
    """
    limits = ServerLimits(idle_timeout=GUARD * 2, header_timeout=GUARD * 2, max_connections=3)
    for srv in _serve(session, limits):
        held = [_connect(srv) for _ in range(limits.max_connections)]
        try:
            assert _status(held[0], srv) == b"HTTP/1.1 200"  # the server is up and has accepted them
            with _connect(srv) as extra:
                assert _closed_by_server(extra) == b""  # the cap is full: every held one is counted
            # the others have not asked yet (the first still holds the rest of its answer)
            assert [_status(sock, srv) for sock in held[1:]] == [b"HTTP/1.1 200"] * (limits.max_connections - 1)
        finally:
            for sock in held:
                sock.close()


def test_head_bytes_counts_the_request_line_and_headers_as_sent() -> None:
    sent = b"GET /board?token=abc HTTP/1.1\r\nhost: 127.0.0.1:8000\r\nx-pad: aaa\r\n\r\n"
    scope = {
        "method": "GET",
        "path": "/board",
        "raw_path": b"/board",
        "query_string": b"token=abc",
        "headers": [(b"host", b"127.0.0.1:8000"), (b"x-pad", b"aaa")],
    }
    assert head_bytes(scope) == len(sent) == 67
    assert head_bytes({**scope, "query_string": b""}) == len(sent) - len(b"?token=abc")


def test_a_head_over_max_header_bytes_that_arrives_whole_is_refused_431(session: PlaySession) -> None:
    """h11 bounds only an unfinished head: one sent whole in one piece reaches the app, which refuses it.

    ``max_header_bytes=2048``; a request with the token and a 3,000-byte header, sent at once,
    is answered 431; the same request with a 1,000-byte header is served (200).
    """
    limits = ServerLimits(idle_timeout=GUARD * 2, header_timeout=GUARD * 2, max_header_bytes=2048)
    for srv in _serve(session, limits):
        for pad, status in ((3000, b"HTTP/1.1 431"), (1000, b"HTTP/1.1 200")):
            with _connect(srv) as sock:
                line = f"GET /board?token={srv.token} HTTP/1.1\r\nHost: 127.0.0.1:{srv.port}\r\n"
                sock.sendall(f"{line}X-Pad: {'a' * pad}\r\n\r\n".encode())
                answer = b""
                while len(answer) < 12 and (chunk := sock.recv(12 - len(answer))):  # it may come in pieces
                    answer += chunk
                assert answer == status
