"""Every rule of the registry: its own example triggers it, its quiet example does not."""

from __future__ import annotations

import pytest

from formats.profile import load_profile
from postproc.check import check_text
from postproc.rules import RULES

TEXT_RULES = [r for r in RULES.values() if r.bad]


@pytest.mark.parametrize("rule", TEXT_RULES, ids=[r.id for r in TEXT_RULES])
def test_rule_triggers_on_its_example(rule):
    findings = check_text(rule.bad, load_profile(rule.profile), file="bad.nc")
    hits = [f for f in findings if f.rule == rule.id]
    assert hits, f"{rule.id} quiet on its example; found {[str(f) for f in findings]}"
    f = hits[0]
    assert f.file == "bad.nc" and f.line >= 1 and f.column >= 1
    assert f.severity == rule.severity and f.clause == rule.clause


@pytest.mark.parametrize("rule", TEXT_RULES, ids=[r.id for r in TEXT_RULES])
def test_rule_quiet_on_correct_input(rule):
    findings = check_text(rule.good, load_profile(rule.profile), file="good.nc")
    assert not [f for f in findings if f.rule == rule.id], [str(f) for f in findings]


def test_every_core_rule_has_its_examples_and_every_example_a_rule():
    """The core's registry (crates/core/src/rules.rs) and the examples keyed by ID in
    postproc/rules.py name the same rules: a rule without examples, or examples of a rule the
    core does not have, fails here."""
    from postproc.rules import CORE_RULES, EXAMPLES

    core_ids = [row[1] for row in CORE_RULES]
    assert len(core_ids) == len(set(core_ids))
    assert set(EXAMPLES) == set(core_ids)
    assert list(RULES) == core_ids


def test_the_registry_describes_each_rule_once():
    from postproc.rules import READING_RULES, rule_id

    assert rule_id("TapeParity") == "TG701"
    with pytest.raises(KeyError):
        rule_id("NoSuchRule")
    # the tokenizer's errors (characters, comments, skip, alignment, indexes) and the tape's
    # are the reading rules; nothing the checker finds in a readable block is
    assert {"TG100", "TG101", "TG120", "TG121", "TG123", "TG125", "TG206",
                             "TG701", "TG702"} == READING_RULES
    assert {r.family for r in RULES.values()} == {
        "structure", "words", "formats", "codes", "motion", "tooling", "limits", "link"}


def test_rule_ids_are_written_only_in_the_registry():
    """`grep '"TG[0-9]'` over the runtime sources finds rule IDs only in the registry (the
    core's rules.rs, and the examples keyed by ID in postproc/rules.py): a call site names a
    rule, never its ID."""
    import re
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    registry = {root / "crates/core/src/rules.rs", root / "postproc/rules.py"}
    pattern = re.compile(r"[\"']TG[0-9]")
    sources = [p for package in ("formats", "postproc", "dnc", "tapegate", "benchmarks", "fuzz")
               for p in (root / package).rglob("*.py")]
    sources += list((root / "crates").rglob("*.rs"))
    offenders = []
    for path in sources:
        if path in registry or "fuzz" in path.parts:
            continue
        for number, line in enumerate(path.read_text("utf-8").splitlines(), 1):
            code = line.split("//")[0] if path.suffix == ".rs" else line.split("#")[0]
            if pattern.search(code) and "#[cfg(test)]" not in code:
                offenders.append(f"{path.relative_to(root)}:{number}: {line.strip()}")
    assert not offenders, "\n".join(offenders)


def test_every_error_rule_names_its_source():
    """Issue 32: an error means the control alarms or the manual forbids it, and each error
    rule names its source in docs/rules.md: the clause and, family by family, the alarm, the
    manual's rule or "no source at hand"."""
    from postproc.rules import SOURCES, markdown

    errors = [r.id for r in RULES.values() if r.severity == "error"]
    assert [rule for rule in errors if rule not in SOURCES] == []
    text = markdown()
    for rule in errors:
        section = text.split(f"## {rule}: ", 1)[1].split("\n## ", 1)[0]
        assert f"Source: {SOURCES[rule]}" in section, rule


FAMILY_PROFILES = ["fanuc-mill", "fanuc-lathe", "haas-mill", "haas-lathe", "sinumerik-840d",
                   "okuma-mill", "okuma-lathe", "linuxcnc"]


@pytest.mark.parametrize("profile", FAMILY_PROFILES)
def test_the_iso_only_errors_do_not_fire_on_a_family_profile(profile):
    """The sources say TG202 (no DS), TG301/TG303 (the ISO code table), TG408 (an arc with no
    start) and TG409 (quadrant I J K) are the ISO profiles' alone: a family profile has DS,
    reads a code outside its table as TG306 or TG307, and starts where its caller left the
    tool. A FANUC's TG202 is its own: a decimal point in S alarms there (PS0007)."""
    text = "G17 G90\nG02 X10. Y0 I5. J0 F100.\nG200 X1.\nG25 X1.\nM03 S1000.5\n"
    if not profile.startswith(("linuxcnc", "sinumerik")):
        text = "%\nO1000\n" + text + "M30\n%\n"
    else:
        text += "M30\n"
    found = {f.rule for f in check_text(text, load_profile(profile), file="t.nc")}
    fanuc = profile.startswith("fanuc")
    iso_only = {"TG301", "TG303", "TG408", "TG409"} | (set() if fanuc else {"TG202"})
    assert not found & iso_only, found
    assert ("TG202" in found) == fanuc, found  # S1000.5: PS0007 on a FANUC
    assert found & {"TG306", "TG307"}, found  # G200 is named, as the family's unknown code
