"""The tests' DAP client itself (no essaim needed): its framing reads messages however the
bytes are cut, and refuses bytes that are not DAP (what an adapter printing to stdout would
send), so that the session tests fail on a stray line instead of misreading it."""
import io

import pytest

from dap_client import DapFailure, _Framing, frame


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
