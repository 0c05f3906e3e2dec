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
# LinuxCNC never reads past its M2/M30 (rs274's driver stops there): the line is passed over
_example("TG117", "G21 G0 X1\nM2\nprint[done]\n", "G21 G0 X1\nM2\n(done)\n", "linuxcnc")
# a macro branch to a sequence number the program does not hold (FANUC alarm PS0128)
_example("TG118", "%\nO1\nG21\nGOTO 20\nN10 G0 X1.\nM30\n%\n",
         "%\nO1\nG21\nGOTO 10\nN10 G0 X1.\nM30\n%\n", "fanuc-mill")
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
_example("TG128",
         "%\nO1\nG21 G90\nG00 X1. /M08\nM30\n%\n",
         "%\nO1\nG21 G90\n/G00 X1. M08\nM30\n%\n",
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
# -- tape ---------------------------------------------------------------------------------------
_example("TG701", "", "")
_example("TG702", "", "")
_example("TG703", "%\nN1 G21\nN2 X1\nN3 M30\n%\n", "%\nN1 G21\nN2 X10\nN3 M30\n%\n", "fanuc-mill")


RULES: dict[str, Rule] = {
    id: Rule(id, _SEVERITIES[severity], clause, title, *EXAMPLES.get(id, ("", "", "")),
             family=family, name=name, reading=reading)
    for name, id, severity, clause, title, family, reading in CORE_RULES
}
# The rules whose findings mean the input could not be read (characters, statements, indexes,
# tape codes): `tapegate plot` says a file of only these is no program to draw.
READING_RULES = frozenset(r.id for r in RULES.values() if r.reading)
TAPE_PARITY = rule_id("TapeParity")
TAPE_CHARACTER = rule_id("TapeCharacter")

# Where an error's severity comes from, for the rules whose error depends on what the control
# does (issue 32: an error only for an alarm or what the manual forbids; docs/dialects.md names
# the manuals). The other errors are ISO 6983-1's, by the clause in the table.
SOURCES = {
    "TG114": "ISO 6983-1 Annex E (M02/M30 end a program). A program that returns is exempt: "
             "M99 (Fanuc/Haas Custom Macro B), M17 or RET (SINUMERIK Job Planning, "
             "subprograms), RTS (Okuma OSP user task), and a LinuxCNC subroutine file "
             "(o<name> sub ... o<name> endsub, optionally M2: LinuxCNC O codes, \"Calling "
             "Files\"). A LinuxCNC o<name> sub never closed by its endsub holds the rest of "
             "the file, its M2 too: said at the sub (rs274 2.9: \"File ended with no percent "
             "sign or program end\").",
    "TG123": "ISO 6983-1 clause 4 (the block skip character before the sequence number). "
             "LinuxCNC's rs274 refuses a '/' anywhere but at the start of the line (\"Bad "
             "character '/' used\"); SINUMERIK writes the skip levels /0-/9 in front of the "
             "block only (Programming Manual Fundamentals). A Fanuc or Haas reads a '/' in the "
             "middle of a block (skipping from it to the end of the block with the switch on): "
             "TG128 there, not this error.",
    "TG131": "ISO 6983-1 5.2. In a Custom Macro B call (G65/G66/G66.1) argument "
             "specification II passes up to ten I J K sets (FANUC 0i-F/30i-B Operator's "
             "Manuals, \"Custom macro\"): the eleventh is the error.",
    "TG203": "ISO 6983-1 Annex C, and a profile whose control alarms on decimals past its "
             "resolution (checks.past_decimals = \"alarm\", the strict ISO profiles). Where the "
             "control rounds (SINUMERIK, MD 10200) or no source says, TG208 instead.",
    "TG205": "ISO 6983-1 Annex C; FANUC alarm PS0003 (too many digits). A Haas sequence "
             "number past N99999 and an Okuma sequence name past N04 are TG208 (no alarm "
             "documented). A Fanuc O number takes eight digits (the 0i-F/30i-B 8-digit program "
             "number option; the profiles are the machine with its options). A word that "
             "names a block or a program in its code's block (G70-G73 P Q, M99 P, Haas M97 P: "
             "a sequence number; G65/G66 P, Haas M98 P: a program) has N's or O's format there "
             "(the profile's codes.*.words; FANUC \"Multiple repetitive cycle\", "
             "\"Subprogram\", \"Custom macro\").",
    "TG206": "The control's parameter ranges: Custom Macro B up to #999999 (FANUC 30i-B), "
             "LinuxCNC #1-#5601 (rs274: \"Parameter number out of range\" for #5602), "
             "SINUMERIK R0-R99 by default (MD 28050, raised in the profile).",
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
             "return, a jump target and a LinuxCNC sub start with the feed unknown.",
    "TG306": "The control alarms on a G code it does not have and nothing can make it valid: "
             "LinuxCNC's rs274 (\"G-code out of range\", \"Unknown g code used\" for a "
             "decimal code such as G41.2); "
             "checks.unknown_g = \"alarm\". M codes past M199 on LinuxCNC (rs274: \"M-code "
             "greater than 199\"), which no configuration can remap. The SINUMERIK 840D in "
             "Siemens mode has no G43/G44/G49 nor G80-G89 (Programming Manual Fundamentals, "
             "\"List of G functions\": ISO dialect mode's codes; it drills with CYCLE81-89).",
    "TG118": "FANUC/Haas: the block a word or GOTO names is searched by its sequence number "
             "(PS0063, PS0060, PS0128; Haas M97). SINUMERIK: GOTOF searches toward the end, "
             "GOTOB toward the start, GOTO both ways, and the control alarms where the label or "
             "block number is not there (Programming Manual Job Planning, \"Program jumps to "
             "jump markers\"); GOTOC does not alarm and is not checked.",
    "TG304": "ISO 6983-1 Annex E (one code of a modal group per block). HEIDENHAIN ISO "
             "applies a G90 or G91 to the coordinates after it, so both may stand in one block "
             "(TNC 426/425 ISO manual: \"G02 G91 X+5 G90 Y-5\"): no TG304 there.",
    "TG307": "Not an error: a code the profile does not list may be the machine's. Fanuc: the "
             "CNC decodes M00 M01 M02 M30 M98 M99 M198 (and M codes its parameters make calls), "
             "the rest go to the machine builder's PMC ladder (0i-F/30i-B Operator's Manuals, "
             "\"Auxiliary function\"); SINUMERIK hands M functions it does not decode to the "
             "PLC (Programming Manual Fundamentals, \"M functions\"); LinuxCNC runs M codes its "
             "configuration remaps or provides (M100-M199 in USER_M_PATH).",
    "TG501": "ISO 6983-1 / the control's compensation rules; LinuxCNC's rs274 refuses an arc as "
             "the move just after G40 (\"the move just after exiting cutter compensation mode "
             "must be straight\") and accepts one as the entry move.",
}
assert set(SOURCES) <= set(RULES), set(SOURCES) - set(RULES)


def markdown() -> str:
    """docs/rules.md, generated from the registry."""
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
    for r in RULES.values():
        lines.append(f"| {r.id} | {r.severity} | {r.clause} | {r.title} |")
    lines.append("")
    lines += ["## Where the errors come from", "",
              "An error means the control raises an alarm or the program does what the manual "
              "forbids; what tapegate merely does not know is a warning or a note. The errors "
              "below depend on the control; the others are ISO 6983-1's, by their clause "
              "([dialects.md](dialects.md) names the manuals).", ""]
    for rule, source in SOURCES.items():
        lines.append(f"- **{rule}** ({RULES[rule].title}): {source}")
    lines.append("")
    for r in RULES.values():
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
