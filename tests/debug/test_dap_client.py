"""The tests' DAP client itself (no essaim needed): its framing reads messages however the
bytes are cut, and refuses bytes that are not DAP (what an adapter printing to stdout would
send), so that the session tests fail on a stray line instead of misreading it; against a
scripted adapter, it sends a session's requests in the order editors do, and a request that
fails or an event that never comes fails the test with the transcript."""
import io
import sys

import pytest

from dap_client import DapClient, DapFailure, _Framing, frame


def reader(data: bytes, cut: int):
    stream = io.BytesIO(data)
    return _Framing(lambda n: stream.read(min(n, cut)))


@pytest.mark.parametrize("cut", [1, 7, 65536])
def test_messages_are_read_whatever_the_chunks(cut):
    messages = [{"seq": 1, "type": "event", "event": "initialized"},
                {"seq": 2, "type": "response", "request_seq": 1, "success": True, "body": {"text": "é\r\n"}}]
    framing = reader(b"".join(frame(m) for m in messages), cut)
    assert [framing.next(), framing.next(), framing.next()] == [*messages, None]


def test_bytes_that_are_not_dap_are_refused():
    framing = reader(b"tick 3: hello\r\n\r\n" + frame({"seq": 1}), 64)
    with pytest.raises(DapFailure, match="not a DAP header line"):
        framing.next()


def test_a_stream_cut_inside_a_message_is_refused():
    framing = reader(frame({"seq": 1, "type": "event"})[:-3], 64)
    with pytest.raises(DapFailure, match="inside a body"):
        framing.next()


# A scripted adapter: answers every request, and plays the events of a session that stops
# once at a breakpoint; enough to check the client's order of requests and its waits.
FAKE_ADAPTER = r'''
import json, sys
out = sys.stdout.buffer
seq = 0
def send(kind, **m):
    global seq
    seq += 1
    body = json.dumps({"seq": seq, "type": kind, **m}).encode()
    out.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    out.flush()
def read():
    head = b""
    while not head.endswith(b"\r\n\r\n"):
        c = sys.stdin.buffer.read(1)
        if not c:
            sys.exit(0)
        head += c
    return json.loads(sys.stdin.buffer.read(int(head.split(b":")[1])))
while True:
    r = read()
    body = {"supportsStepBack": True} if r["command"] == "initialize" else {}
    if r["command"] == "setBreakpoints":
        body = {"breakpoints": [{"verified": True, "line": b["line"]} for b in r["arguments"]["breakpoints"]]}
    send("response", request_seq=r["seq"], command=r["command"], success=r["command"] != "bad", body=body)
    if r["command"] == "initialize":
        send("event", event="initialized")
    if r["command"] == "configurationDone":
        send("event", event="output", body={"category": "stdout", "output": "hello\n"})
        send("event", event="stopped", body={"reason": "breakpoint", "threadId": 2})
    if r["command"] == "continue" and not r["arguments"].get("silent"):
        send("event", event="exited", body={"exitCode": 0})
        send("event", event="terminated")
'''


@pytest.fixture
def fake(tmp_path):
    script = tmp_path / "fake_adapter.py"
    script.write_text(FAKE_ADAPTER)
    client = DapClient.command([sys.executable, script], cwd=tmp_path, timeout=5)
    yield client
    client.kill()


def test_a_session_runs_in_the_order_editors_use(fake):
    got = fake.start(breakpoints={"/x/c.lua": [3, {"line": 7, "condition": "tick == 2"}]})
    assert got["capabilities"] == {"supportsStepBack": True}
    assert [b["line"] for b in got["breakpoints"]["/x/c.lua"]] == [3, 7]
    assert fake.stopped() == {"reason": "breakpoint", "threadId": 2}
    assert fake.outputs("stdout") == ["hello\n"]
    assert fake.run_to_end(2) == 0
    sent = [m["command"] for d, m in fake.transcript if d == "->"]
    assert sent == ["initialize", "launch", "setBreakpoints", "setExceptionBreakpoints", "configurationDone",
                    "continue"]


def test_a_failed_request_or_a_missing_event_fails_the_test_with_the_transcript(fake):
    fake.start()
    with pytest.raises(pytest.fail.Exception, match="bad failed"):
        fake.request("bad")
    fake.timeout = 0.3
    with pytest.raises(pytest.fail.Exception, match=r"(?s)nothing after 0 s.*DAP transcript.*configurationDone"):
        fake.wait_event("never")
