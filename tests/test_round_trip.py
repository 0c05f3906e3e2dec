"""print(parse(text)) == text for any text: the model loses nothing, valid or not."""

from hypothesis import given, settings
from hypothesis import strategies as st

from formats.parser import PERMISSIVE, STRICT, parse_stream, parse_text
from formats.printer import program_text

nc_text = st.text(alphabet="NGXYZIJFSTM0123456789.+-=()/:% \t\r\n\x00;#[]xy", max_size=300)


@settings(max_examples=300)
@given(nc_text, st.sampled_from([STRICT, PERMISSIVE]))
def test_print_parse_is_identity(text, dialect):
    assert program_text(parse_text(text, dialect, errors="collect")) == text


@settings(max_examples=100)
@given(nc_text, st.integers(1, 50))
def test_chunking_never_changes_the_result(text, size):
    chunks = [text[i:i + size] for i in range(0, len(text), size)]
    streamed = list(parse_stream(chunks, PERMISSIVE, errors="collect"))
    whole = parse_text(text, PERMISSIVE, errors="collect")
    assert [(b.line, b.text, b.words) for b in streamed] == [(b.line, b.text, b.words)
                                                             for b in whole]


@given(st.binary(max_size=400))
def test_random_bytes_never_crash(data):
    text = data.decode("utf-8", errors="surrogateescape")
    assert program_text(parse_text(text, PERMISSIVE, errors="collect")) == text
