"""The rule registry: every check of ``tapegate check`` with its ID, severity, clause and examples.

The rules themselves are the core's (``crates/core/src/rules.rs``, one Rust enum): ID, severity,
clause, title, family, and whether a rule means a block could not be read. This module reads
them from the core and adds to each, by ID, a program that triggers it (``bad``) and one that is
quiet (``good``), both under the profile named by ``profile``. The test suite runs every pair
and fails when a rule lacks its examples or an example names no rule; ``docs/rules.md`` is
generated from this registry (``python -m postproc.rules > docs/rules.md``), so the catalogue, the
code and the tests cannot drift apart.
"""

from __future__ import annotations

from formats import _core
from formats.records import FrozenRecord, init_fields, record

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import Literal

    Severity = Literal["error", "warning", "info"]

SEVERITY_RANK = {"info": 0, "warning": 1, "error": 2}
# the core's severity names as the type checker knows them (an unknown one: a KeyError)
_SEVERITIES: dict[str, Severity] = {"error": "error", "warning": "warning", "info": "info"}


@record
class Rule(FrozenRecord):
    """A check rule of the registry: its ID, severity, clause and title."""

    id: str
    severity: Severity
    clause: str
    title: str
    bad: str
    good: str
    profile: str = "iso-mill"
    family: str = ""  # the checker's module: structure, words, formats, codes, motion, ...
    name: str = ""  # the core's variant (``CharacterOutsideSet``)
    reading: bool = False  # a finding of it means a block (or the tape) could not be read

    def __init__(self, id: str, severity: Severity, clause: str, title: str, bad: str, good: str,
                 profile: str = "iso-mill", family: str = "", name: str = "",
                 reading: bool = False) -> None:
        init_fields(self, id, severity, clause, title, bad, good, profile, family, name, reading)


# The core's registry, in the catalogue's order: name, ID, severity, clause, title, family and
# whether the rule is a reading error.
CORE_RULES = _core.rules()
# Each rule's example programs, by ID: (bad, good, profile).
EXAMPLES: dict[str, tuple[str, str, str]] = {}


def _example(id: str, bad: str, good: str, profile: str = "iso-mill") -> None:
    assert id not in EXAMPLES, id
    EXAMPLES[id] = (bad, good, profile)


def rule_id(name: str) -> str:
    """The ID of the core's rule ``name`` (``"TapeParity"`` -> ``"TG701"``); an unknown name
    fails where the module naming it is imported."""
    return _core.rule_id(name)


P = "%\nN1 G71\nN2 G90\nN3 G17\n"  # a correct start
E = "N99 M30\n%\n"  # a correct end

# -- characters and program structure (clause 4, Annex A) ---------------------------------------
_example("TG100", P + "N2 X\n" + E, P + "N2 X0\n" + E)
_example("TG101", P + "N2 X1 $\n" + E, P + "N2 X1\n" + E)
_example("TG102", P + "N2 x1\n" + E, P + "N2 X1\n" + E, "neutral")
# a line tapegate cannot read right after a GOTO, before the block it names: never run (a
# FANUC stores it and reads a block's form when it runs it)
_example("TG108", "%\nO1\nG21\nGOTO 10\n---------\nN10 G0 X1.\nM30\n%\n",
         "%\nO1\nG21\nGOTO 10\n(---------)\nN10 G0 X1.\nM30\n%\n", "fanuc-mill")
# a SINUMERIK program's definitions stand at its head (Job Planning, DEF)
_example("TG109",
         "N10 G0 X0\nN20 DEF REAL ABC=1\nN30 G0 X=ABC\nN40 M30\n",
         "N10 DEF REAL ABC=1\nN20 G0 X0\nN30 G0 X=ABC\nN40 M30\n",
         "sinumerik-840d")
_example("TG110", "N1 G71 G90\n" + E, P + E)
_example("TG111", "%N1 G71 G90\n" + E, P + E)
_example("TG112", "%BRACKET\nN1 G71\n" + E, "%(BRACKET)\nN1 G71\n" + E)
_example("TG113",
         "%\nN1 G21\nO1234\n" + E.replace("N99", "N99"),
         "%\nO1234\nN1 G21\n" + E,
         "fanuc-mill")
_example("TG114", P + "N2 X1\n%\n", P + "N2 X1\n" + E)
_example("TG115", P + "N2 M30\n", P + "N2 M30\n%\n")
_example("TG116", P + "N2 M30\nN3 X1\n%\n", P + "N2 M30\n%\n")
# a control family's: the control ends the program at M30 and never runs what follows
_example("TG106", "%\nO1\nG21 G90 G00 X0 Y0\nM30\n(ENABLE LOOKAHEAD)\nG05.1 Q1\n%\n",
         "%\nO1\nG21 G90 G00 X0 Y0\nG05.1 Q1\nM30\n%\n", "fanuc-mill")
# LinuxCNC never reads past its M2/M30 (rs274's driver stops there): the line is passed over
_example("TG117", "G21 G0 X1\nM2\nprint[done]\n", "G21 G0 X1\nM2\n(done)\n", "linuxcnc")
# a macro branch to a sequence number the program does not hold (FANUC alarm PS0128)
_example("TG118", "%\nO1\nG21\nGOTO 20\nN10 G0 X1.\nM30\n%\n",
         "%\nO1\nG21\nGOTO 10\nN10 G0 X1.\nM30\n%\n", "fanuc-mill")
# the same branch under an IF the known values make false: that pass does not search for it
_example("TG139", "%\nO1\nG21\n#1=0\nIF [#1 EQ 1] GOTO 20\nN10 G0 X1.\nM30\n%\n",
         "%\nO1\nG21\n#1=0\nIF [#1 EQ 1] GOTO 10\nN10 G0 X1.\nM30\n%\n", "fanuc-mill")
_example("TG119", "%\nO1\nG21\nG10 L50\nN1420 R15000\nG00 X10.\nM30\n%\n",
         "%\nO1\nG21\nG10 L50\nN1420 R15000\nG11\nG00 X10.\nM30\n%\n", "fanuc-mill")
# -- comments, skip, alignment ------------------------------------------------------------------
_example("TG120", P + "N2 X1 (OPEN\n" + E, P + "N2 X1 (CLOSED)\n" + E)
_example("TG121", P + "N2 X1 (A (B) C)\n" + E, P + "N2 X1 (A B C)\n" + E)
_example("TG122", P + "N2 X1 (50% FEED)\n" + E, P + "N2 X1 (HALF FEED)\n" + E)
_example("TG123", P + "N2 / X1\n" + E, P + "/N2 X1\n" + E)
_example("TG124", "%\n:1 G71 G90\n" + E, "%\nN1 G71 G90\n" + E, "pm322-eia")
_example("TG125", P + "N2 X1 :3\n" + E, P + ":3 X1\n" + E)
_example("TG126",
         "%\nO1\nG21 G90\n(T1 D10 FLAT - 21:09)\nM30\n%\n",
         "%\nO1\nG21 G90\n(T1 D10 FLAT - 21H09)\nM30\n%\n",
         "fanuc-mill")
_example("TG127",
         "%\nO1\nG21 G90\n(BORE 25\u00b0 CHAMFER)\nM30\n%\n",
         "%\nO1\nG21 G90\n(BORE 25 DEG CHAMFER)\nM30\n%\n",
         "fanuc-mill")
_example("TG135",
         "\ufeff%\nO1\nG21 G90\nG00 X1.\nM30\n%\n",
         "%\nO1\nG21 G90\nG00 X1.\nM30\n%\n",
         "fanuc-mill")
# a '(' inside a Fanuc comment whose two readings leave the same words: read once, a warning
_example("TG136",
         "%\nO1\nG21 G90\nG00 X1. (VNMG 332(1))\nM30\n%\n",
         "%\nO1\nG21 G90\nG00 X1. (VNMG 332-1)\nM30\n%\n",
         "fanuc-mill")
# a LinuxCNC subroutine file whose endsub names another label: called, rs274 returns there
_example("TG138", "o<t-4> sub\nG0 X3\no<t_4> endsub\n", "o<t-4> sub\nG0 X3\no<t-4> endsub\n",
         "linuxcnc")
# a LinuxCNC definition whose endsub stands in an `if` of its body left open: a call with the
# condition false reads to the end of the file
_example("TG142", "o<m> sub\no100 if [#<_x>]\nG0 X1\no<m> endsub\nM2\n",
         "o<m> sub\no100 if [#<_x>]\nG0 X1\no100 endif\no<m> endsub\nM2\n", "linuxcnc")
_example("TG128",
         "%\nO1\nG21 G90\nG00 X1. /M08\nM30\n%\n",
         "%\nO1\nG21 G90\n/G00 X1. M08\nM30\n%\n",
         "fanuc-mill")
# a FANUC skips the text from the first % to the next LF (B-63524EN/01): a title there, or the
# program number, is not read
# a Haas or Okuma: ISO 6983-1 refuses the text, no source says the control alarms on it
_example("TG137", "%PART 7\nO1\nG20 G90\nM30\n%\n", "%(PART 7)\nO1\nG20 G90\nM30\n%\n",
         "haas-mill")
_example("TG129",
         "% PART A REV 2\nO1\nG21 G90\nM30\n%\n",
         "%\nO1 (PART A REV 2)\nG21 G90\nM30\n%\n",
         "fanuc-mill")
# -- words: order, repetition, formats (clauses 5, 6) -------------------------------------------
_example("TG130", P + "N2 X1 G01 F100\n" + E, P + "N2 G01 X1 F100\n" + E)
_example("TG131", P + "N2 G01 X1 X2 F100\n" + E, P + "N2 G01 X2 F100\n" + E)
_example("TG132", P + "N2 M03 M08\n" + E, P + "N2 M03\nN3 M08\n" + E)
_example("TG133", P + "N2 G00 G90 X1\n" + E, P + "N2 G00 X1\n" + E)
_example("TG134", P + "N2 G01 W5. F100\n" + E, P + "N2 G01 Z5. F100\n" + E)
_example("TG140",
         "%\nO1000\nG21 G90 G00 X0 Y0\nIF [#1 GT 0] GOTO 20\nN20 G01 X1 F100\nM30\n%\n",
         "%\nO1000\nG21 G90 G00 X0 Y0\nG01 X1 F100\nM30\n%\n",
         "fanuc-mill")
_example("TG141",
         "%\nO1000\n#101 = 200\nG21 G90 G01 X1 F[#101*2]\nM30\n%\n",
         "%\nO1000\nG21 G90 G01 X1 F200.\nM30\n%\n",
         "fanuc-mill")
_example("TG201", P + "N2 G01 X12.5 F100\nN3 Y12500\n" + E, P + "N2 G01 X12.5 F100\nN3 Y12.5\n" + E)
_example("TG202",
         "%\nN001 G01 X12.5\n" + E.replace("N99", "N099"),
         "%\nN001 G01 X0125\n" +
      E.replace("N99", "N099"),
         "pm322-eia")
_example("TG203", P + "N2 G01 X1.23456 F100\n" + E, P + "N2 G01 X1.235 F100\n" + E)
_example("TG204", P + "N2 G01 X1 F-100\n" + E, P + "N2 G01 X1 F100\n" + E)
_example("TG205", P + "N2 G01 X123456 F100\n" + E, P + "N2 G01 X12345 F100\n" + E)
_example("TG206", P + "N2 X12=5\n" + E, P + "N2 X2=5\nN3 R11 = 22.2\n" + E)
_example("TG208",
         "N10 G71 G90 G1 X1.23456 F100\nN20 M30\n",
         "N10 G71 G90 G1 X1.235 F100\nN20 M30\n",
         "sinumerik-840d")
_example("TG209",
         "%\nO1\nG21 G90 G00 X0\n#5021 = 10.\nM30\n%\n",
         "%\nO1\nG21 G90 G00 X0\n#100 = #5021\nM30\n%\n",
         "fanuc-mill")
_example("TG211",
         "%\nO1\nG20 G90 G00 X0\n#5021 = 1.\nM30\n%\n",
         "%\nO1\nG20 G90 G00 X0\n#100 = #5021\nM30\n%\n",
         "haas-mill")
_example("TG212",
         "%\nO1\nG20 G90 G00 X0\n#100 = #30003.078\nM30\n%\n",
         "%\nO1\nG20 G90 G00 X0\n#100 = #30003\nM30\n%\n",
         "haas-mill")
_example("TG210",
         "%\nO1\nG21 G90 G00 X0\n#1 = 100\nIF [#2 GT 0] GOTO 10\n#1 = 5021\n"
         "N10 #[#1] = 10.\nM30\n%\n",
         "%\nO1\nG21 G90 G00 X0\n#1 = 100\nIF [#2 GT 0] GOTO 10\n#1 = 5021\n"
         "N10 #1 = 100\n#[#1] = 10.\nM30\n%\n",
         "fanuc-mill")
_example("TG207", P + "N2 G1=1 X1=5 F100\n" + E, P + "N2 G01 X1=5 F100\n" + E)
# -- codes (Annex E) ----------------------------------------------------------------------------
_example("TG301", P + "N2 G123\n" + E, P + "N2 G01 X1 F100\n" + E, "pm322-eia")
_example("TG302", P + "N2 M12\n" + E, P + "N2 M09\n" + E)
_example("TG303", P + "N2 G25\n" + E, P + "N2 G01 X1 F100\n" + E)
_example("TG304", P + "N2 G00 G01 X1 F100\n" + E, P + "N2 G01 X1 F100\n" + E)
# a FANUC's coolant on and off in one block: no source says the control alarms
_example("TG308", "%\nO1\nG21 G90 G00 X0 M08 M09\nM30\n%\n",
         "%\nO1\nG21 G90 G00 X0 M08\nM09\nM30\n%\n", "fanuc-mill")
_example("TG306",
         "G21 G90 G0 X0\nG130 X1\nM2\n",
         "G21 G90 G0 X0\nG1 X1 F100\nM2\n",
         "linuxcnc")
_example("TG307",
         "%\nO1\nG21 G90 G00 X0\nG12.7 X1.\nM30\n%\n",
         "%\nO1\nG21 G90 G00 X0\nG01 X1. F100.\nM30\n%\n",
         "fanuc-mill")
_example("TG305", P + "N2 M240\n" + E, P + "N2 M08\n" + E)
# -- motion and geometry (clauses 7, Annex E) ---------------------------------------------------
_example("TG401", P + "N2 G01 X10\n" + E, P + "N2 G01 X10 F100\n" + E)
_example("TG402", P + "N2 G93 G01 X10 F2\nN3 X20\n" + E, P + "N2 G93 G01 X10 F2\nN3 X20 F2\n" + E)
_example("TG403",
         P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I11 J0 F100\n" + E,
         P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_example("TG404",
         P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 K10 F100\n" + E,
         P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 F100\n" + E)
_example("TG405",
         P + "N2 G00 X0 Y0\nN3 G02 X0 Y0 I0 J0 F100\n" + E,
         P + "N2 G00 X0 Y0\nN3 G02 X0 Y0 I5 J0 F100\n" + E)
_example("TG406",
         P + "N2 G00 X0 Y0 Z0\nN3 G02 X20 Y0 I10 J0 Z-1 F100\n" + E,
         P + "N2 G00 X0 Y0 Z0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_example("TG407", P + "N2 G06 X10 Y5 F100\nN3 G01 X20\n" + E, P + "N2 G06 X10 Y5 I5 J0 F100\n" + E)
_example("TG408",
         P + "N2 G02 X20 Y0 I10 J0 F100\n" + E,
         P + "N2 G00 X0 Y0\nN3 G02 X20 Y0 I10 J0 F100\n" + E)
_example("TG409",
         "%\nN1 G90 G17\nN2 G00 X2000 Y0\nN3 G03 X-2000 Y0 I2000 J0 F100\nN99 M30\n%\n",
         "%\nN1 G90 G17\nN2 G00 X2000 Y0\nN3 G03 X0 Y2000 I2000 J0 F100\n"
      "N4 G03 X-2000 Y0 I0 J2000\nN99 M30\n%\n",
         "cm332-quadrant")
_example("TG411",
         "G21 G90 G17\nG01 X0 Y0 Z5 F100\nG81 X1 Y1 Z-1 R1\nG80\nX2\nM2\n",
         "G21 G90 G17\nG01 X0 Y0 Z5 F100\nG81 X1 Y1 Z-1 R1\nG80\nG01 X2\nM2\n",
         "linuxcnc")
_example("TG412",
         "G21 G90 G17\nG00 X0 Y0 Z5\nG01 Z-1 F100\nG02 X10 Y0 R5\nG53 Z0\nM2\n",
         "G21 G90 G17\nG00 X0 Y0 Z5\nG01 Z-1 F100\nG02 X10 Y0 R5\nG53 G0 Z0\nM2\n",
         "linuxcnc")
# a lathe's G28 through the part zero (Haas G28: "moves to X0 Y0 Z0 in the current work
# coordinate system then to machine zero")
_example("TG418", "%\nO1\nG21 G99\nG0 X50. Z2.\nG28 X0 Z0\nM30\n%\n",
         "%\nO1\nG21 G99\nG0 X50. Z2.\nG28 U0 W0\nM30\n%\n", "fanuc-lathe")
_example("TG410",
         "%\nO1\nG21 G90 G17 G00 X0 Y0\nG02 X20. Y0 R5. F100.\nM30\n%\n",
         "%\nO1\nG21 G90 G17 G00 X0 Y0\nG02 X20. Y0 R10. F100.\nM30\n%\n",
         "fanuc-mill")
# -- compensation, threads, speed, dwell, cycles (clauses 10-13, Annex E) ------------------------
_example("TG501",
         P + "N2 G00 X0 Y0\nN3 G41 G02 X20 Y0 I10 J0 F100 D1\n" + E,
         P + "N2 G41 G01 X0 Y0 F100 D1\nN3 G02 X20 Y0 I10 J0\n" + E)
_example("TG502",
         P + "N2 G41 G01 X0 F100 D1\nN3 D2\n" + E,
         P + "N2 G41 G01 X0 F100 D1\nN3 G40 G01 X5\nN4 D2\n" + E)
# (a SINUMERIK's D of an R parameter the checker does not know: $P_TOOLNO, the active tool's
# number, is the control's; known to be 2, it is a D change, allowed under compensation)
_example("TG503",
         "G71 G90 G17 G0 X0 Y0 T1 D1\nM6\nR1=$P_TOOLNO\nG41 G1 X10 Y0 F100\nD=R1 X20\n"
         "G40 X60\nM30\n",
         "G71 G90 G17 G0 X0 Y0 T1 D1\nM6\nR1=2\nG41 G1 X10 Y0 F100\nD=R1 X20\n"
         "G40 X60\nM30\n",
         "sinumerik-840d")
_example("TG511", P + "N2 G33 Z-20 K1.5 F100\n" + E, P + "N2 G33 Z-20 K1.5\n" + E, "iso-lathe")
_example("TG512", P + "N2 G33 Z-20 K-1.5\n" + E, P + "N2 G33 Z-20 K1.5\n" + E, "iso-lathe")
_example("TG513", P + "N2 G34 Z-20 K1.5\n" + E, P + "N2 G34 Z-20 K1.5 F0.1\n" + E, "iso-lathe")
_example("TG521",
         P + "N2 G96 S200 M03\n" + E,
         P + "N2 G92 S3000\nN3 G96 S200 M03\n" + E,
         "iso-lathe")
_example("TG531", P + "N2 G04 X2 M03\n" + E, P + "N2 G04 X2\n" + E)
_example("TG532", P + "N2 G04\n" + E, P + "N2 G04 F2\n" + E)
_example("TG541",
         P + "N2 G81 X10 Y10 F100\n" + E,
         P + "N2 G81 X10 Y10 Z-5 R2 F100\n" + E,
         "fanuc-mill")
# (haas-mill: the manual marks R and Z optional, kept from an earlier cycle)
_example("TG543",
         "%\nO1\nG20 G90 G00 X0 Y0 Z1.\nG81 X1. Y1. Z-0.5 F10.\nG80\nM30\n%\n",
         "%\nO1\nG20 G90 G00 X0 Y0 Z1.\nG81 X1. Y1. Z-0.5 R0.1 F10.\nG80\nM30\n%\n",
         "haas-mill")
# (fanuc-mill: a repeat count that is no whole number of one or more)
_example("TG544",
         "%\nO1\nG21 G90 G00 X0 Y0 Z5.\nG81 X0 Y0 Z-5. R2. F100.\nG91 X10. K2.5\nG90 G80\nM30\n%\n",
         "%\nO1\nG21 G90 G00 X0 Y0 Z5.\nG81 X0 Y0 Z-5. R2. F100.\nG91 X10. K2\nG90 G80\nM30\n%\n",
         "fanuc-mill")
_example("TG542",
         P + "N2 G81 X10 Y10 Z-5 R2 F100\nN3 G01 X20\n" + E,
         P + "N2 G81 X10 Y10 Z-5 R2 F100\nN3 G80\nN4 G01 X20\n" + E)
# -- profile limits -----------------------------------------------------------------------------
_example("TG601",
         P + "N2 G00 X-450\nN3 X600\nN4 G53 Z200\n" + E,
         P + "N2 G00 X-450\nN3 X400\nN4 G53 Z0\n" + E)
# (on a profile whose F format holds more than its feed_max: iso-mill's F031 holds 999.9, its
# limit, and a word past its format is the format's error, TG205, its value unknown)
_example("TG602", P + "N2 G01 X1 F20000\n" + E, P + "N2 G01 X1 F9000\n" + E, "sinumerik-7e2")
_example("TG603", P + "N2 S7000 M03\n" + E, P + "N2 S5000 M03\n" + E)
_example("TG604", P + "N2 T120\n" + E, P + "N2 T12\n" + E)
# a FANUC clamps a cutting feed above its maximum (fanuc-mill's feed_max is 10000 mm/min)
_example("TG605",
         "%\nO1\nG21 G90 G01 X1. F20000.\nM30\n%\n",
         "%\nO1\nG21 G90 G01 X1. F9000.\nM30\n%\n",
         "fanuc-mill")
# a family's profile: the control limits the speed, or no source says it alarms
# (fanuc-mill's spindle_max is 10000); a clamp (G92 S15000) turns nothing
_example("TG606",
         "%\nO1\nG21 G90 G97 S12000 M03\nM30\n%\n",
         "%\nO1\nG21 G90 G92 S15000\nG97 S8000 M03\nM30\n%\n",
         "fanuc-mill")
# -- tape ---------------------------------------------------------------------------------------
_example("TG701", "", "")
_example("TG702", "", "")
_example("TG703", "%\nN1 G21\nN2 X1\nN3 M30\n%\n", "%\nN1 G21\nN2 X10\nN3 M30\n%\n", "fanuc-mill")


# RULES: each rule's record, by ID, in the catalogue's order; READING_RULES: the rules whose
# findings mean the input could not be read (characters, statements, indexes, tape codes):
# `tapegate plot` says a file of only these is no program to draw. Both are made when first
# asked for (the module's __getattr__): their 84 records were 2.2M instructions of the 92M a
# `check DIR -j 2` runs before its first thread, and a check asks for a rule's record only for
# --select and --ignore, SARIF and a tape image (docs/benchmarks.md, "the serial start-up
# without enum").
if TYPE_CHECKING:
    RULES: dict[str, Rule]
    READING_RULES: frozenset[str]


def _registry() -> dict[str, Rule]:
    """RULES and READING_RULES, made and kept in the module (two threads asking at once both
    make the same, and either is kept)."""
    rules = {
        id: Rule(id, _SEVERITIES[severity], clause, title, *EXAMPLES.get(id, ("", "", "")),
                 family=family, name=name, reading=reading)
        for name, id, severity, clause, title, family, reading in CORE_RULES
    }
    globals().update(RULES=rules,
                     READING_RULES=frozenset(r.id for r in rules.values() if r.reading))
    return rules


def _known() -> dict[str, Rule]:
    """RULES, made if not yet (for this module's own functions: a name of the module read
    inside it does not go through its __getattr__)."""
    rules: dict[str, Rule] | None = globals().get("RULES")
    return rules if rules is not None else _registry()


def __getattr__(name: str) -> object:
    """RULES and READING_RULES, made at the first ask (PEP 562)."""
    if name in ("RULES", "READING_RULES"):
        _registry()
        return globals()[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


TAPE_PARITY = rule_id("TapeParity")
TAPE_CHARACTER = rule_id("TapeCharacter")

# Where each error's severity comes from (issue 32: an error only for an alarm or what the
# manual forbids): the ISO 6983-1 clause, then for each family that the rule fires on (FANUC,
# Haas, SINUMERIK, Okuma, LinuxCNC) the control's alarm or the manual's rule, or "no source at
# hand" where none was found; docs/dialects.md names the manuals and alarm lists.
SOURCES = {
    "TG108": "FANUC and Haas store a program's text as it comes and read a block's form when "
             "they run it: a FANUC file always ends with % (Series 16i/18i-TB Operator's Manual "
             "B-63524EN/01, 8, \"File format\"), where the control stops reading it in (or at "
             "M02/M30/M99, by its parameter: CNC Concepts, \"Controlling when the machine stops "
             "reading a program\"); a Haas alarms at run time on a block's form (Mill Operator's "
             "Manual, NGC, 2017, 6.14, Editing). A line no run reaches is never read: taken so "
             "only right after a block that always leaves (M02, M30, M99, #3000= or GOTO, not "
             "under IF, not block-skipped, outside WHILE), with no block carrying an N between "
             "and none of its own (a jump, a computed GOTO #i, or another program's M99 P n may "
             "name any such block); every other line tapegate cannot read stays its reading "
             "error.",
    "TG114": "ISO 6983-1 Annex E (M02/M30 end a program). A program that returns is exempt: "
             "M99 (Fanuc/Haas Custom Macro B), M17 or RET (SINUMERIK Job Planning, "
             "subprograms), RTS (Okuma OSP user task), and a LinuxCNC subroutine file "
             "(o<name> sub ... o<name> endsub, optionally M2: LinuxCNC O codes, \"Calling "
             "Files\"). A LinuxCNC o<name> sub never closed by its endsub holds the rest of "
             "the file, its M2 too: said at the sub (rs274 2.9: \"File ended with no percent "
             "sign or program end\"). A subroutine file is read as a call runs it (rs274 -i "
             "with SUBROUTINE_PATH, issue 32, audit 37): an endsub inside a condition or loop "
             "of its body returns and does not end the definition, an endsub of another label "
             "returns too (TG138, a warning; interp_read.cc read_o compares the label only "
             "while it skips a definition), and lines before its sub are skipped by the call "
             "(TG117; interp_o_word.cc control_back_to): none of these is a TG114. An "
             "M2, M30 or (LinuxCNC, rs274 2.9 convert_stop) main-level M99 inside a "
             "condition whose value the checker does not know counts as an end: a numbered "
             "parameter the program never sets reads 0 in `rs274 -g` (`o1 if [#5 NE 0]` / "
             "`M99` / `o1 endif` is refused there, \"File ended with no percent sign or "
             "program end\"), its var file empty, but a machine's interpreter keeps "
             "#31-#5000 (global, volatile: cleared at start-up only) from the programs run "
             "before in the session and reads #5161-#5390 (persistent) from its var file, "
             "interp_parameter_def.hh, so the checker takes no parameter it never saw set as "
             "surely 0 (#1-#30 of the main level neither); a global never set "
             "(`#<_foo>`) is refused by rs274 2.9 (\"Named parameter #<_foo> not defined\"), "
             "no zero either (issue 32, lcnc79).",
    "TG142": "LinuxCNC rs274ngc (interp_o_word.cc convert_control_functions): a definition "
             "not called is skipped to the first o-word line of its label (skipping_o), so "
             "the file runs as a program past an endsub inside a block of the body; a call "
             "runs the body, and a block whose condition is false (a repeat's count below "
             "one) is skipped to the next o-word line of its label, which a block left open "
             "has none of: rs274 reads to the end of the file (rs274 2.9: \"File ended with "
             "no percent sign or program end\"; `rs274 -g`, issue 32, lcnc77b). A warning, "
             "the value being the call's; an error (TG114) where a call of the file that "
             "surely runs gives constant values that make it false.",
    "TG123": "ISO 6983-1 clause 4 (the block skip character before the sequence number). "
             "LinuxCNC's rs274 refuses a '/' anywhere but at the start of the line (\"Bad "
             "character '/' used\"); SINUMERIK writes the skip levels /0-/9 in front of the "
             "block only (Programming Manual Fundamentals). A Fanuc or Haas reads a '/' in the "
             "middle of a block (skipping from it to the end of the block with the switch on): "
             "TG128 there, not this error.",
    "TG137": "ISO 6983-1 clause 4 refuses words before the first end of block and an "
             "identification with letters outside parentheses (TG111, TG112). On a Haas no "
             "source at hand says what the control does with the text after the first %: the "
             "NGC mill manual says only that % begins and ends a program written in a text "
             "editor (Mill Operator's Manual, NGC, 2017, 5.3.1); no Okuma source at hand speaks "
             "of it either. Issue 32: what tapegate does not know is a warning, so a warning "
             "naming the maker, where a FANUC (which skips the text: TG129) and the strict ISO "
             "profiles (TG111/TG112, errors) differ.",
    "TG308": "Not an error (issue 32, severity by evidence): ISO 6983-1 Annex E wants one code "
             "of a modal group per block (TG304), but no FANUC, SINUMERIK or Okuma source at "
             "hand says the control alarms on two M codes of one group: the FANUC CNC hands the "
             "M codes it does not decode to the builder's PMC ladder (0i-F/30i-B Operator's "
             "Manuals, \"Auxiliary function\"), and which of the two the machine takes is the "
             "builder's; the SINUMERIK's NC decodes M0 M1 M2 M17 M30, the spindle's M3 M4 M5 "
             "M19 M70, M6 and M40-M45 itself and hands the other M functions to the PLC "
             "(Programming Manual Fundamentals, \"M functions\"), and no source says what it "
             "does with two of one group; the Okuma's List of M Codes (4203-E) gives each "
             "code's group, not what the control does with two. Searched and not found: "
             "FANUC's multiple M commands in a block (parameter 3404, M3B), the SINUMERIK's "
             "number of M functions a block, and the Okuma's (audit 50 B1). The modal state "
             "after the block is not known, so a restart after it is refused all the same "
             "(restart: TG304's reason). Not for two codes of a spindle's drive where one of them "
             "turns it, as the profile's meaning keys say (`spindle-cw`, `spindle-ccw`, "
             "`live-tool-cw`, ...: docs/profiles.md; M03 M04, M03 M05, M03 M19; the Okuma "
             "lathe's M-tool spindle, M12-M14 of its List of M Codes; the SINUMERIK's M3 M19, "
             "M3 M70, whose M3 M4 M5 M19 M70 are auxiliary function group 2 by default, 808D "
             "Parameter Manual AUXFU_PREDEF_GROUP; and its plain M3 (or M0=3) beside spindle "
             "1's M1=4, one spindle where the master spindle, machine data 20090 "
             "SPIND_DEF_MASTER_SPIND, is spindle 1, as on a one-spindle machine: 840D sl "
             "Function Manual Basic Functions H2; after the program's own SETMS(2) beside "
             "spindle 2's instead, and after a SETMS whose argument the checker cannot read "
             "beside any spindle's, the master not known: Programming Manual Fundamentals, "
             "\"Main spindle, master spindle\", review 56a F2): "
             "whether and which way the spindle turns for the cuts "
             "after the block is not known, and that decides how the tool meets the work, so "
             "the project's safety rule (refuse what decides how the machine moves, with the "
             "reason) keeps TG304 there (review 51 F9), its reason saying who decodes the "
             "codes (the FANUC's builder's ladder, the SINUMERIK's NC; review 55a F3); a stop "
             "beside an orientation or the axis mode (M05 M19, M5 M70) turns nothing and stays "
             "TG308 (review 55a F6). "
             "Not on a Haas (its NGC manual allows one M code a line: TG304) nor LinuxCNC "
             "(rs274 \"Two m codes used from same modal group\": TG304).",
    "TG129": "FANUC Series 16i/18i/160i/180i-TB Operator's Manual (B-63524EN/01), 8, memory "
             "card file format: \"In a read operation, data between the first % and the next "
             "LF is skipped\"; FANUC Fast Ethernet / Fast Data Server Operator's Manual "
             "(B-64014EN/03), 2.5: the leader section up to the first end of block may hold a "
             "title. A warning: the control reads on, without what stood there (an O number "
             "there is lost). Not on a Haas (no Haas source says so; TG137 there) nor the "
             "strict ISO profiles: TG111/TG112 there.",
    "TG130": "ISO 6983-1 clause 5.2 (the word order the standard recommends): judged on the "
             "ISO profiles (iso-mill, iso-lathe, pm322-eia, cm332-quadrant, sinumerik-7e2) "
             "and heidenhain-iso, whose source was not looked at for it. Not on the FANUC, "
             "Haas, Okuma, SINUMERIK and LinuxCNC profiles (audit 50, B4): their controls "
             "read a block's words in any order and their manuals write their own forms "
             "against 5.2's order (FANUC and Haas: G10 L2 P1 X0 Y0 Z0, M98 P2000 L3, Haas "
             "M97 P100, the lathe's G71 P10 Q20 U0.01 W0.005 D0.05 F0.01, G66 P9002 Z-5. R1.; "
             "LinuxCNC G code overview, \"Order of Execution\": the order of a line's items "
             "is not their position on it), so the note there was noise on the manual's own "
             "forms.",
    "TG131": "ISO 6983-1 5.2. In a Custom Macro B call (G65/G66/G66.1) argument "
             "specification II passes up to ten I J K sets (FANUC 0i-F/30i-B Operator's "
             "Manuals, \"Custom macro\"): the eleventh is the error.",
    "TG203": "ISO 6983-1 Annex C, and a profile whose control alarms on decimals past its "
             "resolution (checks.past_decimals = \"alarm\", the strict ISO profiles). Where the "
             "control rounds (SINUMERIK, MD 10200), rounds only a computed value (Fanuc, Haas) "
             "or no source says, TG208 instead.",
    "TG205": "ISO 6983-1 Annex C; FANUC alarm PS0003 (too many digits). A Haas sequence number "
             "past N99999 and an Okuma sequence name past N04 are TG208 (no alarm documented), "
             "and so is a Haas program number past O99999 (the NGC manual's format is Onnnnn, "
             "Mill Operator's Manual, NGC, 2017, 4.3.3 and 5.2.2; no Haas source says whether a "
             "longer one alarms, and the number moves nothing: issue 32, severity by evidence). A "
             "Fanuc O number takes eight digits (the 0i-F/30i-B 8-digit program number option; "
             "the profiles are the machine with its options). A word that names a block or a "
             "program in its code's block (G70-G73 P Q, M99 P, Haas M97 P: a sequence number; "
             "G65/G66 P, Haas M98 P: a program) has N's or O's format there (the profile's "
             "codes.*.words; FANUC \"Multiple repetitive cycle\", \"Subprogram\", \"Custom "
             "macro\").",
    "TG208": "A profile's checks.past_decimals and checks.past_sequence (what its control "
             "does with digits past the format: SINUMERIK rounds, MD 10200; a Fanuc and a Haas "
             "round a variable's or expression's value in an address to its increment, "
             "checks.past_decimals = \"round_computed\" (FANUC Custom Macro, \"ROUND\": G91 "
             "X-#1 with #1 = 1.2345 moves 1.235 mm; Haas Mill Operator's Manual 96-8000, "
             "\"Notes on functions\": #1 = 1.00333, G0 X[#1 + #1] moves to 2.0067), and no "
             "manual at hand says what a number written with more decimals does; a Haas "
             "sequence number past N99999 has no alarm in its manuals). A Haas program number past "
             "O99999: the NGC manual gives Onnnnn (Mill Operator's Manual, NGC, 2017, 4.3.3 and "
             "5.2.2) and no Haas source says what a longer one does; the number names the "
             "program and moves nothing, so the doubt is said and the program read on (issue "
             "32, severity by evidence; docs/dialects.md). convert still refuses a number its "
             "target's O format cannot hold (a digit overflow).",
    "TG206": "The control's parameter ranges: Custom Macro B up to #999999 (FANUC 30i-B), "
             "LinuxCNC #1-#5601 (rs274: \"Parameter number out of range\" for #5602), "
             "SINUMERIK R0-R99 by default (MD 28050, raised in the profile). FANUC: no "
             "variable #34-#99 (local #1-#33, common #100-#199 or #100-#999 with the option, "
             "#500-#999, system #1000 and up: 0i-F/30i-B Operator's Manuals, \"Custom macro\"); "
             "a number that names no variable is alarm PS0115, variable number out of range "
             "(FANUC alarm list). Not on a Haas (its NGC table not read for #34-#99).",
    "TG209": "FANUC 0i-F/30i-B Operator's Manuals, \"Custom macro\" (system variables: "
             "#1000-#1035 interface inputs, #3011/#3012 date and time, #4001- modal information, "
             "#5001- positions are read only) and alarm PS0116, write-protected variable. "
             "LinuxCNC 2.9's rs274: #5400-#5413 (tool) and #5420-#5428 (position) \"Parameter "
             "is readonly\", the predefined #<_x>, #<_current_tool>... \"Cannot assign to "
             "read-only parameter\". SINUMERIK List of System Variables (PGA): the actual "
             "values $AA_IM, $AA_IB, $AA_IBN, $AA_IEN, the software limits $AA_SOFTENDP/N, "
             "$AA_DTBW/DTBB/DTEW/DTEB, $AC_RETPOINT, $VA_IS are read-only in a part program. "
             "A profile's checks.read_only adds its control's own list: Haas Mill Operator's "
             "Manual, NGC (2017), 6.14.7 Macro Variables Table (the variables marked read "
             "only: inputs #11000-#11255 and #1080-#1098, #13000-#13063, timers #3020 #3023 "
             "#3025, #3026 tool in spindle, #3027 spindle RPM, #6198, ATM and tool data "
             "#8501-#8515, #8551-#8567), on haas-mill and haas-lathe.",
    "TG211": "Not an error (issue 32: what tapegate merely does not know is a warning). Custom "
             "Macro B holds the positions #5001-#5086, the previous block's codes #4001-#4126 "
             "and the date #3011/#3012 read only (FANUC PS0116, TG209 on a Fanuc); the Haas "
             "Mill Operator's Manual, NGC (2017), 6.14.7 Macro Variables Table, does not mark "
             "them read only, and no Haas source at hand says what a Haas does with the "
             "assignment. A program counting on the write is doubtful on a Haas, so named. The "
             "variables the NGC's table marks read only (the profile's checks.read_only) stay "
             "TG209.",
    "TG212": "Not an error (issue 32, severity by evidence: what tapegate merely does not "
             "know is a warning). The Haas Mill Operator's Manual, NGC (2017), 6.14.7 Macro "
             "Variables Table, gives #30000-#39999 as the parameters; Renishaw's Inspection "
             "Plus macros for the NGC read them with a decimal part (#30003.078, #30057.21), "
             "which no Haas source at hand documents (whether the decimals select an element "
             "of the parameter or one of its bits: docs/dialects.md). Either way the program "
             "reads a value tapegate does not know, as it does an unknown system variable: the "
             "block is read, and what depends on the value is unknown (TG141), so no geometry "
             "rule fires on it and a restart past it is refused. Setting such a variable "
             "(#30003.078 = 5) stays TG100: what it would change on the machine is not known. "
             "On a Fanuc a variable is numbered with a whole number (\"Custom macro\"): TG100.",
    "TG210": "As TG209, for a variable chosen by a value (#[#1] = ...): the value the checker "
             "knows comes from the blocks above, and a GOTO read before names the sequence "
             "number of this block or one above it, so the jump may arrive with another value "
             "(FANUC \"Custom macro\": GOTO n branches to sequence number n, variables keep "
             "their values). The control alarms (PS0116) only where the value it has then is a "
             "read-only variable: a warning naming the parameter and the sequence number.",
    "TG401": "ISO 6983-1 clause 7 (F for a feed move); the control alarms on a main "
             "program's feed move without F (FANUC PS0011, SINUMERIK 10860, rs274 \"Cannot do "
             "g1 with zero feed rate\"). A subprogram runs under its caller's feed: a program "
             "part that returns (M99, M17/RET, RTS), a SINUMERIK .SPF, what follows M02/M30 or a "
             "return, a jump target and a LinuxCNC sub start with the feed unknown. A block's "
             "M02/M30 resets the state once its words are done: its own move is judged with "
             "its own motion and feed (a G00 X1 M02 after a G01 is a rapid; a G01 X1 M30 "
             "with no F in force is a feed move without one where the reset motion is G00). "
             "F0 in force "
             "on a feed move (G1, G2, G3, a lathe's G90/G92/G94, a fixed cycle's holes) is an "
             "error on every profile, wherever it was written: FANUC PS0011 \"feed zero\" (30i "
             "specification A-91417: cutting with a feed rate of zero), SINUMERIK 14800 "
             "\"programmed path velocity less than or equal to zero\" (Function Manual Feeds "
             "V1, Alarms), rs274 \"Cannot do g1 with zero feed rate\" and \"Cannot make arc "
             "with zero feed rate\" (LinuxCNC's cycles: TG412); no Haas source at hand, the "
             "Custom Macro B family's PS0011 applies. The FANUC F1-digit feed option, where F0 "
             "selects the rapid rate, is not modelled.",
    "TG306": "The control alarms on a G code it does not have and nothing can make it valid: "
             "LinuxCNC's rs274 reads no G code from G100 on nor one with two decimals, even "
             "where a REMAP names it (\"G-code out of range\"; rs274 2.9); G0-G99.9 that its "
             "tables leave blank are open to a REMAP (LinuxCNC Remap manual, \"Currently "
             "unallocated G-codes\"), a TG307 warning, as \"Unknown g code used\" is for a "
             "configuration that does not remap it; "
             "checks.unknown_g = \"alarm\". M codes past M999 on LinuxCNC, which no "
             "configuration can remap (M200-M999 are open to a REMAP: LinuxCNC Remap "
             "manual, \"Currently unallocated M-codes\"; a TG307 warning, as rs274's "
             "\"M-code greater than 199\" is for a machine whose configuration does not remap "
             "it). The SINUMERIK 840D in "
             "Siemens mode has no G43/G44/G49 nor G80-G89 (Programming Manual Fundamentals, "
             "\"List of G functions\": ISO dialect mode's codes; it drills with CYCLE81-89).",
    "TG118": "FANUC/Haas: the block a word or GOTO names is searched by its sequence number "
             "(PS0063, PS0060, PS0128; Haas M97). SINUMERIK: GOTOF searches toward the end, "
             "GOTOB toward the start, GOTO both ways, and the control alarms where the label or "
             "block number is not there (Programming Manual Job Planning, \"Program jumps to "
             "jump markers\"); GOTOC does not alarm and is not checked.",
    "TG139": "FANUC Custom Macro B, \"Branch and repetition\": IF [expression] GOTO n "
             "branches to N n where the expression holds and runs the next block where it "
             "does not (the 0i operator's manual's section as a translation gives it; Haas "
             "Mill Operator's Manual, \"Macros\": \"otherwise processing continues with the "
             "next program line in sequence\"), so a pass with the condition false searches "
             "for no N n; one where it holds alarms (PS0128) as TG118 says (review 56b, F8).",
    "TG304": "ISO 6983-1 Annex E (one code of a modal group per block). Haas: two G codes of "
             "one group may not stand in one block (Mill Operator's Manual, NGC, 2017, "
             "\"Programming\" and \"G-codes\"; its M-code chapter allows one M code a line). "
             "FANUC: no page at hand says what a 0i or 30i does with two G codes of a group; "
             "the standard's error stands. Two M codes of a group on a FANUC, SINUMERIK or "
             "Okuma OSP are TG308, a warning, but for two codes of a spindle's drive where one "
             "turns it (M03 M05: refused, as how the tool meets the work is not known; "
             "TG308's source): no "
             "source at hand shows an alarm (searched: "
             "FANUC's multiple M commands in a block, parameter 3404 M3B, and SINUMERIK's M "
             "functions a block; no page found; for the Okuma, audit 50 B1, \"Okuma OSP M codes "
             "same group specified in the same block alarm\" and \"Okuma OSP programming "
             "manual maximum number of M codes in one block\": nothing of Okuma's; its List "
             "of M Codes, 4203-E, gives each code's group, not what the control does with "
             "two). The group of program stops (M00 M01 M02 M30, LinuxCNC's M60) by the same "
             "evidence (audit 50 B1: it was TG304 everywhere, naming no source; searched "
             "\"multiple M commands in a single block M3B parameter 3404 M00 M01 M02 M30 M98 "
             "M99 must not be specified together\": no FANUC or Haas page): TG304 on the ISO "
             "profiles (Annex E), on LinuxCNC (rs274 puts M0 M1 M2 M30 M60 in one modal group "
             "and refuses two) and on a Haas (one M code a line), TG308 on a FANUC, SINUMERIK "
             "or Okuma; a restart after such a block is refused either way, as which stop it "
             "makes is not known. LinuxCNC: rs274 \"Two m codes used from same modal "
             "group\". HEIDENHAIN ISO applies a G90 or G91 to the coordinates after it, so both "
             "may stand in one block "
             "(TNC 426/425 ISO manual: \"G02 G91 X+5 G90 Y-5\"): no TG304 there.",
    "TG307": "Not an error: a code the profile does not list may be the machine's. Fanuc: the "
             "CNC decodes M00 M01 M02 M30 M98 M99 M198 (and M codes its parameters make calls), "
             "the rest go to the machine builder's PMC ladder (0i-F/30i-B Operator's Manuals, "
             "\"Auxiliary function\"); a Haas is its own builder: its M codes are the NGC manual's "
             "list, which the profile holds, and the manual does not say what the control does "
             "with one it lacks (Mill Operator's Manual, NGC, 2017, \"M-codes\"), so the "
             "message says that, not FANUC's; SINUMERIK hands M functions it does not decode "
             "to the PLC (Programming Manual Fundamentals, \"M functions\"); LinuxCNC runs M "
             "codes its configuration remaps or provides (M100-M199 in USER_M_PATH), and G "
             "codes of G0-G99.9 its tables leave blank where the configuration remaps them (Remap "
             "manual, \"Currently unallocated G-codes\"; rs274 2.9 runs a remapped G6, G44, "
             "G60, G68.2). A G code the profile lacks takes the block's axis words as its own "
             "(a macro's arguments, a remap's words): where the axes stand after it is not "
             "known until a move sets them (issue 32, item 4), and no geometry rule judges "
             "the words. A decimal point in "
             "S or T beside such an M code on a FANUC (M165 P9811 Z0 S2.): alarm PS0007 where "
             "the M code is the builder's, while parameters 6080-6089 may make it a custom "
             "macro call (O9020-O9029; 0i-F/30i-B Operator's Manuals, \"Custom macro\"), whose "
             "arguments are real numbers; which it is, the machine's parameters say: a warning "
             "at the word, its value unknown (issue 32, severity by evidence; an M code of the "
             "table keeps TG202).",
    "TG501": "ISO 6983-1 / the control's compensation rules; LinuxCNC's rs274 refuses an arc as "
             "the move just after G40 (\"the move just after exiting cutter compensation mode "
             "must be straight\") and accepts one as the entry move.",
    "TG100": "ISO 6983-1 6.1. A block the reader cannot take apart is not checked further, so it "
             "stays an error on every family. FANUC: alarms PS0004 (address and number not in "
             "the word format; a macro statement out of its syntax), PS0005 (no data after an "
             "address) and PS0009 (improper NC address) (FANUC alarm list). Haas: an address "
             "written apart from its number alarms (Mill Operator's Manual, NGC, 2017, 6.14 "
             "Macros, Editing: `X 0`); no Haas alarm list at hand for the other forms. LinuxCNC: "
             "rs274 refuses the block (\"Bad character ... used\", \"Unknown word starting with "
             "...\", \"No characters found in reading real value\"; rs274ngc_return.hh). "
             "SINUMERIK, Okuma: no alarm list at hand for these forms (not read either way)."
             " Fanuc and Haas: words after a ';' in the same line (`G00 X1.; G01 X2.`). The "
             "';' is the end of block as the control shows it (FANUC B-64604EN/B-64484EN "
             "program format: ';' stands for the EOB code, LF in ISO code). A control or its "
             "input that takes it so runs the words after it as the next block, and one that "
             "does not alarms on the ';'. Neither reads them as a comment, so tapegate "
             "refuses them at the first word (and convert never carries them unconverted). A "
             "';' followed only by blanks or a ( ) comment is read as the end of the block.",
    "TG101": "ISO 6983-1 Annex A and the profile's extra characters. FANUC: alarm PS0001, TH "
             "error: a character read in with the wrong parity or outside the code (FANUC alarm "
             "list; a DNC line's non-ISO characters give it), and a memory card read drops "
             "lower-case letters and some special characters (16i/18i-TB, B-63524EN, \"File "
             "format\"). LinuxCNC: rs274 \"Bad character 'x' used\". Haas, SINUMERIK, Okuma: no "
             "source at hand says the control alarms on a character outside its set (its manuals "
             "list the characters it reads).",
    "TG111": "ISO 6983-1 clause 4 (an end of block before the first block). No control source at "
             "hand says a Fanuc, Haas or Okuma alarms on it: the FANUC sources say the reader "
             "skips what stands between the first % and the next end of line (16i/18i-TB, "
             "B-63524EN, \"File format\"; the 30i Fast Ethernet/Data Server manual, B-64014EN, "
             "2.5, shows `% TITLE ;`), so the words are not run (an O number there is lost): "
             "TG129, a warning, there. Haas, Okuma: no source says what the control does, so "
             "TG137, a warning (issue 32, severity by evidence). LinuxCNC: rs274 "
             "refuses a % line with words (\"Bad character '%' used\"; TG412 as well). Not "
             "checked on SINUMERIK and HEIDENHAIN, whose % line names the program.",
    "TG112": "ISO 6983-1 clause 4 (a program identification with letters in parentheses). As "
             "TG111: on a Fanuc the text after % up to the end of line is skipped (B-63524EN, "
             "\"File format\"; B-64014EN, 2.5): TG129 there; no source at hand says a Haas or "
             "Okuma alarms on it: TG137, a warning, there; LinuxCNC's rs274 "
             "refuses the line (\"Bad character '%' used\"). Not checked on SINUMERIK and "
             "HEIDENHAIN.",
    "TG109": "SINUMERIK Programming Manual \"Job Planning\" (828D, 07/2010, 1.1.5 \"Definition "
             "of user variables (DEF)\"): program-global and local user variables are defined "
             "in the definition section of the part program, each in a block of its own; the "
             "SINUMERIK 808D Programming and Operating Manual (Local User Data): the definition "
             "is made at the start of the program. A DEF after the first block of the program "
             "section is what the manual forbids. The alarm's number (14500, illegal DEF or "
             "PROC instruction, as a third-party 840D simulator raises it) was not found in "
             "Siemens's diagnostics manual at hand. DEFINE, EXTERN and PROC are not judged.",
    "TG116": "ISO 6983-1 Annex E (M02/M30 end the program). No control source at hand says a "
             "Fanuc, Haas, SINUMERIK or Okuma alarms on words after M02/M30: the control ends "
             "the program there and never runs them (a program that follows with its own O "
             "number is read as its own program, issue 32 item 4). LinuxCNC reads nothing after "
             "its M2/M30 (TG117, a warning, there instead). On the strict ISO profiles only: "
             "on a control family's profile TG106, a warning, instead.",
    "TG106": "No control source at hand says a Fanuc, Haas, SINUMERIK, Okuma or Heidenhain "
             "control alarms on words after M02/M30: it ends the program there, and never runs "
             "the words unless a jump (GOTO, M99 P, M97 P) reaches them; a program that follows "
             "with its own O number is read as its own program (issue 32, item 4). What the "
             "control does is not an alarm, and the words are kept as written: a warning (issue "
             "32, item 3; audit of held-out programs: a FANUC post's `(Enable lookahead)` and "
             "`G5.1 Q1` after M30, which never run).",
    "TG119": "FANUC 0i-F/30i-B Operator's Manuals, \"Programmable parameter input (G10 L50)\" "
             "and tool life data input (G10 L3): the mode's blocks hold only the data words "
             "until G11; the alarm's number was not at hand. Haas: its G10 takes L2, L10-L13 and "
             "L20 (Mill Operator's Manual, NGC, 2017, G10), so L50 and L3 are not a Haas form; "
             "no Haas alarm number at hand. Not checked on SINUMERIK, Okuma and LinuxCNC "
             "(LinuxCNC's rs274 refuses any G10 L50 with \"Line with G10 does not have L0, L1, "
             "L10, L11, L2, or L20\": TG412 there).",
    "TG120": "ISO 6983-1 clause 4 (a comment closes before the end of block). LinuxCNC: rs274 "
             "\"Unclosed comment found\". SINUMERIK: parentheses are call brackets, an "
             "unbalanced one a syntax error (Programming Manual Fundamentals; alarm number not "
             "at hand). FANUC, Haas, Okuma: no source at hand says whether the control alarms or "
             "reads the rest of the line as the comment (the message says so); read as ISO "
             "6983-1 has it.",
    "TG121": "ISO 6983-1 clause 4. LinuxCNC: rs274 \"Nested comment found\", for any '(' "
             "inside a comment, whether or not a second ')' follows. Okuma: no source "
             "at hand; read as ISO 6983-1 has it. FANUC, Haas: no source at hand says whether "
             "the control ends a comment at its first ')' or nests it to the matching one, so "
             "both readings are taken: where the first ')' leaves a letter, digit, '#', '%', "
             "':', a ';' (the end of block), a '/' (the block skip, TG128) or a ',' that would "
             "join a following C, R or A (a chamfer, corner or angle word) that the nested "
             "reading hides, they send different blocks and this error says what each sends; "
             "where nothing left can change what is sent or skipped, TG136. A ')' without its "
             "'(' is refused on every family. SINUMERIK: parentheses are call brackets "
             "(Programming Manual Fundamentals); an unbalanced one is not read.",
    "TG136": "FANUC, Haas: no source at hand settles whether a '(' inside a comment nests "
             "(searched: docs/dialects.md, \"A '(' inside a comment on a Fanuc or Haas\"). The "
             "first reading leaves only a stray ')' or marks that make no word, end no block and "
             "skip nothing (no letter, digit, '#', '%', ':', ';', '/', nor a ',' before C, R or "
             "A), so both send the same block: it is read once and the doubt is a warning, not "
             "an error. `send` prints it before the first byte. Not on ISO or Okuma (the comment "
             "ends at its first ')'; a stray ')' after it is TG121), LinuxCNC (TG121: rs274 "
             "refuses the comment) or SINUMERIK (parentheses are call brackets).",
    "TG122": "ISO 6983-1 clause 4 (% is the rewind stop). FANUC: % ends the input of a program "
             "(16i/18i-TB, B-63524EN, \"File format\": a file ends with %), so the blocks after "
             "the comment are not read in: the program is cut short, with no alarm number at "
             "hand. Haas, Okuma: no source at hand. ':' only where the profile says its tape "
             "reader stops there (checks.comment_colon = \"stop\"). Not checked on LinuxCNC "
             "(rs274 reads a % in a comment) and SINUMERIK.",
    "TG202": "ISO 6983-1 6.1 (a decimal point needs the format's DS). Every family profile has "
             "DS, so the rule fires only on the strict ISO and tape profiles. On a FANUC "
             "(fanuc-mill, fanuc-lathe) a decimal point in M, S or T (M3.0, S1000.0, T1.0) is "
             "alarm PS0007, illegal use of decimal point: a decimal point at an address that "
             "takes none (FANUC alarm list, as a public transcription of it gives it); S. K. "
             "Sinha's summary of Custom Macro B calls M3.0 S1000 and M03 S1000.0 illegal "
             "statements, M[3.0] being rounded, and names parameter 3451#2 by which a mill "
             "reads one decimal of S and rounds it. A macro call's arguments (G65 P9732 S1.) "
             "are real numbers: not judged; beside an M code the table lacks, which parameters "
             "6080-6089 may make a macro call, TG307 instead (a warning). P, H and D (whose "
             "meaning P takes from its code) and a Haas (no Haas source at hand) keep TG208.",
    "TG204": "ISO 6983-1 Annex C (the format's sign). FANUC: alarm PS0006, illegal use of minus "
             "sign (FANUC alarm list). LinuxCNC: rs274 \"Negative f word used\", \"Negative tool "
             "id\", \"Negative h word used\", \"Negative d word tool radius index used\" "
             "(rs274ngc_return.hh). Haas, SINUMERIK, Okuma: no alarm number at hand for a sign "
             "on F, S, T, H or D.",
    "TG301": "ISO 6983-1 Annex E (the code table). Fires only on the ISO profiles: on a family "
             "profile a code outside the table is TG306 (the control alarms: its source there) "
             "or TG307 (a warning naming it).",
    "TG303": "ISO 6983-1 Annex E (permanently unassigned codes). Fires only on the ISO profiles: "
             "a family profile reads such a code as outside its table (TG306 or TG307).",
    "TG402": "ISO 6983-1 Annex E (G93: F in each block). Haas: \"If in G93, an F value is used "
             "on each line\" (Mill Operator's Manual, NGC, 2017, G01 and G93). FANUC: with "
             "parameter 13450 set, a change of the feed mode (G93/G94/G95) clears the feed and a "
             "cutting block without F then alarms PS0011, feed zero (30i/31i/32i specification "
             "A-91417); the 0i-F's own G93 page was not at hand. LinuxCNC: rs274 \"F word "
             "missing with inverse time g1 move\". SINUMERIK, Okuma: no source at hand (Okuma "
             "alarm-B 2244 is an F out of its G93 range, not a missing one).",
    "TG403": "ISO 6983-1 7.3. FANUC: alarm PS0020, over tolerance of radius (parameter 3410 on "
             "the 0i, 2410 on the 30i; FANUC alarm list). SINUMERIK: alarm 14040, error in end "
             "point of circle (MD 21000 CIRCLE_ERROR_CONST, MD 21010 CIRCLE_ERROR_FACTOR; "
             "Diagnostics Manual). Okuma: alarm-B 2252 code 3 (the radius from I K and the "
             "distance from the centre to the end point differ by more than the tolerance, 20 "
             "µm as standard). LinuxCNC: rs274 \"Radius to end of arc differs from radius "
             "to start\". Haas: no Haas alarm list at hand; the profile's tolerance stands in "
             "for the machine's.",
    "TG404": "ISO 6983-1 7.3. FANUC: alarm PS0022, R or I,J,K command not found (FANUC alarm "
             "list). Okuma: alarm-B 2255 for L with I K or without X and Z, and alarm-B 2252 "
             "code 4 for I and K zero (whether an arc with none of I, K, L gives it, the page "
             "does not say). LinuxCNC: rs274 \"R i j k words all missing for arc\". Haas, "
             "SINUMERIK: no alarm number at hand.",
    "TG405": "ISO 6983-1 7.3. Okuma: alarm-B 2252 code 4 (I and K zero). LinuxCNC: rs274 "
             "\"Zero-radius arc\", for a radius under 0.00127 mm (0.00005 in). FANUC, Haas, "
             "SINUMERIK: no alarm number at hand; no arc of radius 0 exists, and the rule decides "
             "motion, so it stays an error. Only LinuxCNC has a threshold: on the other families "
             "the centre must be on the start or end point, and a radius of one least increment "
             "(0.001 mm) is an arc (held27, cifo-cnc `216.nc`).",
    "TG408": "ISO 6983-1 7.3. ISO profiles only: a program of a family profile starts where its "
             "caller or the operator left the tool (issue 32 item 4), so the rule does not fire "
             "there.",
    "TG409": "ISO 6983-1 7.3, quadrant-limited controls only (checks.ijk = \"quadrant\": the "
             "`cm332-quadrant` profile); no family profile reads I J K so.",
    "TG410": "ISO 6983-1 7.3 (no arc of that radius joins the points). Okuma: alarm-B 2252 code "
             "1 (L shorter than half the distance to the end point). LinuxCNC: rs274 \"Arc "
             "radius too small to reach end point\". FANUC, Haas, SINUMERIK: no alarm number at "
             "hand; the rule decides motion (no such arc exists), so it stays an error.",
    "TG411": "LinuxCNC only: rs274 \"Cannot use axis values without a g code that uses them\" "
             "(no motion mode at the start and after G80). The other families keep G00/G01 from "
             "reset and through G80, and the rule does not fire there.",
    "TG412": "LinuxCNC only: each case is the message of LinuxCNC 2.9's rs274 (interp_cycles.cc, "
             "interp_check.cc, interp_convert.cc, interp_o_word.cc; rs274ngc_return.hh), "
             "quoted in the rule's finding.",
    "TG502": "ISO 6983-1 clause 10. LinuxCNC: rs274 \"Cannot change tools with cutter radius "
             "compensation on\" at M6; a T word alone only selects the next tool there and rs274 "
             "takes it (no alarm source for a bare T: reported). Haas: a new D under "
             "compensation takes effect at the end of the move (Mill Operator's Manual, NGC, "
             "2017, Cutter Compensation): documented, no alarm (reported; left an error, since "
             "it decides the tool path). SINUMERIK: the offset number D can be changed in "
             "compensation mode, the new radius in effect from its block (840Di sl Programming "
             "Manual Fundamentals, 11/2006, 8.8, \"Changing the offset number D\"): a D alone "
             "is no finding there (a T still is: no Siemens page read for it). FANUC, Okuma: no "
             "alarm number at hand.",
    "TG503": "SINUMERIK: the offset number D can be changed in compensation mode, the new "
             "radius in effect from its block (840Di sl Programming Manual Fundamentals, "
             "11/2006, 8.8, \"Changing the offset number D\"); D0 is no offset, so under "
             "G41/G42 it switches the offset off (TG502, review 37). A D written by an R "
             "parameter or expression the checker evaluates (`R1=2` before `D=R1`) is judged "
             "by its value: no finding, or TG502 for 0. One it cannot evaluate (R1 set from "
             "a system variable, after a jump or call) may be either: a warning, no alarm "
             "source either way.",
    "TG511": "ISO 6983-1 clause 11 (G33: the lead in I/J/K, so no F). LinuxCNC: rs274 \"F word "
             "used with a g33/g33.1\". FANUC, Haas, SINUMERIK: no alarm number at hand for a "
             "lead word and F in one threading block (their threading words were not read for "
             "this rule). Okuma: not fired.",
    "TG512": "ISO 6983-1 clause 11. FANUC: alarm PS0006, illegal use of minus sign (FANUC alarm "
             "list). LinuxCNC: no alarm: rs274 runs `G33 K-1` (a spindle-synchronised move at -1 "
             "per revolution), so no source says it refuses it (reported; left an error, since "
             "it decides the motion). Haas, SINUMERIK: no alarm number at hand. Okuma: not "
             "fired.",
    "TG513": "ISO 6983-1 clause 11 (G34/G35: the initial lead and its rate). FANUC (the lathe's "
             "G34, motion group 01 of the 0i-TF list) and SINUMERIK: their G34 words were not "
             "read for this rule, and no alarm number is at hand for a missing one. LinuxCNC has "
             "no G34 (rs274: \"Unknown g code used\"), so the block is refused there for its "
             "code (the profile reads G34 from the ISO table: reported). Haas: no source at "
             "hand. Okuma: not fired.",
    "TG532": "ISO 6983-1 clause 13 (G04 with its time word). LinuxCNC: rs274 \"Dwell time "
             "missing with g4\". FANUC, Haas, SINUMERIK, Okuma: the dwell's time words are in "
             "their manuals (docs/dialects.md, \"Dwell\"); no alarm number at hand for a G04 "
             "without one.",
    "TG541": "ISO 6983-1 Annex E (a fixed cycle's depth and retract). LinuxCNC: rs274 \"R "
             "clearance plane unspecified in cycle\", \"Z value unspecified in xy plane canned "
             "cycle\" (rs274ngc_return.hh), only in the block that starts the cycle. FANUC, "
             "Okuma: no alarm number at hand. Haas: the manual marks R and Z optional, so there "
             "it is TG543, a warning. SINUMERIK: not fired (G81-G89 are TG306 in Siemens mode).",
    "TG543": "Haas Mill Operator's Manual, NGC, 2017, the canned cycles G73-G89 (e.g. \"G81 "
             "Drill Canned Cycle (Group 09)\"): R and Z are marked optional, and the R plane "
             "and depth stay in force for the cycles after it until G80 (\"Canned "
             "Cycles\"); no value is given for a cycle that never had them, and "
             "no alarm. So on the Haas profiles a missing R or Z is this warning, not TG541. "
             "FANUC, Okuma: no source at hand (TG541 stays an error).",
    "TG544": "FANUC 0i-MF operator's manual, \"Canned cycle\": K the number of repeats (a "
             "whole number; K0 stores the cycle's data and drills no hole); Haas mill "
             "operator's manual, G81-G89: \"L number of holes\". What a FANUC does with a K "
             "that is not whole, or a Haas with an L that is not whole or L0, no source at "
             "hand says: a warning naming what is not known. LinuxCNC: rs274 refuses both "
             "(\"Non integer value for integer\", \"Cannot do zero repeats of cycle\"): "
             "TG412. SINUMERIK, Okuma, HEIDENHAIN: not fired.",
    "TG601": "The profile's machine (its [limits] travel and work offsets). A control stops at "
             "its stored stroke limits with an overtravel alarm; the alarm numbers of the "
             "families were not at hand. The family profiles' travels are a typical machine's; "
             "`linuxcnc` sets none.",
    "TG602": "The profile's machine (feed_max). Haas: a feed an axis cannot reach alarms (\"max "
             "feedrate exceeded\": Mill Operator's Manual, NGC, 2017, G01). FANUC: not an alarm: "
             "a cutting feed above the parameter's upper limit is clamped to it (Power Mate i-D "
             "Descriptions, B-63172EN, 4.2.2 \"Cutting feed rate clamp\"; 0i-C Parameter Manual, "
             "B-64120EN, parameter 1422, the maximum cutting feedrate), a documented effect, so "
             "on the FANUC profiles it is TG605, a warning. SINUMERIK: no source at hand (left "
             "an error, reported). Okuma, LinuxCNC: their profiles set no feed_max.",
    "TG603": "The profile's machine (spindle_max), on the strict ISO profiles and on a user's "
             "profile file that sets spindle_max itself (its [limits]: its maximum is the "
             "user's machine, a chuck's rating perhaps; a file with no base sets all its "
             "limits). A file on a base whose own [limits] do not set spindle_max has the "
             "built-in base's sample maximum: TG606, as on the base. The S of the spindle "
             "speed clamp's code (G50 S on a "
             "lathe; G92 S on a FANUC mill and the ISO profiles, not on a Haas, Okuma or "
             "LinuxCNC mill, whose G92 only sets coordinates; a SINUMERIK's G26 S) is a limit, "
             "not a speed: never judged. On a built-in control family's profile, TG606 (a "
             "warning) instead; `linuxcnc` sets no spindle_max.",
    "TG606": "The profile's machine (spindle_max). SINUMERIK: the control limits an excessive "
             "spindle speed setpoint to the maximum in MD35100 SPIND_VELO_LIMIT (808D Function "
             "Manual, 01/2017, \"Maximum spindle speed\"; 840D Function Manual S1, 06/2019, "
             "18.8.4: setpoints limited to the gear stage's maximum): a documented effect, no "
             "alarm. FANUC, Haas, Okuma, Heidenhain: no source at hand says the control alarms "
             "on an S above the machine's maximum rather than limiting it, and the family "
             "profiles' maxima are a sample machine's (audit of held-out programs: a Robodrill's "
             "S24000 against fanuc-mill's 10000): what tapegate does not know is a warning "
             "(issue 32, item 3).",
    "TG604": "The profile's machine (tool_max). FANUC: alarm PS0043, illegal T-code command (a T "
             "code beyond the allowable range; FANUC alarm list). Haas: tool numbers run from 1 "
             "to 200 (Mill Operator's Manual, NGC, 2017, Advanced Tool Management), and a value "
             "outside an address's range is a range error alarm (6.14 Macros); the profile's 30 "
             "are a VF-2's pockets. LinuxCNC: rs274 refuses a tool not in the tool table "
             "(\"Requested tool N not found in the tool table\"); the profile sets no tool_max. "
             "SINUMERIK, Okuma: not fired.",
    "TG701": "ISO 6983-1 Annex A (even parity for ISO, odd for EIA). FANUC: alarm PS0001, TH "
             "error (a character with the wrong parity read in; FANUC alarm list). Haas, "
             "SINUMERIK, Okuma: no alarm number at hand for their serial input. LinuxCNC reads "
             "files, not tape: not used.",
    "TG702": "ISO 6983-1 Annex A (the tape code's characters). FANUC: alarm PS0001, TH error (a "
             "code the reader does not have; FANUC alarm list). Haas, SINUMERIK, Okuma: no alarm "
             "number at hand. LinuxCNC: not used (no tape).",
}
assert set(SOURCES) <= {r[1] for r in CORE_RULES}, set(SOURCES) - {r[1] for r in CORE_RULES}


def markdown() -> str:
    """docs/rules.md, generated from the registry."""
    registry = _known()
    lines = [
        "# Check rules",
        "",
        "Generated from the core's rule registry (`crates/core/src/rules.rs`) and the examples",
        "of `postproc/rules.py` by `python -m postproc.rules > docs/rules.md`; a test fails when",
        "this file and the registry differ. Every rule's example programs are run by the test",
        "suite: the first must trigger the rule, the second must be quiet.",
        "",
        "Severities: **error** (the program will not run as meant), **warning** (it may run, but",
        "not on every control, or not as the standard says), **info** (worth knowing).",
        "`tapegate check --select` / `--ignore` take these IDs or prefixes (`TG4`).",
        "",
        "| ID | severity | clause | rule |",
        "|---|---|---|---|",
    ]
    for r in registry.values():
        lines.append(f"| {r.id} | {r.severity} | {r.clause} | {r.title} |")
    lines.append("")
    lines += ["## Where the errors come from", "",
              "An error means the control raises an alarm or the program does what the manual "
              "forbids; what tapegate merely does not know is a warning or a note. Each error "
              "names its source: the ISO 6983-1 clause, and for each family it fires on "
              "(FANUC, Haas, SINUMERIK, Okuma, LinuxCNC) the control's alarm or the manual's "
              "rule; \"no source at hand\" marks a family for which none was found, where the "
              "rule stays an error only as ISO 6983-1's ([dialects.md](dialects.md) names the "
              "manuals and alarm lists).", ""]
    for r in registry.values():
        if r.id in SOURCES:
            lines.append(f"- **{r.id}** ({r.title}): {SOURCES[r.id]}")
    lines.append("")
    for r in registry.values():
        lines += [f"## {r.id}: {r.title}", "",
                  f"Severity {r.severity}; clause {r.clause}; example profile `{r.profile}`.", ""]
        if r.id in SOURCES:
            lines += [f"Source: {SOURCES[r.id]}", ""]
        if r.bad:
            lines += ["Triggers:", "", "```", r.bad.rstrip("\n"), "```", "", "Quiet:", "",
                      "```", r.good.rstrip("\n"), "```", ""]
        else:
            lines += ["Found while decoding a tape image (ISO even parity or EIA odd parity); "
                      "examples are binary and live in the tests.", ""]
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    print(markdown(), end="")
