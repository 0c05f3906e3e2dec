//! The rule registry: the one list of the checker's rules (`docs/rules.md`).
//!
//! Every finding names a [`Rule`]; a call site names a variant, never an ID string, so a rule
//! that does not exist cannot be reported, and the ID, severity, clause, title and family of
//! each rule are written here once. Python reads the registry from the core
//! (`formats._core.rules()`): `postproc.rules` adds each rule's example programs by ID, and
//! `docs/rules.md`, SARIF's rule table, `--select`, `--ignore`, `--fail-on` and the CLI's
//! reading rules all come from it.

/// How bad a finding is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    Info,
    Warning,
    Error,
}

impl Severity {
    pub const fn name(self) -> &'static str {
        match self {
            Severity::Info => "info",
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }
}

/// The family a rule belongs to: one module of the checker each (`check::*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// Characters, program start and end, comments, skip and alignment.
    Structure,
    /// Words in a block: order, repetition, addresses, what the checker cannot follow.
    Words,
    /// Annex C word formats, decimal styles and indexes.
    Formats,
    /// G and M codes and their modal groups.
    Codes,
    /// Motion, feeds and arcs.
    Motion,
    /// Compensation, threads, speeds, dwells and fixed cycles.
    Tooling,
    /// The machine's limits: travel, feed, speed, tools.
    Limits,
    /// The link: tape parity and code, the TV check.
    Link,
}

impl Family {
    pub const fn name(self) -> &'static str {
        match self {
            Family::Structure => "structure",
            Family::Words => "words",
            Family::Formats => "formats",
            Family::Codes => "codes",
            Family::Motion => "motion",
            Family::Tooling => "tooling",
            Family::Limits => "limits",
            Family::Link => "link",
        }
    }
}

macro_rules! rules {
    ($($variant:ident = $id:literal, $severity:ident, $clause:literal, $family:ident,
       $reading:literal, $title:literal;)*) => {
        /// One rule of the checker.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Rule {
            $($variant,)*
        }

        impl Rule {
            /// Every rule, in the catalogue's order.
            pub const ALL: &'static [Rule] = &[$(Rule::$variant,)*];

            /// The stable ID users select, ignore and see in reports (`TG101`).
            pub const fn id(self) -> &'static str {
                match self {
                    $(Rule::$variant => $id,)*
                }
            }

            /// The variant's name, for the Python side's constants (`CharacterOutsideSet`).
            pub const fn name(self) -> &'static str {
                match self {
                    $(Rule::$variant => stringify!($variant),)*
                }
            }

            pub const fn severity(self) -> Severity {
                match self {
                    $(Rule::$variant => Severity::$severity,)*
                }
            }

            /// The clause of ISO 6983-1 (or "profile", "dialect") the rule comes from.
            pub const fn clause(self) -> &'static str {
                match self {
                    $(Rule::$variant => $clause,)*
                }
            }

            pub const fn title(self) -> &'static str {
                match self {
                    $(Rule::$variant => $title,)*
                }
            }

            pub const fn family(self) -> Family {
                match self {
                    $(Rule::$variant => Family::$family,)*
                }
            }

            /// The rule means a block (or the tape) could not be read at all: the CLI counts
            /// such findings as reading errors (exit code 65), not as check findings.
            pub const fn reading(self) -> bool {
                match self {
                    $(Rule::$variant => $reading,)*
                }
            }
        }
    };
}

rules! {
    Unreadable = "TG100", Error, "6.1", Structure, true,
        "block cannot be read (a word without a number, a stray digit...)";
    CharacterOutsideSet = "TG101", Error, "Annex A", Structure, true,
        "character outside Annex A and the profile's extra characters";
    NeverRun = "TG108", Warning, "dialect", Structure, false,
        "a line tapegate cannot read that no run reaches (FANUC, Haas): right after a block that always leaves (M02, M30, M99, a #3000 alarm outside IF, a GOTO outside IF), outside any WHILE loop, with no block carrying a sequence number between and none of its own; the control stores it and alarms only if it runs it; and a % glued to the block after the program's end, the end of record";
    LowerCaseAddress = "TG102", Warning, "Annex A", Structure, false,
        "lower-case address (the profile reads it as upper case)";
    NoProgramStart = "TG110", Warning, "4", Structure, false,
        "program does not begin with the program start character %";
    WordsOnPercentLine = "TG111", Error, "4", Structure, false,
        "words on the % line: an end of block must precede the first block";
    IdentificationNotInParentheses = "TG112", Error, "4", Structure, false,
        "program identification with letters not enclosed in parentheses";
    ProgramNumberNotFirst = "TG113", Warning, "4", Structure, false,
        "program number word not in the first block after %";
    NoProgramEnd = "TG114", Error, "Annex E", Structure, false,
        "program ends without M02 or M30";
    NoClosingPercent = "TG115", Warning, "4", Structure, false,
        "M02/M30 not followed by the closing %";
    WordsAfterEnd = "TG116", Error, "Annex E", Structure, false,
        "words after the end of program (M02/M30)";
    WordsAfterEndNotRun = "TG106", Warning, "dialect", Structure, false,
        "words after the end of program (M02/M30) on a control family's profile (Fanuc, Haas, SINUMERIK, Okuma, Heidenhain): the control ends the program there and never runs them unless a jump reaches them, and no source at hand says it alarms; kept as written, said once";
    NotRead = "TG117", Warning, "dialect", Structure, false,
        "lines the control never reads: LinuxCNC stops at an M2/M30 it runs, and at an M99 of the main program (2.9: the end of an endless program, interp_convert.cc convert_stop; only O-word lines, a subroutine's definition, and a FANUC-style `O300` ... `M99` program are read after it) and at the closing % of a file begun with %; passed over, kept as written, said once; and the lines before a LinuxCNC subroutine file's `o<name> sub`, which a call skips (said at the file's end, where the file is one: its sub closed and nothing but M2 after it)";
    TargetNotFound = "TG118", Error, "dialect", Structure, false,
        "the block a cycle, call or jump names is not in the program (G70-G73 P/Q, Haas M97 P, a main program's M99 P, GOTO n; a SINUMERIK's GOTOF/GOTOB/GOTO label not where it searches): the control alarms there (FANUC PS0063, PS0060, PS0128; SINUMERIK jump destination not found)";
    TargetNotFoundIfTrue = "TG139", Warning, "dialect", Structure, false,
        "a Custom Macro B `IF [..] GOTO n` whose condition is false with the values known where it is read, and no block N n in its program: that pass does not jump and searches for nothing (FANUC Custom Macro B: a condition not satisfied runs the next block), so TG118's error is not said; a pass where the condition holds (a loop, a jump back, other values) alarms there (FANUC PS0128). Where a word of the program may bring the run back to a block with other values -- a GOTO to a block already read, one whose number is worked out, or a jump by number of a code (`M99 P`, Haas `M97 P`, `M98 Q`), which arrives with the values where it stands -- the first pass's values settle nothing, and the missing target stays TG118's error";
    DataModeNotClosed = "TG119", Error, "dialect", Structure, false,
        "a word of the program inside FANUC's G10 L50 (parameter) or G10 L3 (tool life) data input mode, whose blocks hold only data words until its G11: the G11 is missing (or shares its block with the word), and the control alarms at the block (reported at the G10 that opened the mode); and G10 L50 or L3 on a Haas, which has no such mode (its G10 takes L2, L10-L13 and L20), as convert says of it";
    DefinitionAfterProgram = "TG109", Error, "dialect", Structure, false,
        "a SINUMERIK DEF after the first block of the program section: a program's definitions stand in the definition section at its head (Programming Manual Job Planning, definition of user variables)";
    CommentNotClosed = "TG120", Error, "4", Structure, true,
        "comment not closed before the end of block";
    NestedComment = "TG121", Error, "4", Structure, true,
        "nested or unbalanced comment brackets";
    StopCharacterInComment = "TG122", Error, "4", Structure, false,
        "comment containing '%' (a rewind stop), or ':' where the control's tape reader takes it for the alignment stop (checks.comment_colon = \"stop\")";
    SkipNotFirst = "TG123", Error, "4", Structure, true,
        "'/' block skip not immediately before the sequence number";
    AlignmentNotInClassification = "TG124", Warning, "4", Structure, false,
        "':' alignment used but the profile's classification has no ':'";
    AlignmentNotFirst = "TG125", Warning, "4", Structure, true,
        "alignment ':' not at the start of the block";
    ColonInComment = "TG126", Info, "4", Structure, false,
        "':' in comments where the control reads a comment as text (checks.comment_colon = \"text\"): harmless, said once per file with a count";
    OutsideAscii = "TG127", Warning, "Annex A", Structure, false,
        "text outside ASCII in a comment, a string or a LinuxCNC name (`#<name>`, `o<name>`; a Latin-1 degree sign, GBK or UTF-8 text): read, and said once per file with the character, its column and what it stands in, since a 7-bit tape code cannot carry it";
    SkipWithinBlock = "TG128", Warning, "dialect", Structure, false,
        "'/' block skip in the middle of a block (Fanuc, Haas): with the block-skip switch on, the control ignores the block from the slash to its end; checked as written, the switch off; and a '/' after a macro variable outside brackets (X#146/2), read as a division, which may be the block skip: a doubtful reading";
    LeaderSkipped = "TG129", Warning, "dialect", Structure, false,
        "text after the first % on a FANUC: the control skips everything from the first % to the next LF (FANUC 16i/18i-TB B-63524EN/01, 8, memory card file format; B-64014EN/03, 2.5, a title in the leader section), so a title there is not read, and an O number or a <NAME> there is lost; elsewhere TG111/TG112";
    LeaderUnknown = "TG137", Warning, "dialect", Structure, false,
        "text after the first % on a Haas or Okuma that ISO 6983-1 clause 4 refuses (words before the first end of block, TG111's case; an identification with letters outside parentheses, TG112's): no Haas or Okuma source at hand says whether the control reads it, skips it or alarms, so a warning, not an error";
    ByteOrderMark = "TG135", Warning, "dialect", Structure, false,
        "a UTF-8 byte order mark (EF BB BF) at the file's start, an editor's mark and no part of the program: on LinuxCNC an error instead (TG412: rs274ngc's read_text refuses it, \"Bad character '\\357' used\"); elsewhere the controls' manuals do not list it among the characters they read, and a 7-bit tape code cannot carry it (tapegate's DNC sender leaves it out)";
    NestedCommentRead = "TG136", Warning, "dialect", Structure, false,
        "a '(' inside a comment on a Fanuc or Haas whose two readings (the comment ends at its first ')', or it nests to the matching one) send the same block: the first leaves no word, ';', '/' or joining ',' (only a stray ')' or marks): read once, to the matching ')'; no source says which the control takes (where the readings differ, TG121); `send` shows it before sending";
    EndsubNamedOtherwise = "TG138", Warning, "dialect", Structure, false,
        "a LinuxCNC subroutine file's endsub that names another label than its sub (`o<init-tool-change> sub` ... `o<init_tool_change> endsub`): called, rs274 returns there all the same (it compares an endsub's label only while it skips a definition: interp_read.cc read_o), and the file needs no M2 if nothing else follows it; a program that defines the sub reads on past it to the endsub of the sub's own label (TG114 where there is none)";
    BlockOpenAtEndsub = "TG142", Warning, "dialect", Structure, false,
        "a LinuxCNC definition whose only endsub of its label stands inside an `if`, `while` or `repeat` of its body left open (`o<min> sub` / `o100 if [#1]` / `G0 X1` / `o<min> endsub` / `M2`): a call returns at the endsub where the condition holds, but where it is false (a count below one) rs274 skips to the next o-word line of the block's label, which the file does not have, and reads to its end (\"File ended with no percent sign or program end\"); not called, the definition is skipped to that endsub and the file runs as a program (interp_o_word.cc, skipping_o). A warning, the condition's value being the call's; an error (TG114) where a call of the file that surely runs gives the values that make it false (its arguments as #1 to #n, the other parameters of #1-#30 zero, interp_read.cc read_o), at that call's line also where it calls another definition whose body calls this one so, outside its own blocks (`o300 sub` / `o200 call [0]` / `o300 endsub` / `o300 call`), or where the block never runs and nothing follows the endsub; nothing for a `do`, which runs its lines before any test, or a condition surely true. A condition on a value the checker does not know stays a warning: a predefined global such as `#<_x>` is the machine's current position, which `rs274 -g` gives as 0 and a machine as where it stands (a global never set, `#<_foo>`, is no zero either: rs274 2.9 refuses it, \"Named parameter #<_foo> not defined\")";
    WordOrder = "TG130", Info, "5.2", Words, false,
        "word order: N, G, X Y Z U V W P Q R A B C, I J K after X Y Z, F, S, T D, M (clause 5.2 recommends it; controls read any order)";
    DimensionRepeated = "TG131", Error, "5.2", Words, false,
        "dimension word repeated in a block";
    WordRepeated = "TG132", Warning, "5.2", Words, false,
        "non-dimensional word repeated in a block";
    SeveralGWords = "TG133", Info, "Annex D", Words, false,
        "more than one G word in a block (interchangeability)";
    AddressNotClassified = "TG134", Warning, "Annex C", Words, false,
        "address not in the profile's detailed format classification";
    NotFollowed = "TG140", Info, "dialect", Words, false,
        "jump, loop or call the checker does not follow: the position, feed and speed are unknown after it; a SINUMERIK procedure that couples, reconfigures or sets axes: the position (said once per file); a Haas G268 feature coordinate system: the machine positions, compared with the travel through the profile's work offsets no more; a rotation, scaling or mirror image the checker cannot apply exactly (its angle or factor from parameters, a 3-D rotation, G268, an Okuma's G11, G62 and G69): the positions under it, left out of the travel's spans, and after its cancel an axis moved under it until an absolute position gives it (said once per file); a shift of the coordinates whose amount is not known (a G92 where the position is not known, a G10 of the work system in force, a G52 under G91 over a local shift, LinuxCNC's G52, a preset, a shift left at the program's end): the travel's span of each axis it names starts again there (said once per file)";
    NotEvaluated = "TG141", Info, "dialect", Words, false,
        "value the checker cannot evaluate (F[#101*2], X[#1+#2]; a variable set to a constant is known): set but unknown from there on (said once per file)";
    MixedDecimalStyles = "TG201", Warning, "6.1", Formats, false,
        "implicit and explicit decimal mixed in one program";
    UnexpectedDecimalPoint = "TG202", Error, "6.1", Formats, false,
        "decimal point where the profile has no explicit decimal sign (DS)";
    TooManyDigits = "TG203", Error, "Annex C", Formats, false,
        "more digits than the word format holds";
    UnexpectedSign = "TG204", Error, "Annex C", Formats, false,
        "sign on a word whose format has none";
    DigitOverflow = "TG205", Error, "Annex C", Formats, false,
        "value out of the word format's range (digit overflow); on a Haas, O999999 after a main program's end is said as the heading of the offsets the control saves with it (Setting 156, still refused: its G10 lines are not read), and a block there other than a plain G10 offset line ends that section, refused at its line and read";
    IndexOutOfRange = "TG206", Error, "6.2", Formats, true,
        "address index 0 or above the profile's maximum (parameters: the profile's number of parameters)";
    PastFormat = "TG208", Warning, "profile", Formats, false,
        "value past the word format where the control does not alarm: more decimals than its resolution (checks.past_decimals = \"round\", \"round_computed\" or \"unknown\"), a sequence number longer than its format (checks.past_sequence), a lathe thread's start angle Q written with a decimal point, in the G32 or G92 block or a block after it that repeats it (the manuals give it in 0.001 deg without one: Haas lathe G32/G76, FANUC 0i-TF G32, G92), a Haas program number past O's five digits (no Haas source says whether the NGC alarms; the number moves nothing, and the program is read as written)";
    ReadOnlyVariable = "TG209", Error, "profile", Formats, false,
        "assignment to a read-only system variable (Custom Macro B: an input, the date, modal information, a position, alarm PS0116; LinuxCNC: tool data, the position, predefined #<_names>; SINUMERIK: the actual values $AA_IM...; a profile's checks.read_only: a Haas NGC's inputs, timers...)";
    ReadOnlyVariableUndocumented = "TG211", Warning, "profile", Formats, false,
        "assignment to a variable Custom Macro B holds read only (the positions, the previous block's codes, the date) on a Haas, whose documentation does not mark it so nor say what the control does";
    ParameterElementRead = "TG212", Warning, "profile", Formats, false,
        "a Haas parameter variable read with a decimal part (#30003.078, #30057.21, as Renishaw's Inspection Plus macros for the NGC write them): the NGC manual gives #30000-#39999 as the parameters, no Haas source at hand says what the decimal part selects, so its value is unknown to tapegate, as an unknown system variable's is: read on, and no rule checks what depends on it (said once per variable and file); set with one, it stays TG100";
    ReadOnlyVariableUncertain = "TG210", Warning, "profile", Formats, false,
        "assignment to a variable chosen by a value (#[#1] = ...) that is read only for the value the checker knows, where a jump may arrive with another value (the block follows the sequence number a GOTO names)";
    IndexedG = "TG207", Warning, "6.2.2", Formats, false,
        "indexed G word: the standard does not intend G indexing (the profile may allow it)";
    CodeNotInTable = "TG301", Error, "Annex E", Codes, false,
        "G or M code not in the profile's code table";
    CodeUnassigned = "TG302", Warning, "Annex E", Codes, false,
        "code unassigned by the standard and not designated by the profile (individual use)";
    CodePermanentlyUnassigned = "TG303", Error, "Annex E", Codes, false,
        "permanently unassigned code";
    ModalGroupConflict = "TG304", Error, "Annex E", Codes, false,
        "two codes of one modal group in a block";
    MCodesOneGroup = "TG308", Warning, "dialect", Codes, false,
        "two M codes of one modal group in a block (M08 M09, two program stops M00 M30) on a FANUC, SINUMERIK or Okuma OSP, where no source at hand says the control alarms or which it takes; a warning, not TG304 (a restart after the block is refused all the same); two codes of a spindle's drive where one turns it (M03 M05, by the profile's meaning keys) stay TG304";
    CodeAlarms = "TG306", Error, "profile", Codes, false,
        "G or M code the control does not have and alarms on (checks.unknown_g / unknown_m = \"alarm\"; the default for G codes of a dialect family)";
    CodeNotInProfile = "TG307", Warning, "profile", Codes, false,
        "G or M code not in the profile's code table, on a control family that may run it (a Fanuc or Haas G code its parameters make a macro call, a machine builder's M code): named, not refused; and a decimal point in S or T beside such an M code on a FANUC, PS0007 unless parameters 6080-6089 make the M code a macro call (real arguments)";
    MClassMissing = "TG305", Warning, "Annex E", Codes, false,
        "M code of a class the profile does not have";
    NoFeedRate = "TG401", Error, "7", Motion, false,
        "feed motion without a feed rate in force, or at F0";
    InverseTimeWithoutFeed = "TG402", Error, "Annex E", Motion, false,
        "G93 inverse time motion without F in the block";
    ArcRadiusMismatch = "TG403", Error, "7.3", Motion, false,
        "arc: start and end radius differ by more than the tolerance";
    ArcCentreMissing = "TG404", Error, "7.3", Motion, false,
        "arc centre word missing or outside the selected plane";
    ArcZeroRadius = "TG405", Error, "7.3", Motion, false,
        "arc of zero radius";
    HelicalArc = "TG406", Info, "7.3", Motion, false,
        "helical arc (third axis moves with the arc)";
    ParabolaIncomplete = "TG407", Warning, "7.4", Motion, false,
        "G06 parabola without its tangent point (I J K) or second block";
    ArcWithoutStart = "TG408", Error, "7.3", Motion, false,
        "arc without a position to start from (no earlier X/Y/Z; ISO 6983-1 profiles: a dialect's program starts where its caller or the operator left the tool)";
    ArcCrossesQuadrant = "TG409", Error, "7.3", Motion, false,
        "arc crosses a quadrant boundary on a quadrant-limited control (checks.ijk = \"quadrant\": sign-less I J K, one quadrant per block)";
    NoMotionMode = "TG411", Error, "7", Motion, false,
        "axis words with no motion mode in force: LinuxCNC has none at the start and after G80 (the other controls keep G00/G01 from reset and through G80); beside G4 too, whose time is P";
    LinuxCncRefuses = "TG412", Error, "dialect", Motion, false,
        "a block LinuxCNC's interpreter refuses, with rs274ngc's message: G53 under G2/G3 (\"Must use g0 or g1 with g53\"), G53 in G91 (\"Cannot use g53 incremental\", check_g_codes); its canned-cycle refusals (interp_cycles.cc): the first G73/G83 block without Q, a Q of zero or less, the first G82/G86/G88/G89 without P, the first G87 without I J K, L0, R below the bottom (in force along the plane's cycle axis), no feed rate (or G93; every G93/G94/G95 zeroes it until the next F), cutter compensation on, G74 under M3, G84 under M4, G74/G84/G86-G88 with the spindle stopped (after a call the checker does not follow, the spindle direction and compensation are unknown until set again); T, H, L or G41/G42's D more than 0.0001 from a whole number (a cycle's `L2.5`: \"Non integer value for integer\", read_l); G10 with no L, or an L other than L0, L1, L2, L10, L11 and L20 (FANUC's G10 L50: \"Line with G10 does not have L0, L1, L10, L11, L2, or L20\", interp_check.cc); G76 (threading) without P or I J K, with J not above 0, K not above J, or under compensation; G70-G72 without Q, outside G18 or under compensation; G41.1/G42.1 without D, or with L outside G18; an E word no code of its block uses (\"E word with no G70, G76, M66, M67 or M68 to use it\": the block's motion is not G33, G33.1, G70 or G76 and it has no M66-M68; `X1e3` is X1 E3); a `%` line rs274 reads as a block (\"Bad character '%' used\": in a file not begun with `%`, or a closing `%` with a comment; not one after the endsub of a subroutine file named by its label, `tp.ngc` for `o<tp> sub`, which a call never reads, unless a line after it makes the file a program, past an M2 after it too; not one after an endsub of another label that returns from the file, its definition still open, which neither a call nor a run as a program reads; a file named otherwise is never called, only run as a program), a binary operation outside `[ ]` after a value in an assignment wherever the line may run, in an o-word condition, loop or subroutine body too (`#1=#2*3`: \"Bad character '*' used\", rs274ngc read_items; in an address's value, `X#2+1`, the reading's TG100, TG101 or TG123 refuses the operator first), or an indexed word of a letter with one (SINUMERIK's `R7=R5-R4`: \"Bad character '=' used\"), and a UTF-8 byte order mark at the file's start (\"Bad character '\\357' used\", rs274ngc read_text); the block's words against its codes (interp_check.cc check_g_codes, check_other_codes): G4 P-1 (\"Dwell time missing with g4\"), G4 with G2/G3, G10 L2/L20 with P outside 0-9 and L1/L10/L11 with P below 1 (no P is P-1), G10's P not whole, an H word with no G43/G43.2 in its block or G76 as its motion, a P word with no G4, G10, G64, no G2, G3, G5, G5.2, G70, G74, G76, G82, G84, G86, G88, G89 as its motion and no M19, M50-M53, M62-M66, M98 or user M code, an arc's P not whole or below 1, M19's P outside 0-2, an I, J, K or R word with a straight move or none (\"I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it\", \"R word with no g code that uses it\"; the motion is the block's code, or the mode in force where it moves, or G2/G3 in force for I J K alone), a Q word with no G5, G10, G64, G73, G76, G83, G70-G72, M19, M61, M66-M68 or user M code, an L word with no G10, G5.2, G76, canned cycle, compensation code, M66 or M98, a D word with no G41/G42 (or .1), G70-G72 or G96, a $ word with no M3-M5, M19, M51, S, G33, G33.1 or G76 (\"$ (spindle selection) word with no ... to use it\"), an A, B or C word in a canned cycle, M19's R outside 0-360, G96 without S, G33/G33.1 without K (a block with an M code rs274 lacks, a remap, is left alone; one with a G code it lacks is TG306's alone); G33, G33.1, G76 with the spindle stopped (interp_convert.cc convert_straight; M6 stops it, convert_tool_change); a code run under cutter radius compensation (interp_convert.cc, each function's first check: M6, M48-M53, M62-M68 under the compensation before the block, its M codes running first; a change of plane (G17, G18 or G19 other than the plane in force, \"Cannot change planes with cutter radius compensation on\"; G17.1-G19.1, whose plane the compensation then stops at: refused at the code where a compensated move may be held, else at the next G0/G1 move, \"BUG: Invalid plane for cutter compensation\", and any G17-G19 after it), G41/G42 in G19 or G17.1-G19.1 (\"Cutter radius compensation allowed only in XY, XZ planes\") or when on, then, under the compensation after the block's G40-G42, G43-G49, G54-G59.3, G61/G64, G98/G99, G10 L2/L20 of the active system, G52/G92, G28/G30, G28.1/G30.1, G53 and the splines G5/G5.1 (\"Cannot convert spline with cutter radius compensation\"): \"Cannot change tool offset with cutter radius compensation on\", \"Cannot wait for digital input with cutter radius compensation on\" ...); G5/G5.1 outside G17, in G18, G19 or G17.1-G19.1 (\"Splines must be in the XY plane\", convert_spline, after its feed checks: under G94 a feed rate of zero, \"Cannot make arc with zero feed rate\", under G93 a block without F, \"F word missing with inverse time arc move\", under G95 none) and G2/G3 in G17.1-G19.1 (\"Cannot do an arc in planes G17.1, G18.1, or G19.1\", convert_arc, before the arc's own checks; G5.2/G5.3 in any plane run; the plane is not known, and no plane refusal said, after a call, in a definition's body before it sets one, and after a condition or loop whose ways through leave different planes; a definition's plane is not the main program's below its endsub); a G1 or an arc under G95 with no spindle speed, S0 or none since the start (\"Cannot feed with zero spindle speed in feed per rev mode\", convert_straight, convert_arc); an arc with R and any of I J K (\"Mixed radius ijk format for arc\", convert_arc), an R arc with no word of its plane's axes (\"X and y words missing for arc in xy plane\", convert_arc), or, without compensation, one that ends where it starts (\"Current point same as end point of arc\", interp_arc.cc arc_data_r); a subroutine's body reading a local named parameter (not `#<_global>`) that no line of the body assigns before, where the file calls it: locals are per call level, the caller's is not seen (\"Named parameter #<zz> not defined\"); a subroutine definition the main program reaches after a call found it ahead (interp_o_word.cc control_save_offset: \"sub: o|100| found in illegal location\"), or a second time on a loop's second turn (a definition in the body of a `repeat [2]`, a `while` or `do` whose condition is known true at its end), a second definition of a subroutine (\"redefining sub\"), an if or repeat of a label the main program recorded before, or a while of one a keyword other than do recorded (\"duplicate O-word label\"), a closing o-word whose label, worked out as the line runs, the lines of its block (which surely ran) changed (\"undefined O-word label\"), a `break` or `continue` of a label recorded for an `if` or a `repeat` wherever rs274 reads it, running it or skipping to it (\"no matching while/do label\"), or of a subroutine's own label in its body (\"undefined O-word label\"); a call that surely runs of a subroutine whose only definition stands in a block known not to run, with none after the call (\"EOF in file seeking o-word\"); the lines of blocks known to run, nested in one another in any way, judged in the state the program left; no rule judges a line rs274 never runs (in the skip of a block known not to run, `o1 if [0]`, or after an M2 that surely runs, one in blocks known to run too); an endsub inside a condition or loop of the body of a file that opens with the definition and then runs as a program (rs274 ends the definition at it and refuses the o-word line closing the condition or loop: \"undefined O-word label\", and a second endsub: \"not in a subroutine definition\"; in a subroutine file, called, it is an early return); a bare O number (`O103`, after an N at most) inside a definition before the main program's end (\"Nested subroutine definition\": read_o takes it for the start of a FANUC-style program, refused while a subroutine is defined or called, whether the body runs or is skipped); an M98 after another word, a comment or a statement of its block (\"Unknown m code used: M98\": rs274ngc reads M98 where an O word stands, its block's first word after the N, interp_read.cc read_o), or with a word other than P and L after it, which rs274 refuses or does not run (`M98 P100 G1 X10. M8` calls and neither moves nor turns the coolant on)";
    ReturnThroughZero = "TG418", Warning, "dialect", Motion, false,
        "a Fanuc or Haas lathe's G28 X0 or Z0: the intermediate point is the work zero (X and Z absolute), the tool rapids there before it returns home (G28 U0 W0 returns from where it stands)";
    ArcRadiusTooShort = "TG410", Error, "7.3", Motion, false,
        "arc radius (R, Sinumerik CR=, Okuma lathe L) shorter than half the chord: no arc of that radius joins the points";
    CompensationOnArc = "TG501", Error, "10", Tooling, false,
        "cutter compensation introduced or removed in a circular block";
    ToolChangeInCompensation = "TG502", Error, "10", Tooling, false,
        "new T or D while cutter compensation is active (G40 first)";
    UnknownDInCompensation = "TG503", Warning, "10", Tooling, false,
        "SINUMERIK: a D whose value the checker does not know (`D=R1`, R1 not known there) while G41/G42 is active: a D change is allowed there, but D0 would switch the offset off under compensation (TG502 where the value is known to be 0)";
    LeadAndFeed = "TG511", Error, "11", Tooling, false,
        "G33 constant lead with both a lead word and F";
    SignedLead = "TG512", Error, "11", Tooling, false,
        "thread lead with an algebraic sign";
    VariableLeadIncomplete = "TG513", Error, "11", Tooling, false,
        "G34/G35 variable lead without its lead and rate words";
    SurfaceSpeedWithoutLimit = "TG521", Warning, "12", Tooling, false,
        "G96 constant surface speed without an earlier spindle speed limit in the control's own form: G92 S (ISO, Fanuc and Haas mills), G50 S (Fanuc, Haas and Okuma lathes), LIMS= or G26 S (SINUMERIK; its ISO mode's G92 S too), D in the G96 block (LinuxCNC)";
    DwellNotAlone = "TG531", Warning, "13", Tooling, false,
        "G04 dwell not alone in its block";
    DwellWithoutTime = "TG532", Error, "13", Tooling, false,
        "G04 dwell without the control's time word (LinuxCNC: P; SINUMERIK: F or S; Fanuc and Haas lathes: X, U or P; Fanuc and Haas mills: X or P; elsewhere X, P or F)";
    CycleIncomplete = "TG541", Error, "Annex E", Tooling, false,
        "fixed cycle without its depth (Z; X or U in a FANUC lathe's side cycles G87-G89) or retract (R) word (FANUC and Haas: kept from the cycle in force if it drills along the same axis; LinuxCNC: G73 and G74 too, and only in the block that starts the cycle: a block repeating it keeps them; Haas: TG543, a warning)";
    CycleWordsOptional = "TG543", Warning, "Annex E", Tooling, false,
        "fixed cycle without its depth (Z) or retract (R) word on a Haas, whose manual marks both optional (kept from an earlier cycle until G80) but gives no value for a cycle that never had them: the R plane or depth the control takes is not known";
    CycleRepeatCount = "TG544", Warning, "profile", Tooling, false,
        "canned cycle repeat count that is not a whole number of one or more (FANUC K, Haas L): FANUC K0 stores the cycle's data and drills no hole; what a FANUC does with K2.5, or a Haas with L2.5 or L0, no source at hand says; the plane's axes are not followed after it (LinuxCNC: TG412, rs274 refuses L2.5 and L0)";
    MotionInCycle = "TG542", Warning, "Annex E", Tooling, false,
        "motion code while a fixed cycle is active (G80 first; ISO only: Fanuc, Haas, Siemens and LinuxCNC end a cycle with any motion code)";
    TravelExceeded = "TG601", Error, "profile", Limits, false,
        "axis travel outside the machine's limits: a machine position (work position + the profile's work offset, where it gives them; or G53) outside the travel, said where each excursion starts; or a span of the program wider than the travel (under a rotation or scaling, its positions taken back to the coordinates before it)";
    FeedTooHigh = "TG602", Error, "profile", Limits, false,
        "feed rate above the machine's maximum";
    SpeedTooHigh = "TG603", Error, "profile", Limits, false,
        "spindle speed above the machine's maximum";
    ToolOutOfRange = "TG604", Error, "profile", Limits, false,
        "tool number outside the machine's range";
    FeedClamped = "TG605", Warning, "profile", Limits, false,
        "feed rate above the machine's maximum on a FANUC, which clamps a cutting feed to the maximum its parameters set rather than alarming: the cut runs slower than programmed";
    SpeedLimited = "TG606", Warning, "profile", Limits, false,
        "spindle speed above the machine's maximum on a built-in control family's profile (Fanuc, Haas, SINUMERIK, Okuma, Heidenhain), a sample machine of the family: a SINUMERIK limits the speed to its maximum, and no source at hand says the others alarm rather than limiting it: the spindle turns slower than programmed, or the profile's sample machine is not the user's";
    TapeParity = "TG701", Error, "Annex A", Link, true,
        "tape parity error (character with the wrong parity)";
    TapeCharacter = "TG702", Error, "Annex A", Link, true,
        "character the tape code does not have";
    OddBlockLength = "TG703", Info, "profile", Link, false,
        "TV check: blocks of an odd number of characters, which the sender pads (said once per file, with the count)";
}

impl Rule {
    /// The rule of an ID (`"TG101"`), if there is one.
    pub fn from_id(id: &str) -> Option<Rule> {
        Rule::ALL.iter().copied().find(|r| r.id() == id)
    }

    /// The position of the rule in [`Rule::ALL`]: an index into per-rule tables.
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether each finding of the rule is about one code or address, which its message names
    /// at its head ([`subject`]): the G and M code rules (`M160 is not in the profile's M code
    /// list`), an indexed G word and an address outside the classification (`address U is
    /// not ...`). A folded text report folds these per rule and per that name, so that each
    /// code is shown (stop 58: a second unknown M code was folded into the first's line).
    pub const fn about_a_code(self) -> bool {
        matches!(self.family(), Family::Codes)
            || matches!(self, Rule::AddressNotClassified | Rule::IndexedG)
    }
}

/// What a finding of a rule [`Rule::about_a_code`] names: its message up to the first `:` or
/// ` is ` (`M160`, `G12.1`, `address U`), the whole message where it has neither.
pub fn subject(message: &str) -> &str {
    // (one walk of the head's bytes: the two searches each walked to their end where the
    // message has no `:` or no ` is `)
    let bytes = message.as_bytes();
    let end = (0..bytes.len())
        .find(|&i| bytes[i] == b':' || bytes[i..].starts_with(b" is "))
        .unwrap_or(bytes.len());
    &message[..end]
}

/// Which rules a run reports: `--select` and `--ignore` (IDs or prefixes such as `TG4`),
/// resolved once into one flag per rule.
#[derive(Debug, Clone)]
pub struct Selection {
    on: Vec<bool>,
}

impl Selection {
    pub fn new(select: &[String], ignore: &[String]) -> Selection {
        let on = Rule::ALL
            .iter()
            .map(|rule| {
                let id = rule.id();
                (select.is_empty() || select.iter().any(|p| id.starts_with(p.as_str())))
                    && !ignore.iter().any(|p| id.starts_with(p.as_str()))
            })
            .collect();
        Selection { on }
    }

    /// Every rule reported.
    pub fn all() -> Selection {
        Selection {
            on: vec![true; Rule::ALL.len()],
        }
    }

    /// No rule reported: the walks that read a program for its state alone (restart).
    pub fn none() -> Selection {
        Selection {
            on: vec![false; Rule::ALL.len()],
        }
    }

    pub fn enabled(&self, rule: Rule) -> bool {
        self.on[rule.index()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_and_round_trip() {
        let mut ids: Vec<&str> = Rule::ALL.iter().map(|r| r.id()).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), Rule::ALL.len());
        for rule in Rule::ALL {
            assert_eq!(Rule::from_id(rule.id()), Some(*rule));
            assert_eq!(Rule::ALL[rule.index()], *rule);
        }
        assert_eq!(Rule::from_id("TG000"), None);
    }

    #[test]
    fn selection_by_prefix() {
        let s = Selection::new(&["TG4".into()], &["TG41".into()]);
        assert!(s.enabled(Rule::NoFeedRate));
        assert!(!s.enabled(Rule::ArcRadiusTooShort));
        assert!(!s.enabled(Rule::NoMotionMode));
        assert!(!s.enabled(Rule::Unreadable));
        assert!(Selection::all().enabled(Rule::Unreadable));
        assert!(!Selection::none().enabled(Rule::Unreadable));
    }
}
