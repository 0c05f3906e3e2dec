"""Every error carries a stable code and its location as fields (docs/errors.md), so that code
and tests compare codes and fields, never a message's text."""

from __future__ import annotations

import ast
import pickle
import re
from pathlib import Path

import pytest

from dnc.gateway_config import ConfigError, config_from_text
from dnc.link import LinkError, flow_settings, open_port
from dnc.session import open_pty, send_frames
from formats.convert import ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError, ParseError, ProfileError, TapegateError
from formats.parser import parse_text
from formats.profile import NEUTRAL, load_profile, profile_from_text, serial_settings
from postproc.restart import RestartRefused, plan_restart

ROOT = Path(__file__).resolve().parents[1]
FANUC = load_profile("fanuc-mill")


def raised(kind: type[TapegateError], call, *args, **kw) -> TapegateError:
    with pytest.raises(kind) as caught:
        call(*args, **kw)
    return caught.value


# -- profiles and the gateway configuration: the key at fault --------------------------------


@pytest.mark.parametrize(("text", "code", "key"), [
    ("bogus = 1\n", "profile-unknown-key", "bogus"),
    ("[serial]\nbaud = 1234\n", "profile-value", "serial.baud"),
    ("[serial]\nbaud = true\n", "profile-value", "serial.baud"),
    ("[serial]\nspeed = 9600\n", "profile-unknown-key", "serial.speed"),
    ("[limits]\nX = [10, -10]\n", "profile-value", "limits.X"),
    ("[checks]\npqr = { P = \"angle\" }\n", "profile-value", "checks.pqr.P"),
    ("general = \"PM 399\"\n", "profile-classification", "general"),
    ("reset = [\"G999\"]\n", "profile-value", "reset"),
    # one code written twice, on a base or not (review 56d F4: a KeyError on a base)
    ("base = \"fanuc-mill\"\n[codes]\nM3 = { function = \"a\", duration = \"spindle\" }\n"
     "M03 = { function = \"b\", duration = \"spindle\" }\n", "profile-code-twice", "codes.M03"),
    ("dialect = \"fanuc\"\n[codes]\nM3 = { function = \"a\", duration = \"spindle\" }\n"
     "M03 = { function = \"b\", duration = \"spindle\" }\n", "profile-code-twice", "codes.M03"),
])
def test_a_profile_error_names_its_key(text: str, code: str, key: str) -> None:
    error = raised(ProfileError, profile_from_text, text, source="m.toml")
    assert (error.code, error.key, error.file) == (code, key, "m.toml")


def test_profile_errors_that_are_not_about_a_key(tmp_path: Path) -> None:
    missing = raised(ProfileError, load_profile, "fanuk-mill")
    assert (missing.code, missing.key) == ("profile-not-found", None)
    bad = tmp_path / "bad.toml"
    bad.write_text("name = \n")
    toml = raised(ProfileError, load_profile, str(bad))
    assert (toml.code, toml.file) == ("profile-toml", str(bad))
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe\x00")
    assert raised(ProfileError, load_profile, str(binary)).code == "profile-unreadable"


def test_serial_settings_name_the_key_under_the_prefix_given() -> None:
    """A port's serial table is read with its own prefix and error type: the message and the
    key name the port, and nothing is rewritten after the fact."""
    error = raised(ConfigError, serial_settings, {"stop_bits": 3}, FANUC.serial,
                   prefix="port[2].serial.", error=ConfigError)
    assert (error.code, error.key) == ("config-value", "port[2].serial.stop_bits")
    assert error.message == "port[2].serial.stop_bits must be 1 or 2"
    unknown = raised(ConfigError, serial_settings, {"bauds": 1}, FANUC.serial,
                     prefix="port[0].serial.", error=ConfigError)
    assert (unknown.code, unknown.key) == ("config-unknown-key", "port[0].serial.bauds")


def test_a_config_error_is_placed_on_its_keys_line(tmp_path: Path) -> None:
    (tmp_path / "programs").mkdir()
    text = ("[gateway]\nidle = 1.0\n\n[[port]]\nname = \"m0\"\nurl = \"loop://\"\n"
            "profile = \"fanuc-mill\"\nprograms = \"programs\"\nreceive = \"in\"\n\n"
            "[[port]]\nname = \"m1\"\nurl = \"socket://127.0.0.1:9\"\nprofile = \"fanuc-mill\"\n"
            "programs = \"programs\"\nreceive = \"in\"\nserial = { baud = 7 }\n")
    path = tmp_path / "gateway.toml"
    error = raised(ConfigError, config_from_text, text, path)
    assert (error.code, error.key, error.file, error.line) == (
        "config-value", "port[1].serial.baud", str(path), 17)
    error = raised(ConfigError, config_from_text, text.replace("idle", "idel"), path)
    assert (error.code, error.key, error.line) == ("config-unknown-key", "gateway.idel", 2)
    error = raised(ConfigError, config_from_text, text.replace("url = \"loop://\"\n", ""),
                   path)
    assert (error.code, error.key, error.line) == ("config-missing-key", "port[0].url", 4)


# -- reading, converting, restarting ---------------------------------------------------------


def test_a_block_that_cannot_be_read_has_the_checkers_rule() -> None:
    def read(text: str) -> TapegateError:
        return raised(ParseError, parse_text, text, FANUC.dialect, file="p.nc")

    error = read("N1 G01 X1.\nN2 X1.0.0\n")
    assert (error.code, error.file, error.line, error.column) == ("TG100", "p.nc", 2, 8)
    error = read("N1 X1. $\n")
    assert (error.code, error.line, error.column) == ("TG101", 1, 8)
    error = read("N1 (open\n")
    assert (error.code, error.line, error.column) == ("TG120", 1, 4)


@pytest.mark.parametrize(("program", "options", "code", "clause"), [
    ("N1 X123456.\n", {}, "conversion-format", "Annex C"),  # digit overflow
    ("N1 X1.2345\n", {"rounding": "error"}, "conversion-format", "Annex C"),
    ("N1 G65 P9010 A1. B2.\n", {"units": "inch", "source": FANUC}, "conversion-unprovable",
     "6.4.7"),
])
def test_the_cores_conversion_errors_carry_a_code(program: str, options: dict[str, object],
                                                  code: str, clause: str) -> None:
    from formats.wordformat import Rounding

    if "rounding" in options:
        options = {**options, "rounding": Rounding(options["rounding"])}
    opts = ConvertOptions(load_profile("iso-mill"), **{"source": NEUTRAL, **options})
    error = raised(ConversionError, convert_text, program, opts, file="p.nc")
    assert (error.code, error.clause, error.file, error.line) == (code, clause, "p.nc", 1)
    assert error.column is not None


def test_an_existing_output_is_refused_with_its_code(tmp_path: Path) -> None:
    source, output = tmp_path / "p.nc", tmp_path / "out.nc"
    source.write_text("N1 G01 X1. F100.\nM30\n")
    output.write_text("keep me\n")
    error = raised(ConversionError, convert_file, str(source), str(output),
                   ConvertOptions(load_profile("iso-mill")))
    assert (error.code, error.file) == ("output-exists", str(source))
    assert output.read_text() == "keep me\n"


def test_restart_errors() -> None:
    text = "N10 G90 G54 G00 X0 Y0\nN20 G41 D1 G01 X10. F100.\nN30 X20.\nN40 G40\nM30\n"
    blocks = parse_text(text, FANUC.dialect)
    refused = raised(RestartRefused, plan_restart, blocks, FANUC, 3, "p.nc")
    assert (refused.code, refused.file, refused.line) == ("restart-refused", "p.nc", 3)
    nowhere = raised(RestartRefused, plan_restart, parse_text(text, FANUC.dialect), FANUC, 99,
                     "p.nc")
    assert (nowhere.code, nowhere.file) == ("restart-no-block", "p.nc")


# -- the link ---------------------------------------------------------------------------------


def test_a_stalled_send_says_where_it_stopped_as_a_field() -> None:
    pty = open_pty()  # nobody behind it: no DC1 ever comes
    port = open_port(pty.path, FANUC.serial)
    try:
        frames = [(1, b"%\n"), (2, b"N1 G01 X1.\n")]
        error = raised(LinkError, send_frames, port, frames,
                       flow_settings(FANUC.serial, xon_timeout=0.2))
    finally:
        port.close()
        pty.close()
    assert (error.code, error.stopped_at) == ("link-flow", (0, 0))
    assert error.message.endswith("; stopped at the start of the program, 0 bytes sent")


# -- the fields survive, and every code is documented -----------------------------------------


def test_an_error_keeps_its_fields_across_processes() -> None:
    error = ProfileError("serial.baud = 7: choose one of ...", key="serial.baud", file="m.toml",
                         line=3)
    copy = pickle.loads(pickle.dumps(error))
    assert (type(copy), copy.code, copy.key, copy.file, copy.line, str(copy)) == (
        ProfileError, "profile-value", "serial.baud", "m.toml", 3, str(error))


def _codes_in_source() -> set[str]:
    """Every code the source gives an error: ``code="..."`` at a raise, a class's
    ``default_code``/``unknown_key_code``, and the binding's ``set_item("code", "...")``."""
    codes: set[str] = set()
    for package in ("formats", "postproc", "dnc", "tapegate"):
        for path in (ROOT / package).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                if isinstance(node, ast.keyword) and node.arg == "code":
                    if isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
                        codes.add(node.value.value)
                elif isinstance(node, ast.Assign | ast.AnnAssign) and any(
                        isinstance(t, ast.Name) and t.id in ("default_code", "unknown_key_code")
                        for t in (node.targets if isinstance(node, ast.Assign)
                                  else [node.target])):
                    if isinstance(node.value, ast.Constant):
                        codes.add(node.value.value)
                    else:  # a rule's ID from the core's registry (docs/rules.md): ParseError's
                        assert isinstance(node.value, ast.Call), path
                        assert ast.unparse(node.value.func) == "_core.rule_id", path
    for path in (ROOT / "crates" / "python" / "src").glob("*.rs"):
        text = path.read_text()
        codes.update(re.findall(r'set_item\("code", "([a-z-]+)"\)', text))
        codes.update(re.findall(r'=> "(conversion[a-z-]*)"', text))
    return {code for code in codes if not code.startswith("TG")}  # rules: docs/rules.md


def test_every_code_raised_is_in_the_documented_table() -> None:
    doc = (ROOT / "docs" / "errors.md").read_text().split("\n## Codes\n")[1]
    table = set(re.findall(r"^\| `([a-z][a-z-]*)` \|", doc, re.MULTILINE))
    codes = _codes_in_source()
    assert {"profile-value", "config-value", "link-flow", "conversion-format",
            "diff-modal-drift"} <= codes  # the walk found them
    assert codes - table == set(), "codes raised but not in docs/errors.md"
    assert table - codes == set(), "codes in docs/errors.md that nothing raises"


# -- the command line: one table from error to message and exit code --------------------------


def test_the_command_line_maps_each_error_in_one_place() -> None:
    from dnc.gateway_config import ConfigError as Config
    from dnc.link import PortLost
    from dnc.workflow import Refused
    from formats.errors import OutputError
    from tapegate.common import error_exit

    where = {"file": "p.nc", "line": 3, "column": 4}
    assert error_exit(ConversionError("X9 overflows", **where)) == ("p.nc:3:4: X9 overflows", 1)
    assert error_exit(ConversionError("X9 overflows", **where), input_exit=2)[1] == 2  # diff
    assert error_exit(ProfileError("no profile named 'x'")) == (
        "tapegate: no profile named 'x'", 2)
    assert error_exit(ProfileError("no such table", file="m.toml", line=2)) == (
        "tapegate: m.toml:2: no such table", 2)
    assert error_exit(Config("port[0].url is missing", file="g.toml", line=7)) == (
        "tapegate: g.toml:7: port[0].url is missing", 2)
    assert error_exit(OutputError("cannot write o/x.nc: no such folder", file="x")) == (
        "tapegate: cannot write o/x.nc: no such folder", 2)
    assert error_exit(PortLost("port /dev/ttyS0 vanished")) == (
        "tapegate: port /dev/ttyS0 vanished", 3)
    assert error_exit(LinkError("EIA code is always sent with software parity",
                                code="link-settings")) == (
        "<input>: EIA code is always sent with software parity", 1)
    assert error_exit(TapegateError("modbus: cannot listen on 127.0.0.1:1: denied",
                                    code="listen-failed"))[1] == 3
    assert error_exit(Refused([])) == (
        "tapegate: not sent: the check found 0 error(s); fix them or use --force", 1)


def test_no_code_reads_an_errors_message_to_decide() -> None:
    """An error's text is for people: no runtime code tests it (``"stopped at" in
    exc.message``), edits it (``exc.message.replace``) or matches it (``re.match(...,
    exc.message)``). Passing it on whole, to a log or a journal, is reading, not deciding."""
    found = []
    for package in ("formats", "postproc", "dnc", "tapegate"):
        for path in (ROOT / package).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                def is_message(n: ast.AST) -> bool:
                    return isinstance(n, ast.Attribute) and n.attr in ("message", "msg")

                if isinstance(node, ast.Compare) and any(
                        is_message(n) for n in (node.left, *node.comparators)):
                    found.append(f"{path.name}:{node.lineno} compares a message")
                elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                      and is_message(node.func.value)):
                    found.append(f"{path.name}:{node.lineno} calls {node.func.attr} on a message")
                elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                      and isinstance(node.func.value, ast.Name) and node.func.value.id == "re"
                      and any(is_message(a) for a in node.args)):
                    found.append(f"{path.name}:{node.lineno} matches a message")
                elif (isinstance(node, ast.Assign)
                      and any(is_message(t) for t in node.targets)
                      and isinstance(node.value, ast.Call)):
                    found.append(f"{path.name}:{node.lineno} rewrites a message")
    assert found == []
