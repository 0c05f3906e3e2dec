"""Findings out: compiler-style text, JSON for scripts, SARIF 2.1.0 for CI and code review."""

from __future__ import annotations

import json
from collections.abc import Sequence
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from postproc.check import CheckStats, Finding
from postproc.rules import RULES

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_LEVEL = {"error": "error", "warning": "warning", "info": "note"}


def text(findings: Sequence[Finding]) -> str:
    return "".join(f"{f}\n" for f in findings)


def as_json(findings: Sequence[Finding], stats: dict[str, CheckStats] | None = None) -> str:
    data: dict[str, Any] = {"findings": [
        {"rule": f.rule, "severity": f.severity, "message": f.message, "file": f.file,
         "line": f.line, "column": f.column, "clause": f.clause} for f in findings]}
    if stats:
        data["stats"] = {name: stats_dict(s) for name, s in stats.items()}
    return json.dumps(data, indent=2) + "\n"


def stats_dict(s: CheckStats) -> dict[str, Any]:
    return {
        "blocks": s.blocks, "units": s.units,
        "bounding_box": {a: [str(s.low[a]), str(s.high[a])] for a in sorted(s.low)},
        "rapid_length": round(s.rapid_length, 3), "feed_length": round(s.feed_length, 3),
        "cycle_time_seconds": round(s.seconds, 1), "tools": s.tools,
    }


def sarif(findings: Sequence[Finding]) -> str:
    """A SARIF 2.1.0 log with one run; rules described from the registry."""
    used = sorted({f.rule for f in findings})
    index = {rule: i for i, rule in enumerate(used)}
    try:
        tool_version = version("tapegate")
    except PackageNotFoundError:  # pragma: no cover - running from a source tree
        tool_version = "0"
    rules = [{
        "id": rule,
        "name": rule,
        "shortDescription": {"text": RULES[rule].title},
        "fullDescription": {"text": f"{RULES[rule].title} (ISO 6983-1 {RULES[rule].clause})"},
        "defaultConfiguration": {"level": _LEVEL[RULES[rule].severity]},
        "properties": {"clause": RULES[rule].clause},
    } for rule in used]
    results = [{
        "ruleId": f.rule,
        "ruleIndex": index[f.rule],
        "level": _LEVEL[f.severity],
        "message": {"text": f"{f.message} [{f.clause}]"},
        "locations": [{"physicalLocation": {
            "artifactLocation": {"uri": Path(f.file).as_posix()},
            "region": {"startLine": f.line, "startColumn": f.column},
        }}],
    } for f in findings]
    log = {
        "$schema": SARIF_SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "tapegate", "version": tool_version,
                                "rules": rules}},
            "results": results,
        }],
    }
    return json.dumps(log, indent=2) + "\n"


def stats_text(name: str, s: CheckStats) -> str:
    unit = "in" if s.units == "inch" else "mm"
    lines = [f"{name}: {s.blocks} blocks"]
    for axis in sorted(s.low):
        lines.append(f"  {axis}: {s.low[axis]} to {s.high[axis]} {unit}")
    minutes, seconds = divmod(int(round(s.seconds)), 60)
    lines.append(f"  rapid path {s.rapid_length:.1f} {unit}, feed path {s.feed_length:.1f} {unit}")
    lines.append(f"  estimated cycle time {minutes} min {seconds:02d} s "
                 "(feeds, the profile's rapid rate, dwells)")
    lines.append(f"  tools: {', '.join(f'T{t}' for t in s.tools) or 'none'}")
    return "\n".join(lines) + "\n"
