"""The play server refuses what a hostile page (or a rebinding host name) would send.

Each request below is one a web page on another origin can make a browser send, or
one a DNS-rebinding page makes with a foreign Host. The expectation is stated from
the rule (only the page this server handed out, with its token, changes the game), so
every refused request must leave the session untouched: no move recorded, still open.
Requests go to the real server (uvicorn on a free port) over plain sockets, as a
browser's would; ``http.client`` sends whatever Host header it is given.
"""

from __future__ import annotations

import http.client
import json
import socket
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from hg_marl.core.errors import HumanError

pytest.importorskip("starlette")
pytest.importorskip("uvicorn")

from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.web import COOKIE, MAX_BODY, TOKEN_HEADER, Server


@dataclass
class Answer:
    status_code: int
    text: str
    headers: dict[str, str]


class Client:
    """Plain HTTP to the real server (http.client sends the Host header it is given)."""

    def __init__(self, server: Server) -> None:
        self.port, self.token = server.port, server.token
        self.own = f"http://127.0.0.1:{self.port}"

    def request(self, method: str, url: str, content: bytes = b"", headers: dict[str, str] | None = None) -> Answer:
        headers = {"host": f"127.0.0.1:{self.port}", **(headers or {})}
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=600)
        try:
            conn.request(method, url, body=content if method == "POST" else None, headers=headers)
            r = conn.getresponse()
            return Answer(r.status, r.read().decode(errors="replace"), {k.lower(): v for k, v in r.getheaders()})
        finally:
            conn.close()

    def get(self, url: str, headers: dict[str, str] | None = None) -> Answer:
        return self.request("GET", url, headers=headers)

    def post(self, url: str, content: bytes, headers: dict[str, str]) -> Answer:
        return self.request("POST", url, content, headers)

    def own_headers(self, **extra: str) -> dict[str, str]:
        """What the play page sends, with ``extra`` replacing some of it ("" drops a header)."""
        headers = {"origin": self.own, TOKEN_HEADER: self.token, "content-type": "application/json", **extra}
        return {k: v.replace("PORT", str(self.port)) for k, v in headers.items() if v}


@pytest.fixture
def session(tmp_path: Path) -> PlaySession:
    return PlaySession("planner", seed=0, record=tmp_path, player="guard-test")


@pytest.fixture
def server(session: PlaySession) -> Iterator[Server]:
    srv = Server(session, 0)
    srv.start_in_thread()
    yield srv
    srv.stop()


@pytest.fixture
def client(server: Server) -> Client:
    return Client(server)


def move(session: PlaySession) -> bytes:
    return json.dumps({"action": session.choices()[0].index}).encode()


def test_the_own_page_plays_a_move(client: Client, session: PlaySession) -> None:
    page = client.get(f"/?token={client.token}")
    assert page.status_code == 200 and client.token in page.text
    assert f"{COOKIE}={client.token}" in page.headers["set-cookie"]
    assert "samesite=strict" in page.headers["set-cookie"].lower()
    assert "frame-ancestors 'none'" in page.headers["content-security-policy"]
    r = client.post("/act", move(session), client.own_headers())
    assert r.status_code == 200 and len(session.response_times) == 1
    # localhost is the same server under its other name
    headers = client.own_headers(host="localhost:PORT", origin="http://localhost:PORT")
    r = client.post("/act", move(session), headers)
    assert r.status_code == 200 and len(session.response_times) == 2


HOSTILE: dict[str, tuple[dict[str, str], int]] = {
    "foreign Host (DNS rebinding)": ({"host": "evil.example:PORT"}, 403),
    "no port in Host": ({"host": "127.0.0.1"}, 403),
    "own host name, other port": ({"host": "127.0.0.1:80"}, 403),
    "foreign Origin": ({"origin": "http://evil.example"}, 403),
    "own host, other port as Origin": ({"origin": "http://127.0.0.1:80"}, 403),
    "null Origin (sandboxed frame)": ({"origin": "null"}, 403),
    "missing Origin": ({"origin": ""}, 403),
    "missing token": ({TOKEN_HEADER: ""}, 403),
    "wrong token": ({TOKEN_HEADER: "guess"}, 403),
    "non-ASCII token": ({TOKEN_HEADER: "\u00e9t\u00e9"}, 403),
    "text/plain (no preflight)": ({"content-type": "text/plain"}, 415),
    "form post": ({"content-type": "application/x-www-form-urlencoded"}, 415),
}


@pytest.mark.parametrize("name", list(HOSTILE))
@pytest.mark.parametrize("route", ["/act", "/quit"])
def test_hostile_state_changes_are_refused(client: Client, session: PlaySession, name: str, route: str) -> None:
    changes, status = HOSTILE[name]
    r = client.post(route, move(session), client.own_headers(**changes))
    assert r.status_code == status, r.text
    assert session.response_times == [] and not session.closed


def test_a_cookie_alone_does_not_make_a_move(client: Client, session: PlaySession) -> None:
    headers = client.own_headers(**{TOKEN_HEADER: "", "cookie": f"{COOKIE}={client.token}"})
    r = client.post("/act", move(session), headers)
    assert r.status_code == 403 and session.response_times == []


@pytest.mark.parametrize(
    "url,headers",
    [
        ("/", {}),
        ("/?token=guess", {}),
        ("/?token=%C3%A9", {}),
        ("/board", {TOKEN_HEADER: "\u00e9"}),
        ("/board", {}),
        ("/?token=TOKEN", {"host": "evil.example:PORT"}),
        ("/board", {"cookie": f"{COOKIE}=TOKEN", "host": "evil.example:PORT"}),
    ],
)
def test_pages_need_the_token_and_the_own_host(client: Client, url: str, headers: dict[str, str]) -> None:
    fill = {k: v.replace("PORT", str(client.port)).replace("TOKEN", client.token) for k, v in headers.items()}
    r = client.get(url.replace("TOKEN", client.token), headers=fill)
    assert r.status_code == 403 and "<svg" not in r.text


def test_the_cookie_serves_reloads(client: Client) -> None:
    r = client.get("/board", headers={"cookie": f"{COOKIE}={client.token}"})
    assert r.status_code == 200 and "<svg" in r.text


@pytest.mark.parametrize(
    "body,status",
    [
        (b"[" * 100_000 + b"]" * 100_000, 413),  # too big, refused before it is read
        (b"[" * (MAX_BODY // 2) + b"]" * (MAX_BODY // 2), 400),  # fits, but deeper than the parser recurses
        (b'{"action": ', 400),
        (b"\xff\xfe", 400),
        (b'{"action": true}', 400),
        (b'{"action": [1]}', 400),
        (b"[3]", 400),
    ],
)
def test_bad_bodies_are_client_errors(client: Client, session: PlaySession, body: bytes, status: int) -> None:
    r = client.post("/act", body, client.own_headers())
    assert r.status_code == status and session.response_times == []


def test_quit_ends_the_game(client: Client, session: PlaySession) -> None:
    after = move(session)
    r = client.post("/quit", b"{}", client.own_headers())
    assert r.status_code == 200 and session.closed and 'id="summary"' in r.text
    with pytest.raises(HumanError, match="game is over"):
        session.play(json.loads(after)["action"])
    assert session.response_times == []


def _raw(port: int, request: bytes, stream: bytes = b"") -> tuple[int, int]:
    """Send ``request`` then up to 1 MiB of ``stream``; (status, bytes of the stream sent)."""
    with socket.create_connection(("127.0.0.1", port), timeout=600) as sock:
        sock.sendall(request)
        sent = 0
        sock.settimeout(0.05)
        while stream and sent < 1 << 20:
            try:
                sock.sendall(stream)
                sent += len(stream)
            except OSError:
                break
            try:
                if sock.recv(1, socket.MSG_PEEK):
                    break
            except TimeoutError:
                continue
        sock.settimeout(10)
        head = sock.recv(4096)
    return int(head.split(b" ", 2)[1]), sent


def test_a_huge_declared_body_is_refused_unread(server: Server, session: PlaySession) -> None:
    head = (
        f"POST /act HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\nOrigin: http://127.0.0.1:{server.port}\r\n"
        f"{TOKEN_HEADER}: {server.token}\r\nContent-Type: application/json\r\nContent-Length: 300000000\r\n\r\n"
    ).encode()
    status, _ = _raw(server.port, head)
    assert status == 413 and session.response_times == []


def test_a_streamed_body_is_cut_at_the_limit(server: Server, session: PlaySession) -> None:
    head = (
        f"POST /act HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\nOrigin: http://127.0.0.1:{server.port}\r\n"
        f"{TOKEN_HEADER}: {server.token}\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n"
    ).encode()
    chunk = b"1000\r\n" + b" " * 0x1000 + b"\r\n"
    status, sent = _raw(server.port, head, chunk)
    assert status == 413 and session.response_times == []
    assert sent < 1 << 20, "the server answered only after a megabyte: it read past the limit"


def test_a_foreign_host_is_refused_over_the_socket(server: Server, session: PlaySession) -> None:
    status, _ = _raw(server.port, f"GET /?token={server.token} HTTP/1.1\r\nHost: evil.example\r\n\r\n".encode())
    assert status == 403
