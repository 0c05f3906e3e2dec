"""The rule registry: every check of ``tapegate check`` with its ID, severity, clause and examples.

Each rule carries a program that triggers it (``bad``) and one that is quiet (``good``), both under
the profile named by ``profile``; the test suite runs every pair, and ``docs/rules.md`` is
generated from this registry (``python -m postproc.rules > docs/rules.md``), so the catalogue, the
code and the tests cannot drift apart.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Severity = Literal["error", "warning", "info"]
SEVERITY_RANK = {"info": 0, "warning": 1, "error": 2}


@dataclass(frozen=True)
class Rule:
    """A check rule of the registry: its ID, severity, clause and title."""

    id: str
    severity: Severity
    clause: str
    title: str
    bad: str
    good: str
    profile: str = "iso-mill"


RULES: dict[str, Rule] = {}


def _rule(id: str, severity: Severity, clause: str, title: str, bad: str, good: str,
          profile: str = "iso-mill") -> None:
    assert id not in RULES, id
    RULES[id] = Rule(id, severity, clause, title, bad, good, profile)


P = "%\nN1 G71\nN2 G90\nN3 G17\n"  # a correct start
E = "N99 M30\n%\n"  # a correct end

# -- characters and program structure (clause 4, Annex A) ---------------------------------------
_rule("TG100", "error", "6.1", "block cannot be read (a word without a number, a stray digit...)",
      P + "N2 X\n" + E, P + "N2 X0\n" + E)
_rule("TG101", "error", "Annex A", "character outside Annex A and the profile's extra characters",
      P + "N2 X1 $\n" + E, P + "N2 X1\n" + E)
_rule("TG102", "warning", "Annex A", "lower-case address (the profile reads it as upper case)",
      P + "N2 x1\n" + E, P + "N2 X1\n" + E, "neutral")
_rule("TG110", "warning", "4", "program does not begin with the program start character %",
      "N1 G71 G90\n" + E, P + E)
_rule("TG111", "error", "4", "words on the % line: an end of block must precede the first block",
      "%N1 G71 G90\n" + E, P + E)
_rule("TG112", "error", "4", "program identification with letters not enclosed in parentheses",
      "%BRACKET\nN1 G71\n" + E, "%(BRACKET)\nN1 G71\n" + E)
_rule("TG113", "warning", "4", "program number word not in the first block after %",
      "%\nN1 G21\nO1234\n" + E.replace("N99", "N99"), "%\nO1234\nN1 G21\n" + E, "fanuc-mill")
_rule("TG114", "error", "Annex E", "program ends without M02 or M30",
      P + "N2 X1\n%\n", P + "N2 X1\n" + E)
_rule("TG115", "warning", "4", "M02/M30 not followed by the closing %",
      P + "N2 M30\n", P + "N2 M30\n%\n")
_rule("TG116", "error", "Annex E", "words after the end of program (M02/M30)",
      P + "N2 M30\nN3 X1\n%\n", P + "N2 M30\n%\n")
# -- comments, skip, alignment ------------------------------------------------------------------
_rule("TG120", "error", "4", "comment not closed before the end of block",
      P + "N2 X1 (OPEN\n" + E, P + "N2 X1 (CLOSED)\n" + E)
_rule("TG121", "error", "4", "nested or unbalanced comment brackets",
      P + "N2 X1 (A (B) C)\n" + E, P + "N2 X1 (A B C)\n" + E)
_rule("TG122", "error", "4", "comment containing '%' (a rewind stop), or ':' where the control's "
      "tape reader takes it for the alignment stop (checks.comment_colon = \"stop\")",
      P + "N2 X1 (50% FEED)\n" + E, P + "N2 X1 (HALF FEED)\n" + E)
_rule("TG123", "error", "4", "'/' block skip not immediately before the sequence number",
      P + "N2 / X1\n" + E, P + "/N2 X1\n" + E)
_rule("TG124", "warning", "4", "':' alignment used but the profile's classification has no ':'",
      "%\n:1 G71 G90\n" + E, "%\nN1 G71 G90\n" + E, "pm322-eia")
_rule("TG125", "warning", "4", "alignment ':' not at the start of the block",
      P + "N2 X1 :3\n" + E, P + ":3 X1\n" + E)
_rule("TG126", "info", "4", "':' in comments where the control reads a comment as text "
      "(checks.comment_colon = \"text\"): harmless, said once per file with a count",
      "%\nO1\nG21 G90\n(T1 D10 FLAT - 21:09)\nM30\n%\n",
      "%\nO1\nG21 G90\n(T1 D10 FLAT - 21H09)\nM30\n%\n", "fanuc-mill")
# -- words: order, repetition, formats (clauses 5, 6) -------------------------------------------
_rule("TG130", "info", "5.2", "word order: N, G, X Y Z U V W P Q R A B C, I J K after X Y Z, "
      "F, S, T D, M (clause 5.2 recommends it; controls read any order)",
      P + "N2 X1 G01 F100\n" + E, P + "N2 G01 X1 F100\n" + E)
_rule("TG131", "error", "5.2", "dimension word repeated in a block",
      P + "N2 G01 X1 X2 F100\n" + E, P + "N2 G01 X2 F100\n" + E)
_rule("TG132", "warning", "5.2", "non-dimensional word repeated in a block",
      P + "N2 M03 M08\n" + E, P + "N2 M03\nN3 M08\n" + E)
_rule("TG133", "info", "Annex D", "more than one G word in a block (interchangeability)",
      P + "N2 G00 G90 X1\n" + E, P + "N2 G00 X1\n" + E)
_rule("TG134", "warning", "Annex C", "address not in the profile's detailed format classification",
      P + "N2 G01 W5. F100\n" + E, P + "N2 G01 Z5. F100\n" + E)
_rule("TG140", "info", "dialect", "jump, loop or call the checker does not follow: the position, "
      "feed and speed are unknown after it (said once per file)",
      "%\nO1000\nG21 G90 G00 X0 Y0\nIF [#1 GT 0] GOTO 20\nN20 G01 X1 F100\nM30\n%\n",
      "%\nO1000\nG21 G90 G00 X0 Y0\nG01 X1 F100\nM30\n%\n", "fanuc-mill")
_rule("TG141", "info", "dialect", "value the checker cannot evaluate (F[#101*2], X[#1+#2]; a "
      "variable set to a constant is known): set but unknown from there on (said once per file)",
      "%\nO1000\n#101 = 200\nG21 G90 G01 X1 F[#101*2]\nM30\n%\n",
      "%\nO1000\nG21 G90 G01 X1 F200.\nM30\n%\n", "fanuc-mill")
_rule("TG201", "warning", "6.1", "implicit and explicit decimal mixed in one program",
      P + "N2 G01 X12.5 F100\nN3 Y12500\n" + E, P + "N2 G01 X12.5 F100\nN3 Y12.5\n" + E)
_rule("TG202", "error", "6.1", "decimal point where the profile has no explicit decimal sign (DS)",
      "%\nN001 G01 X12.5\n" + E.replace("N99", "N099"), "%\nN001 G01 X0125\n" +
      E.replace("N99", "N099"), "pm322-eia")
_rule("TG203", "error", "Annex C", "more digits than the word format holds",
      P + "N2 G01 X1.23456 F100\n" + E, P + "N2 G01 X1.235 F100\n" + E)
_rule("TG204", "error", "Annex C", "sign on a word whose format has none",
      P + "N2 G01 X1 F-100\n" + E, P + "N2 G01 X1 F100\n" + E)
_rule("TG205", "error", "Annex C", "value out of the word format's range (digit overflow)",
      P + "N2 G01 X123456 F100\n" + E, P + "N2 G01 X12345 F100\n" + E)
_rule("TG206", "error", "6.2", "address index 0 or above the profile's maximum (parameters: "
      "the profile's number of parameters)",
      P + "N2 X12=5\n" + E, P + "N2 X2=5\nN3 R11 = 22.2\n" + E)
_rule("TG207", "warning", "6.2.2", "indexed G word: the standard does not intend G indexing "
      "(the profile may allow it)", P + "N2 G1=1 X1=5 F100\n" + E, P + "N2 G01 X1=5 F100\n" + E)
# -- codes (Annex E) ----------------------------------------------------------------------------
_rule("TG301", "error", "Annex E", "G or M code not in the profile's code table",
      P + "N2 G123\n" + E, P + "N2 G01 X1 F100\n" + E, "pm322-eia")
_rule("TG302", "warning", "Annex E", "code unassigned by the standard and not designated by the "
      "profile (individual use)", P + "N2 M12\n" + E, P + "N2 M09\n" + E)
_rule("TG303", "error", "Annex E", "permanently unassigned code",
      P + "N2 G25\n" + E, P + "N2 G01 X1 F100\n" + E)
_rule("TG304", "error", "Annex E", "two codes of one modal group in a block",
      P + "N2 G00 G01 X1 F100\n" + E, P + "N2 G01 X1 F100\n" + E)
_rule("TG306", "error", "profile", "G or M code the control does not have and alarms on "
      "(checks.unknown_g / unknown_m = \"alarm\"; the default for G codes of a dialect family)",
      "%\nO1\nG21 G90 G00 X0\nG130 X1.\nM30\n%\n", "%\nO1\nG21 G90 G00 X0\nG01 X1. F100.\nM30\n%\n",
      "fanuc-mill")
_rule("TG305", "warning", "Annex E", "M code of a class the profile does not have",
      P + "N2 M240\n" + E, P + "N2 M08\n" + E)
# -- motion and geometry (clauses 7, Annex E) ---------------------------------------------------
_rule("TG401", "error", "7", "feed motion without a feed rate in force",
      P + "N2 G01 X10\n" + E, P + "N2 G01 X10 F100\n" + E)
_rule("TG402", "error", "Annex E", "G93 inverse time motion without F in the block",
      P + "N2 G93 G01 X10 F2\nN3 X20\n" + E, P + "N2 G93 G01 X10 F2\nN3 X20 F2\n" + E)
_rule("TG403", "error", "7.3", "arc: start and end radius differ by more than the tolerance",
      P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I11 J0 F100\n" + E,
      P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_rule("TG404", "error", "7.3", "arc centre word missing or outside the selected plane",
      P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 K10 F100\n" + E,
      P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 F100\n" + E)
_rule("TG405", "error", "7.3", "arc of zero radius",
      P + "N2 G00 X0 Y0\nN3 G02 X0 Y0 I0 J0 F100\n" + E,
      P + "N2 G00 X0 Y0\nN3 G02 X0 Y0 I5 J0 F100\n" + E)
_rule("TG406", "info", "7.3", "helical arc (third axis moves with the arc)",
      P + "N2 G00 X0 Y0 Z0\nN3 G02 X20 Y0 I10 J0 Z-1 F100\n" + E,
      P + "N2 G00 X0 Y0 Z0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_rule("TG407", "warning", "7.4", "G06 parabola without its tangent point (I J K) or second block",
      P + "N2 G06 X10 Y5 F100\nN3 G01 X20\n" + E,
      P + "N2 G06 X10 Y5 I5 J0 F100\n" + E)
_rule("TG408", "error", "7.3", "arc without a position to start from (no earlier X/Y/Z)",
      P + "N2 G02 X20 Y0 I10 J0 F100\n" + E,
      P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_rule("TG409", "error", "7.3", "arc crosses a quadrant boundary on a quadrant-limited control "
      "(checks.ijk = \"quadrant\": sign-less I J K, one quadrant per block)",
      "%\nN1 G90 G17\nN2 G00 X2000 Y0\nN3 G03 X-2000 Y0 I2000 J0 F100\nN99 M30\n%\n",
      "%\nN1 G90 G17\nN2 G00 X2000 Y0\nN3 G03 X0 Y2000 I2000 J0 F100\n"
      "N4 G03 X-2000 Y0 I0 J2000\nN99 M30\n%\n", "cm332-quadrant")
_rule("TG411", "error", "7", "axis words with no motion mode in force: LinuxCNC has none at the "
      "start and after G80 (the other controls keep G00/G01 from reset and through G80)",
      "G21 G90 G17\nG01 X0 Y0 Z5 F100\nG81 X1 Y1 Z-1 R1\nG80\nX2\nM2\n",
      "G21 G90 G17\nG01 X0 Y0 Z5 F100\nG81 X1 Y1 Z-1 R1\nG80\nG01 X2\nM2\n", "linuxcnc")
_rule("TG410", "error", "7.3", "arc radius (R, Sinumerik CR=) shorter than half the chord: no "
      "arc of that radius joins the points",
      "%\nO1\nG21 G90 G17 G00 X0 Y0\nG02 X20. Y0 R5. F100.\nM30\n%\n",
      "%\nO1\nG21 G90 G17 G00 X0 Y0\nG02 X20. Y0 R10. F100.\nM30\n%\n", "fanuc-mill")
# -- compensation, threads, speed, dwell, cycles (clauses 10-13, Annex E) ------------------------
_rule("TG501", "error", "10", "cutter compensation introduced or removed in a circular block",
      P + "N2 G00 X0 Y0\nN3 G41 G02 X20 Y0 I10 J0 F100 D1\n" + E,
      P + "N2 G41 G01 X0 Y0 F100 D1\nN3 G02 X20 Y0 I10 J0\n" + E)
_rule("TG502", "error", "10", "new T or D while cutter compensation is active (G40 first)",
      P + "N2 G41 G01 X0 F100 D1\nN3 D2\n" + E,
      P + "N2 G41 G01 X0 F100 D1\nN3 G40 G01 X5\nN4 D2\n" + E)
_rule("TG511", "error", "11", "G33 constant lead with both a lead word and F",
      P + "N2 G33 Z-20 K1.5 F100\n" + E, P + "N2 G33 Z-20 K1.5\n" + E, "iso-lathe")
_rule("TG512", "error", "11", "thread lead with an algebraic sign",
      P + "N2 G33 Z-20 K-1.5\n" + E, P + "N2 G33 Z-20 K1.5\n" + E, "iso-lathe")
_rule("TG513", "error", "11", "G34/G35 variable lead without its lead and rate words",
      P + "N2 G34 Z-20 K1.5\n" + E, P + "N2 G34 Z-20 K1.5 F0.1\n" + E, "iso-lathe")
_rule("TG521", "warning", "12", "G96 constant surface speed without an earlier G92 S limit",
      P + "N2 G96 S200 M03\n" + E, P + "N2 G92 S3000\nN3 G96 S200 M03\n" + E, "iso-lathe")
_rule("TG531", "warning", "13", "G04 dwell not alone in its block",
      P + "N2 G04 X2 M03\n" + E, P + "N2 G04 X2\n" + E)
_rule("TG532", "error", "13", "G04 dwell without a duration (F, P or X)",
      P + "N2 G04\n" + E, P + "N2 G04 F2\n" + E)
_rule("TG541", "error", "Annex E", "fixed cycle without its depth (Z) or retract (R) word",
      P + "N2 G81 X10 Y10 F100\n" + E, P + "N2 G81 X10 Y10 Z-5 R2 F100\n" + E, "fanuc-mill")
_rule("TG542", "warning", "Annex E", "motion code while a fixed cycle is active (G80 first; ISO "
      "only: Fanuc, Haas, Siemens and LinuxCNC end a cycle with any motion code)",
      P + "N2 G81 X10 Y10 Z-5 R2 F100\nN3 G01 X20\n" + E,
      P + "N2 G81 X10 Y10 Z-5 R2 F100\nN3 G80\nN4 G01 X20\n" + E)
# -- profile limits -----------------------------------------------------------------------------
_rule("TG601", "error", "profile", "axis travel outside the machine's limits: a machine position "
      "(work position + the profile's work offset, where it gives them; or G53) outside the "
      "travel, said where each excursion starts; or a span of the program wider than the travel",
      P + "N2 G00 X-450\nN3 X600\nN4 G53 Z200\n" + E, P + "N2 G00 X-450\nN3 X400\nN4 G53 Z0\n" + E)
_rule("TG602", "error", "profile", "feed rate above the machine's maximum",
      P + "N2 G01 X1 F1000\n" + E, P + "N2 G01 X1 F900\n" + E)
_rule("TG603", "error", "profile", "spindle speed above the machine's maximum",
      P + "N2 S7000 M03\n" + E, P + "N2 S5000 M03\n" + E)
_rule("TG604", "error", "profile", "tool number outside the machine's range",
      P + "N2 T120\n" + E, P + "N2 T12\n" + E)
# -- tape ---------------------------------------------------------------------------------------
_rule("TG701", "error", "Annex A", "tape parity error (character with the wrong parity)",
      "", "")
_rule("TG702", "error", "Annex A", "character the tape code does not have", "", "")
_rule("TG703", "info", "profile", "TV check: blocks of an odd number of characters, which the "
      "sender pads (said once per file, with the count)",
      "%\nN1 G21\nN2 X1\nN3 M30\n%\n", "%\nN1 G21\nN2 X10\nN3 M30\n%\n", "fanuc-mill")


def markdown() -> str:
    """docs/rules.md, generated from the registry."""
    lines = [
        "# Check rules",
        "",
        "Generated from `postproc/rules.py` by `python -m postproc.rules > docs/rules.md`; a test",
        "fails when this file and the registry differ. Every rule's example programs are run by",
        "the test suite: the first must trigger the rule, the second must be quiet.",
        "",
        "Severities: **error** (the program will not run as meant), **warning** (it may run, but",
        "not on every control, or not as the standard says), **info** (worth knowing).",
        "`tapegate check --select` / `--ignore` take these IDs or prefixes (`TG4`).",
        "",
        "| ID | severity | clause | rule |",
        "|---|---|---|---|",
    ]
    for r in RULES.values():
        lines.append(f"| {r.id} | {r.severity} | {r.clause} | {r.title} |")
    lines.append("")
    for r in RULES.values():
        lines += [f"## {r.id}: {r.title}", "",
                  f"Severity {r.severity}; clause {r.clause}; example profile `{r.profile}`.", ""]
        if r.bad:
            lines += ["Triggers:", "", "```", r.bad.rstrip("\n"), "```", "", "Quiet:", "",
                      "```", r.good.rstrip("\n"), "```", ""]
        else:
            lines += ["Found while decoding a tape image (ISO even parity or EIA odd parity); "
                      "examples are binary and live in the tests.", ""]
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    print(markdown(), end="")
