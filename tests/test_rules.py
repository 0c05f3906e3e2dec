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
