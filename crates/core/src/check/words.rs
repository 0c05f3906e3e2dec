//! Words in a block (rules TG130-TG141): their order, repetition and addresses, several G
//! words, and what the checker cannot follow -- a jump, loop or call, a value it cannot
//! evaluate. [`Checker::words`] is the walk over a block's words: it asks the structure and
//! format rules of each word in turn and keeps what each word's value is read as.

use super::{is_dimension, BlockView, Checker, Word, DIMENSIONS};
use crate::decimal::Dec;
use crate::dialect;
use crate::lex::Family;
use crate::modal::{bit, Units};
use crate::rules::Rule;

/// What the warning for a D in a FANUC lathe's G71/G72 block adds: whose format the word is,
/// and that no source at hand says the profile's control reads it.
const ONE_BLOCK_ROUGHING: &str = "; in a G71/G72 block D is the depth of cut of the one-block \
     form G71 P Q U W D F (a Haas's), which the FANUC 0i-TF's standard format writes in a block \
     of its own (G71 U R); whether a 0i or 30i reads the one-block form, and what selects it, \
     is in no FANUC source at hand (docs/dialects.md)";

impl Checker {
    /// Whether TG130 judges this profile's word order: ISO 6983-1's clause 5.2 is the
    /// standard's recommendation, and the profiles read to the standard keep it (ISO, and
    /// HEIDENHAIN's ISO mode, for which no source was looked at). A FANUC, Haas, Okuma,
    /// SINUMERIK or LinuxCNC control reads a block's words in any order and its manual writes
    /// its own forms against 5.2's order (FANUC and Haas: `G10 L2 P1 X0 Y0 Z0`, `M98 P2000
    /// L3`, `G71 P10 Q20 U0.01 W0.005 D0.05 F0.01`, `G66 P9002 Z-5. R1.`; LinuxCNC's G code
    /// overview, "Order of Execution": the order of a line's items is not their position on
    /// it): the note was noise there (audit 50, B4). Asked only of a word out of order.
    #[cold]
    fn word_order_applies(&self) -> bool {
        matches!(self.config.family, Family::Iso | Family::Heidenhain)
    }

    /// `%NAME *` in a HEIDENHAIN program: a call of another program, which runs with this
    /// one's Q parameters and may change them and the position: nothing known is kept.
    pub(super) fn heidenhain_call(&mut self, line: usize, name: &[u8]) {
        if !self.unfollowed_noted {
            self.unfollowed_noted = true;
            let message = format!(
                "%{} (call): the checker reads the program in file order and does not follow \
                 jumps, loops or calls; from here on the position, feed and speed are taken as \
                 unknown until the program sets them",
                String::from_utf8_lossy(name)
                    .trim()
                    .trim_end_matches('*')
                    .trim_end()
            );
            self.report(Rule::NotFollowed, message, line, 1);
        }
        self.machine.forget();
        self.params.clear();
        self.motion_unknown = true;
        self.offsets_rewritten(line, "a jump or call the checker does not follow");
    }

    /// TG140, once per file: the first jump, loop or call the checker cannot follow (a
    /// statement, or a subprogram call `call` by M98/M97/G65/G66). Whether the block leaves
    /// the modal state unknown.
    pub(super) fn statements(&mut self, b: &BlockView<'_>, call: Option<&BlockView<'_>>) -> bool {
        // a Custom Macro B conditional assignment (`IF [..] THEN #106 = 1`) jumps nowhere and
        // moves nothing: only its variable's value is unknown after it (params.rs)
        let macro_b = self.config.family == Family::MacroB;
        if call.is_none() && self.linuxcnc_opened_running(b) {
            return false;
        }
        // and an IF whose condition the values known here make false does not jump: the run
        // goes on to the next block with all it knows (FANUC Custom Macro B, "IF[<conditional
        // expression>]GOTOn": not satisfied, the next block is executed; review 56b, F7), as
        // its target gains no way in (params.rs)
        let statement = b.statements.iter().find(|s| {
            s.1.unfollowed()
                && !(macro_b
                    && s.1 == crate::statement::Kind::Flow
                    && (crate::statement::conditional_assignment(s.2).is_some()
                        || self.condition_known(&s.2.to_ascii_uppercase()) == Some(false)))
        });
        let (column, what) = match (statement, call) {
            (Some(&(column, kind, text)), _) => (
                column,
                format!("{} ({})", String::from_utf8_lossy(text), kind.name()),
            ),
            (None, Some(block)) => {
                // the word that calls: a SINUMERIK's L (`N50 L54`), elsewhere M98/M97 or G65/G66
                // (`dialect::calls`)
                // (by its number: `G91 M98 P2` names M98, not the block's first G; review 46)
                let caller = |w: &&Word<'_>| match (self.config.family, w.letter) {
                    (Family::Sinumerik, letter) => letter == b'L' && w.index.is_empty(),
                    (_, b'M') => !w.point && matches!(w.value, Some(97 | 98 | 198)),
                    (_, b'G') => {
                        !w.point && matches!(w.value, Some(65 | 66)) || w.token().ends_with("66.1")
                    }
                    _ => false,
                };
                let w = block.words.iter().find(caller).unwrap_or(&block.words[0]);
                (w.column, format!("{} (subprogram call)", w.token()))
            }
            (None, None) => return false,
        };
        // (a jump surely taken forward passes over the blocks to its target, asked after the
        // block: passed.rs)
        if macro_b && statement.is_some() {
            self.after_block = true;
            self.jump_left = Some(Box::new(self.left()));
        }
        if !self.unfollowed_noted {
            self.unfollowed_noted = true;
            // (review 48 F3: a forward conditional jump's run is read at its target)
            let message = if call.is_none() && self.jump_keeps_params(b) {
                format!(
                    "{what}: the checker reads the program in file order; where this forward \
                     jump is taken and parameters are known here, the blocks from its target \
                     on are read too with the values they hold here (64 blocks at most: \
                     docs/check.md, \"At a jump target\"); the position, feed and speed are \
                     taken as unknown after it until the program sets them"
                )
            } else {
                format!(
                    "{what}: the checker reads the program in file order and does not follow \
                     jumps, loops or calls; from here on the position, feed and speed are \
                     taken as unknown until the program sets them"
                )
            };
            self.report(Rule::NotFollowed, message, b.line, column);
        }
        true
    }

    pub(super) fn words(&mut self, b: &BlockView<'_>) {
        let line = b.line;
        let plane = self.machine.state.plane;
        let ranks = &RANKS[usize::from(plane == 18 || plane == 19)];
        // the first word of each letter and index: a buffer kept from block to block
        let mut seen = std::mem::take(&mut self.seen);
        seen.clear();
        let mut seen_letters = 0u32;
        let mut last_rank = -1.0f64;
        let mut g_count = 0;
        self.readable.clear();
        for &(column, comment) in b.comments {
            self.comment(comment, line, column);
        }
        // (a line of plain words without a bracketed word has no block skip, at its start or
        // within, and no expression for a '/' to follow: nothing of the block skip's rules to
        // ask; a debug build asks them, and asserts they find nothing)
        if !self.plain_block || cfg!(debug_assertions) {
            let before = self.found.len();
            self.block_skip(b);
            debug_assert!(
                !self.plain_block || self.found.len() == before,
                "line {line}: a plain block's skip found"
            );
        }
        self.named_words(b);
        let has_formats = !self.config.formats.is_empty();
        // (its one reader is the decimal point of an M, S or T word on a FANUC,
        // `dialect::whole_address`: a block without one does not walk its words for G65/G66)
        self.macro_arguments = self.config.family == Family::MacroB
            && !self.config.haas
            && self.letters & bit(b'G') != 0
            && self.letters & (bit(b'M') | bit(b'S') | bit(b'T')) != 0
            && dialect::macro_call(b.words);
        self.m_call_possible = None;
        if self.config.family == Family::MacroB
            && !self.config.haas
            && self.letters & bit(b'M') != 0
            && self.letters & (bit(b'S') | bit(b'T')) != 0
        {
            self.m_call_possible = b
                .words
                .iter()
                .find(|w| {
                    w.letter == b'M'
                        && w.index.is_empty()
                        && w.expression.is_empty()
                        && !w.point
                        && w.value
                            .and_then(|n| i64::try_from(n).ok())
                            .is_some_and(|n| {
                                dialect::m_code_alarms(self.config.family, n).is_none()
                                    && self.config.code(b'M', n).is_none()
                            })
                })
                .map(|w| w.token());
        }
        let mut context = self.format_context();
        // (the words' keys are their own where nothing of the block gives a word another
        // reading: Checker::plain_format_key; a cycle's table gives roles that
        // `Meanings::any` does not count, so the roles themselves are looked at)
        let plain_keys = !self.format_table.afresh
            && self.named.is_empty()
            && (self.meanings_none
                || self.meanings.roles == [None; 26] && !self.meanings.start_angle);
        // the rules of each word's place, letter and address below are a function of the
        // block's addresses alone where it has a key: asked once a key (a debug build asks
        // them of a kept block too, and asserts they find nothing)
        let key = self.addresses_key(b, plane);
        let place = key.map_or(0, CleanBlocks::place);
        let kept = key.is_some_and(|key| self.clean_blocks.0[place] == key);
        if kept && !cfg!(debug_assertions) {
            // a kept block's words are letters A-Z without index (its addresses key): each is
            // only read, a word with an expression as the loop below reads it (a debug build
            // walks the loop, which asks the rules of a kept block as well); a plain block's
            // words have none, and are read with no test of each
            self.seen = seen;
            self.readable.reserve(b.words.len());
            if self.plain_block {
                if plain_keys {
                    for w in b.words {
                        let value = self.plain_word_or_kept(w, line, &mut context);
                        self.readable.push(value);
                    }
                    return;
                }
                for w in b.words {
                    let value = self.format_or_kept(w, line, &mut context, plain_keys);
                    self.readable.push(value);
                }
                return;
            }
            for w in b.words {
                let value = if w.expression.is_empty() {
                    self.format_or_kept(w, line, &mut context, plain_keys)
                } else {
                    self.expression_value(w, line, false)
                };
                self.readable.push(value);
            }
            return;
        }
        let mut clean = true;
        for (i, w) in b.words.iter().enumerate() {
            let letter = w.letter;
            if !kept || cfg!(debug_assertions) {
                let before = self.found.len();
                self.word_characters(i, w, line);
                if letter == b'G' {
                    g_count += 1;
                }
                let r = ranks[usize::from(letter)];
                if matches!(letter, b'I' | b'J' | b'K') {
                    // I J K follow their axis group (5.2's G02 X20 Y20 I20 J0 Z10) or the third
                    // axis (G03 X Y Z I J): only after F, S, T or M are they out of order
                    if last_rank >= 20.0 && self.word_order_applies() {
                        let message = format!("{} is out of the order of clause 5.2", w.token());
                        self.report(Rule::WordOrder, message, line, w.column);
                    }
                } else if r >= 0.0 {
                    if r < last_rank && self.word_order_applies() {
                        let message = format!("{} is out of the order of clause 5.2", w.token());
                        self.report(Rule::WordOrder, message, line, w.column);
                    }
                    last_rank = last_rank.max(r);
                }
                if let Some(j) = earlier(&seen, seen_letters, b.words, w) {
                    // G65 P9001 I1. J2. K3. I4.: argument specification II passes up to ten I
                    // J K sets (#4-#33)
                    let sets = dialect::argument_sets(self.config.family, b.words, letter, i);
                    if letter != b':' && sets.is_none_or(|n| n > 10) {
                        // (the earlier word's text only for a message: a block's second G word,
                        // of one block in twenty of some CAM programs, says none)
                        let other = || b.words[j].token();
                        if let Some(n) = sets {
                            let message = format!(
                                "{}: the {n}th {} word of a macro call; argument specification \
                                 II takes ten I J K sets at most",
                                w.token(),
                                letter as char
                            );
                            self.report(Rule::DimensionRepeated, message, line, w.column);
                        } else if is_dimension(letter) || matches!(letter, b'I' | b'J' | b'K') {
                            let message =
                                format!("{} repeats dimension word {}", w.token(), other());
                            self.report(Rule::DimensionRepeated, message, line, w.column);
                        } else if letter != b'G' && !self.config.repeatable.contains(&letter) {
                            let message = format!("{} repeats {} in one block", w.token(), other());
                            self.report(Rule::WordRepeated, message, line, w.column);
                        }
                    }
                } else {
                    seen.push(i);
                    if letter.is_ascii_uppercase() {
                        seen_letters |= bit(letter);
                    }
                }
                // ':' alignment, '#' parameters and LinuxCNC's polar '@' '^' have no Annex C
                // format
                if has_formats
                    && letter.is_ascii_uppercase()
                    && self.format_in(letter, Units::Metric).is_none()
                    && !dialect::macro_argument(self.config.family, b.words, letter)
                    && !linuxcnc_program_number(self.config.family, w)
                {
                    let mut message = format!(
                        "address {} is not in the profile's classification {}",
                        letter as char, self.config.classification
                    );
                    if letter == b'D' && self.fanuc_one_block_roughing(b) {
                        message.push_str(ONE_BLOCK_ROUGHING);
                    }
                    self.report(Rule::AddressNotClassified, message, line, w.column);
                }
                self.index(w, line);
                clean &= self.found.len() == before;
                debug_assert!(
                    !kept || clean,
                    "line {line}: a kept block's addresses found more"
                );
            }
            // S2=30000, X4=100: another spindle's or axis's value, which the profile's limits
            // and formats do not describe (its one spindle's, its X's): not read as the address's
            let extended =
                !w.index.is_empty() && dialect::extended_address(self.config.family, letter);
            if !w.expression.is_empty() || !letter.is_ascii_uppercase() || extended {
                let known = self.expression_value(w, line, extended);
                self.readable.push(known);
                continue;
            }
            let value = self.format_or_kept(w, line, &mut context, plain_keys);
            self.readable.push(value);
        }
        self.seen = seen;
        if !kept || cfg!(debug_assertions) {
            let before = self.found.len();
            self.several_g(b, g_count);
            clean &= self.found.len() == before;
            debug_assert!(
                !kept || clean,
                "line {line}: a kept block's G words found more"
            );
        }
        if let (Some(key), true, false) = (key, clean, kept) {
            self.clean_blocks.0[place] = key;
        }
    }

    /// The value of a word that is not read by its format: one with an expression, an
    /// address other than a letter, or an `extended` address (S2=30000): a letter's
    /// expression evaluated where its value is known here, else the value where no jump
    /// arrives ([`Checker::arrival_word`]; its word's tests out of line: a program scaling
    /// its axes by parameters has two such words a line).
    #[inline(always)]
    fn expression_value(&mut self, w: &Word<'_>, line: usize, extended: bool) -> Option<Dec> {
        let mut known = (w.index.is_empty() && w.letter.is_ascii_uppercase())
            .then(|| self.constant(w.expression))
            .flatten();
        if known.is_none() && self.arrival.is_some() {
            known = self.arrival_word(w, line, extended);
        }
        known
    }

    /// The key of the rules of a block's words that read only their places, letters and
    /// addresses as written (TG102, TG124, TG125, TG130-TG133, TG137: case, alignment, order,
    /// repeats, several G words, addresses outside the classification; TG206's index, none
    /// here): the addresses of its words as written, one byte each (the last lowest), and whether the plane is
    /// G18 or G19 (the order of I J K). A word's expression (`X[#1*2]`, `Y#<yscale>`) is
    /// no input of those rules: a block of such words has the key of its addresses. None --
    /// its rules asked -- for a block of more than seven words, or with a word that has an
    /// index, an address other than
    /// a letter, a letter written twice (whether that repeat is a macro call's arguments reads
    /// the G word's number) or a letter the profile's classification lacks (whether it is a
    /// macro call's argument, likewise); none at all where verdicts are not kept
    /// ([`Checker::keep_verdicts`]).
    fn addresses_key(&self, b: &BlockView<'_>, plane: i64) -> Option<u64> {
        if b.words.len() > 7 || self.format_table.afresh {
            return None;
        }
        // a line of plain words without a bracketed word: whether a letter repeats and the
        // classification lacks one from its letters, with no test of each word (its words are
        // letters without index or expression; a debug build tests them too, and asserts the
        // same key)
        if self.plain_block && !cfg!(debug_assertions) {
            return self.plain_addresses_key(b.words, plane);
        }
        let has_formats = !self.config.formats.is_empty();
        let mut key = 0u64;
        let mut letters = 0u32;
        for w in b.words {
            let letter = w.letter;
            if !letter.is_ascii_uppercase()
                || !w.index.is_empty()
                || letters & bit(letter) != 0
                || (has_formats && self.format_in(letter, Units::Metric).is_none())
            {
                return None;
            }
            letters |= bit(letter);
            key = key << 8 | u64::from(w.address);
        }
        let side = u64::from(plane == 18 || plane == 19);
        let key = Some(key | (0x80 | side << 3 | b.words.len() as u64) << 56);
        debug_assert!(
            !self.plain_block || self.plain_addresses_key(b.words, plane) == key,
            "line {}: a plain block's addresses key",
            b.line
        );
        key
    }

    /// [`Checker::addresses_key`] of a block of `words` (at most seven) that is a line of
    /// plain words without a bracketed word (`plain_block`: its words are letters A-Z
    /// without an index or an expression): None where a letter repeats (fewer letters than
    /// words, from the letters its reader found) or the classification lacks one, else its
    /// addresses as written, a byte each, and its length and plane; no test of each word.
    #[inline(always)]
    fn plain_addresses_key(&self, words: &[Word<'_>], plane: i64) -> Option<u64> {
        if self.letters.count_ones() as usize != words.len()
            || self.letters & self.format_table.unformatted != 0
        {
            return None;
        }
        let addresses = words
            .iter()
            .fold(0u64, |key, w| key << 8 | u64::from(w.address));
        let side = u64::from(plane == 18 || plane == 19);
        Some(addresses | (0x80 | side << 3 | words.len() as u64) << 56)
    }
    /// A FANUC lathe's G71 or G72 block (not a Haas's): its D, the depth of cut of the
    /// one-block form `G71 P Q U W D F`, is no word of the control's standard format, which
    /// writes the depth in a block of its own (`G71 U R`, FANUC 0i-TF "Multiple repetitive
    /// cycle"); the one-block form is a Haas's, and whether (and under which parameter) a 0i
    /// or 30i reads it is in no FANUC source at hand (docs/dialects.md).
    fn fanuc_one_block_roughing(&self, b: &BlockView<'_>) -> bool {
        self.config.modal.fanuc_lathe
            && !self.config.haas
            && b.words.iter().any(|w| {
                w.letter == b'G'
                    && w.expression.is_empty()
                    && matches!(super::code_number(w.number), b"71" | b"72")
            })
    }

    /// The words the block's codes make name a block or a program (the profile's
    /// [`super::CodeWord`]s: `G71 P100 Q200`, `M98 P1234`), whatever their order in the block.
    fn named_words(&mut self, b: &BlockView<'_>) {
        self.named.clear();
        if self.config.code_words.is_empty() || self.letters & (bit(b'G') | bit(b'M')) == 0 {
            return;
        }
        // (a block whose codes are G00-G03 and G17-G19 alone, where no code word is of one of them, has
        // none of them: its words are not walked; a debug build walks them)
        if self.motion_only
            && self.format_table.named_codes[0] & (0b1111 | 0b111 << 17) == 0
            && !cfg!(debug_assertions)
        {
            return;
        }
        for w in b.words {
            if !matches!(w.letter, b'G' | b'M') || !w.expression.is_empty() || !w.index.is_empty() {
                continue;
            }
            // a whole code below 128 that no code word is of (G1, M3) is not looked for in the
            // list (a debug build looks, and asserts it finds nothing)
            let codes = self.format_table.named_codes[usize::from(w.letter == b'M')];
            let unnamed = !w.point && w.value.is_some_and(|n| n < 128 && codes >> n & 1 == 0);
            if unnamed && !cfg!(debug_assertions) {
                continue;
            }
            let number = super::code_number(w.number);
            for c in &self.config.facts.code_words {
                if c.code.0 == w.letter && c.code.1 == number {
                    debug_assert!(!unnamed, "{}: a code word not in named_codes", w.token());
                    self.named.push((c.letter, c.address, w.token()));
                }
            }
        }
    }

    /// TG141, once per file: the first value the checker cannot evaluate. (Inline: a
    /// program that scales its axes by parameters asks at every block, and only the first
    /// ask says anything; the finding out of line.)
    #[inline(always)]
    pub(super) fn not_evaluated(&mut self, line: usize, w: &Word<'_>) {
        if !self.unknown_noted {
            self.not_evaluated_first(line, w);
        }
    }

    /// [`Checker::not_evaluated`]'s finding.
    #[cold]
    #[inline(never)]
    fn not_evaluated_first(&mut self, line: usize, w: &Word<'_>) {
        self.unknown_noted = true;
        let extended =
            !w.index.is_empty() && dialect::extended_address(self.config.family, w.letter);
        if extended && w.letter == b'M' {
            let message = format!(
                "{}: an M function of another spindle (an extended address) given by a \
                 value the checker cannot evaluate, or that is no whole number from 0; its \
                 code is not checked",
                w.token()
            );
            self.report(Rule::NotEvaluated, message, line, w.column);
            return;
        }
        let what = if extended {
            "an address of another axis or spindle (an extended address), which the \
             profile does not describe"
        } else {
            "a value the checker cannot evaluate"
        };
        let message = format!(
            "{}: {what}; {} is taken as set but unknown from here on (no check of it \
             until a plain value)",
            w.token(),
            w.letter as char
        );
        self.report(Rule::NotEvaluated, message, line, w.column);
    }

    /// TG133: more than one G word in a block. (Inline, the finding out of line: `words`
    /// asks at every block.)
    #[inline]
    pub(super) fn several_g(&mut self, b: &BlockView<'_>, g_count: usize) {
        if g_count > 1 {
            self.several_g_found(b, g_count);
        }
    }

    /// [`Checker::several_g`]'s finding.
    #[inline(never)]
    fn several_g_found(&mut self, b: &BlockView<'_>, g_count: usize) {
        let line = b.line;
        let first_g = super::column_of(b.words, b'G');
        // "{g_count} G words in one block; Annex D recommends one", without the formatter
        // (said of one block in twenty of some CAM programs: slot_assembly_12)
        let mut message = String::with_capacity(48);
        if g_count < 10 {
            message.push(char::from(b'0' + g_count as u8));
        } else {
            message.push_str(&g_count.to_string());
        }
        message.push_str(" G words in one block; Annex D recommends one");
        self.report(Rule::SeveralGWords, message, line, first_g);
    }
}

/// The keys ([`Checker::addresses_key`]) of blocks whose word rules of places, letters and
/// addresses found nothing, by a multiplicative hash (0: none): a block of a kept key is not
/// asked them again.
#[derive(Clone)]
pub(super) struct CleanBlocks(Box<[u64]>);

/// The places of [`CleanBlocks`].
const CLEAN_BLOCKS: usize = 256;

impl Default for CleanBlocks {
    fn default() -> CleanBlocks {
        CleanBlocks(vec![0; CLEAN_BLOCKS].into_boxed_slice())
    }
}

impl CleanBlocks {
    fn place(key: u64) -> usize {
        (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as usize % CLEAN_BLOCKS
    }

    /// The places that hold a key (the tests').
    #[cfg(test)]
    pub(in crate::check) fn kept(&self) -> usize {
        self.0.iter().filter(|&&key| key != 0).count()
    }
}

/// The first word of `w`'s letter and index before it: `seen` holds the first word of each
/// letter and index so far, and `letters` the bits ([`bit`]) of the letters A-Z among them.
/// Asked of every word, and nearly every word's letter is its block's first: where the mask
/// says no earlier word has the letter, there is nothing to search.
fn earlier(seen: &[usize], letters: u32, words: &[Word<'_>], w: &Word<'_>) -> Option<usize> {
    if w.letter.is_ascii_uppercase() && letters & bit(w.letter) == 0 {
        return None;
    }
    seen.iter()
        .copied()
        .find(|&j| words[j].letter == w.letter && words[j].index == w.index)
}

/// A word's place in the order of clause 5.2 by its letter, in the plane `plane` (the centre's
/// I J K after the axes of the plane): -1 for a letter the clause does not order.
pub(super) const fn rank(letter: u8, plane: i64) -> f64 {
    let centre = if plane == 18 || plane == 19 { 4.5 } else { 3.5 };
    match letter {
        b'N' | b'O' | b':' => 0.0,
        b'G' => 1.0,
        b'I' => centre + 0.1,
        b'J' => centre + 0.2,
        b'K' => centre + 0.3,
        b'F' | b'E' => 20.0,
        b'S' => 21.0,
        b'T' | b'D' | b'H' => 22.0,
        b'M' => 23.0,
        _ => {
            let mut i = 0;
            while i < DIMENSIONS.len() {
                if DIMENSIONS[i] == letter {
                    return 2.0 + i as f64;
                }
                i += 1;
            }
            -1.0
        }
    }
}

/// [`rank`] of every byte in the planes G17 (and any other) and G18/G19, worked out when the
/// core is compiled: asked of every word.
const RANKS: [[f64; 256]; 2] = {
    let mut table = [[0.0; 256]; 2];
    let mut letter = 0;
    while letter < 256 {
        table[0][letter] = rank(letter as u8, 17);
        table[1][letter] = rank(letter as u8, 18);
        letter += 1;
    }
    table
};

#[cfg(test)]
mod tests {
    use super::super::Word;

    /// [`super::earlier`] against the slow way, a search of every word before, over blocks of
    /// words of letters (`#` and `:` among them) with and without an index.
    #[test]
    fn a_repeated_word_is_found_as_a_search_finds_it() {
        let letters = b"XYZGM#:IA";
        let mut seed = 7u64;
        for _ in 0..3000 {
            let mut texts = Vec::new();
            for _ in 0..8 {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let letter = letters[(seed >> 33) as usize % letters.len()] as char;
                texts.push(match (seed >> 40) % 3 {
                    0 => format!("{letter}1"),
                    1 => format!("{letter}2=5"),
                    _ => format!("{letter}3=5"),
                });
            }
            let words: Vec<Word<'_>> = texts.iter().map(|t| Word::new(t.as_bytes(), 1)).collect();
            let (mut seen, mut mask) = (Vec::new(), 0u32);
            for (i, w) in words.iter().enumerate() {
                let slow =
                    (0..i).find(|&j| words[j].letter == w.letter && words[j].index == w.index);
                let fast = super::earlier(&seen, mask, &words, w);
                assert_eq!(fast, slow, "{texts:?} {i}");
                if fast.is_none() {
                    seen.push(i);
                    if w.letter.is_ascii_uppercase() {
                        mask |= crate::modal::bit(w.letter);
                    }
                }
            }
        }
    }

    /// The key of a block's rules of places, letters and addresses
    /// ([`super::super::Checker::addresses_key`]): the same for blocks that differ in their
    /// numbers only, another for another address, its case, order or count, and none where a
    /// rule would read more than the addresses.
    #[test]
    fn a_blocks_addresses_are_its_key() {
        use super::super::testing::{dialect, run};
        use super::super::BlockView;
        let (checker, _) = run(iso_mill(), &dialect(Family::Iso), &program("G01 X1. F100."));
        let key = |text: &str, plane: i64| {
            let words: Vec<Word<'_>> = text
                .split(' ')
                .map(|t| Word::new(t.as_bytes(), 1))
                .collect();
            let b = BlockView {
                line: 1,
                text: text.as_bytes(),
                ascii: text.is_ascii(),
                crs: None,
                words: &words,
                skip: false,
                skip_within: None,
                comments: &[],
                percent: false,
                ident: b"",
                statements: &[],
            };
            checker.addresses_key(&b, plane)
        };
        assert_eq!(key("G01 X1. Y2.", 17), key("G02 X-5.5 Y.25", 17));
        assert!(key("G01 X1. Y2.", 17).is_some());
        for other in [
            "G01 Y2. X1.",
            "g01 X1. Y2.",
            "G01 X1.",
            "G01 X1. Y2. Z3.",
            "G01 X1. I2.",
        ] {
            assert_ne!(key("G01 X1. Y2.", 17), key(other, 17), "{other}");
        }
        assert_ne!(key("G02 X1. I2.", 17), key("G02 X1. I2.", 18));
        // a word's expression is no input of the rules of its address: the key of its
        // addresses
        assert_eq!(key("G01 X[1+2]", 17), key("G01 X1.", 17));
        assert_eq!(key("G01 X#1 Y[#<y>*2]", 17), key("G01 X1. Y2.", 17));
        // a repeat, an index, ':' or '#', an unclassified letter, eight words
        for none in [
            "G01 X1. X2.",
            "G01 X4=1.",
            "G01 X[1] X[2]",
            ":10 G01",
            "#1=2",
            "G01 U1.",
            "N1 G01 X1. Y1. Z1. I1. J1. F1.",
        ] {
            assert_eq!(key(none, 17), None, "{none}");
        }
    }

    /// A block whose addresses' rules found nothing before is only read, its words with an
    /// expression too: the value of `X#<c>`, where `X#<b>` of the same addresses was kept,
    /// still goes to the travel (LinuxCNC, X -500 to 500: X from -400 to 700 spans 1100).
    #[test]
    fn a_kept_block_s_expressions_are_read() {
        let text = program(
            "#<a> = -400.\n#<b> = 300.\n#<c> = 700.\nG21 G90 G00 X#<a>\nX#<b>\nX#<c>\nX#<b>",
        );
        let linuxcnc = of_family(Family::LinuxCnc);
        assert_eq!(fired(linuxcnc, &text, Rule::TravelExceeded), [(7, 1)]);
    }

    use super::super::testing::{findings, fired, iso_mill, of_family, program};
    use super::super::{Config, ProfileFacts};
    use crate::lex::Family;
    use crate::rules::Rule;

    fn at(body: &str, rule: Rule) -> Vec<(usize, usize)> {
        fired(iso_mill(), &program(body), rule)
    }

    /// TG130 is the standard's order, and only the ISO profiles' (and HEIDENHAIN's ISO
    /// mode's): a FANUC, Haas, Okuma, SINUMERIK or LinuxCNC manual writes its own forms in its
    /// own order (audit 50, B4: `G10 L2 P1 X0 Y0 Z0`, `M98 P2000 L3`, `G71 P10 Q20 U0.01 W0.005
    /// D0.05 F0.01`, `G66 P9002 Z-5. R1.` were notes).
    #[test]
    fn the_word_order_is_the_iso_profiles_only() {
        for body in [
            "G10 L2 P1 X0 Y0 Z0",
            "M98 P2000 L3",
            "G66 P9002 Z-5. R1.",
            "G01 F100. X1.",
        ] {
            for family in [
                Family::MacroB,
                Family::Okuma,
                Family::Sinumerik,
                Family::LinuxCnc,
            ] {
                assert_eq!(
                    fired(of_family(family), &program(body), Rule::WordOrder),
                    [],
                    "{family:?} {body}"
                );
            }
        }
        assert_eq!(
            fired(
                of_family(Family::Heidenhain),
                &program("G01 F100. X1."),
                Rule::WordOrder
            ),
            [(2, 11)]
        );
    }

    #[test]
    fn the_word_order_of_clause_5_2() {
        assert_eq!(
            at("N10 G02 X1. Y1. I1. J0 F100. S500 T1 M03", Rule::WordOrder),
            []
        );
        // I J K may follow the third axis: G03 X Y Z I J
        assert_eq!(at("G03 X1. Y1. Z1. I1. J0 F100.", Rule::WordOrder), []);
        assert_eq!(at("G01 F100. X1.", Rule::WordOrder), [(2, 11)]);
        assert_eq!(at("G01 X1. F100. I1.", Rule::WordOrder), [(2, 15)]);
    }

    #[test]
    fn repeated_words() {
        assert_eq!(at("G01 X1. X2. F100.", Rule::DimensionRepeated), [(2, 9)]);
        // a Custom Macro B call passes up to ten I J K sets (argument specification II)
        let sets = |n: usize| {
            let words: String = (1..=n).map(|k| format!(" I{k}. J{k}. K{k}.")).collect();
            program(&format!("G65 P9001{words}"))
        };
        let macro_b = || of_family(Family::MacroB);
        assert_eq!(fired(macro_b(), &sets(10), Rule::DimensionRepeated), []);
        let eleventh = fired(macro_b(), &sets(11), Rule::DimensionRepeated);
        assert_eq!(eleventh.len(), 3, "{eleventh:?}");
        // ISO 6983-1 has no macro call: a repeated I is a repeated dimension word
        assert_eq!(
            fired(iso_mill(), &sets(2), Rule::DimensionRepeated).len(),
            3
        );
        assert_eq!(at("G01 X1. F100. S10 S20", Rule::WordRepeated), [(2, 19)]);
        assert_eq!(at("G01 X1. F100. S10 S20", Rule::DimensionRepeated), []);
        // G words repeat by design; so do the profile's repeatable letters
        assert_eq!(at("G17 G01 X1. F100.", Rule::WordRepeated), []);
        let repeatable = Config {
            facts: ProfileFacts {
                repeatable: b"S".to_vec(),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        let text = program("G01 X1. F100. S10 S20");
        assert_eq!(fired(repeatable, &text, Rule::WordRepeated), []);
    }

    /// TG133's message, made without the formatter (a count under ten as one digit, ten and
    /// more by `to_string`): the text held for 2, 9 and 10 G words (review 49a, F7).
    #[test]
    fn several_g_words_are_counted_in_the_message() {
        let said = |body: &str| {
            findings(iso_mill(), &program(body), Rule::SeveralGWords)
                .into_iter()
                .map(|f| (f.line, f.column, f.message))
                .collect::<Vec<_>>()
        };
        let text = |n: usize| format!("{n} G words in one block; Annex D recommends one");
        assert_eq!(said("G17 G01 X1. F100."), [(2, 1, text(2))]);
        let nine = "G17 G21 G40 G49 G80 G90 G94 G54 G01 X1. F100.";
        assert_eq!(said(nine), [(2, 1, text(9))]);
        assert_eq!(said(&format!("X1. {nine} G17")), [(2, 5, text(10))]);
        assert_eq!(
            said(&format!("{nine} G17 G17 G17")),
            [(
                2,
                1,
                "12 G words in one block; Annex D recommends one".to_string()
            )]
        );
    }

    #[test]
    fn several_g_words_and_unclassified_addresses() {
        assert_eq!(at("G17 G01 X1. F100.", Rule::SeveralGWords), [(2, 1)]);
        assert_eq!(at("G01 X1. F100.", Rule::SeveralGWords), []);
        assert_eq!(
            at("G01 X1. F100. U2.", Rule::AddressNotClassified),
            [(2, 15)]
        );
        assert_eq!(at("G01 X1. F100.", Rule::AddressNotClassified), []);
        // with no classification, no address is out of it
        let none = Config {
            facts: ProfileFacts {
                formats: Vec::new(),
                ..iso_mill().facts
            },
            ..iso_mill()
        };
        assert_eq!(
            fired(none, &program("G01 U2. F100."), Rule::AddressNotClassified),
            []
        );
    }

    #[test]
    fn jumps_and_calls_the_checker_does_not_follow_are_said_once() {
        let macro_b = || of_family(Family::MacroB);
        let text = program("G01 X1. F100.\nGOTO 10\nN10 M98 P100\nGOTO 20\nN20 G00 X0");
        let found = findings(macro_b(), &text, Rule::NotFollowed);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].line, found[0].column), (3, 1));
        assert!(
            found[0].message.starts_with("GOTO 10 (flow)"),
            "{}",
            found[0].message
        );
        let call = program("G01 X1. F100.\nM98 P100");
        let found = findings(macro_b(), &call, Rule::NotFollowed);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(
            found[0].message.starts_with("M98 (subprogram call)"),
            "{}",
            found[0].message
        );
        // the call's word named, not the block's first M or G (review 46, F5)
        for (block, word) in [("G91 M98 P100", "M98"), ("M08 G65 P100 A1.", "G65")] {
            let found = findings(macro_b(), &program(block), Rule::NotFollowed);
            assert!(
                found[0]
                    .message
                    .starts_with(&format!("{word} (subprogram call)")),
                "{}",
                found[0].message
            );
        }
        assert_eq!(
            fired(macro_b(), &program("G01 X1. F100."), Rule::NotFollowed),
            []
        );
    }

    #[test]
    fn a_conditional_assignment_moves_nothing_and_keeps_the_checking() {
        // FANUC "Custom macro", conditional execution: IF [..] THEN runs one macro statement;
        // no jump: the position stays known, the arc after it is still checked (TG403)
        let macro_b = || of_family(Family::MacroB);
        let arc = "G00 X0 Y0\n#106 = 0\nIF [#106 EQ 0] THEN #106 = 1\nG02 X10. Y0 I2. J0 F100.";
        assert_eq!(fired(macro_b(), &program(arc), Rule::NotFollowed), []);
        assert_eq!(
            fired(macro_b(), &program(arc), Rule::ArcRadiusMismatch),
            [(5, 1)]
        );
        let no_then = arc.replace(" THEN ", " ");
        let numbered = arc.replace("IF", "N20 IF");
        assert_eq!(
            fired(macro_b(), &program(&numbered), Rule::ArcRadiusMismatch),
            [(5, 1)]
        );
        // the variable's value is no longer known: a word reading it is unknown (TG141)
        let read = "#106 = 0\nIF [#1 EQ 0] THEN #106 = 1\nG00 X#106";
        assert_eq!(
            fired(macro_b(), &program(read), Rule::NotEvaluated),
            [(4, 5)]
        );
        let kept = "#106 = 0\nIF [#1 EQ 0] THEN #107 = 1\nG00 X#106";
        assert_eq!(fired(macro_b(), &program(kept), Rule::NotEvaluated), []);
        // a jump, a statement that is no plain assignment, and the grinder's form without
        // THEN still lose the position
        for text in [
            "G00 X0 Y0\nIF [#1 EQ 0] GOTO 10\nN10 G02 X10. Y0 I2. J0 F100.".to_string(),
            "G00 X0 Y0\nIF [#1 EQ 0] THEN #[#2] = 1\nG02 X10. Y0 I2. J0 F100.".to_string(),
            no_then,
        ] {
            assert_eq!(
                fired(macro_b(), &program(&text), Rule::NotFollowed).len(),
                1,
                "{text}"
            );
            assert_eq!(
                fired(macro_b(), &program(&text), Rule::ArcRadiusMismatch),
                [],
                "{text}"
            );
        }
    }

    /// The SINUMERIK's predefined instructions written alone, frames with their axis words
    /// and declarations are no calls (Programming Manual "Fundamentals" and "Job Planning",
    /// list of instructions): the checker follows the program past them, so a feed motion
    /// with no feed rate after one is still found.
    #[test]
    fn a_sinumerik_instruction_is_no_subprogram_call() {
        let sinumerik = || of_family(Family::Sinumerik);
        for instruction in [
            "DYNNORM",
            "DYNPOS",
            "DYNROUGH",
            "DYNSEMIFIN",
            "DYNFINISH",
            "LIFTFAST",
            "ROTS X30 Y20",
            "AROTS X10 Y5",
            "SETMS",
            "STOPFIFO",
            "FIFOCTRL",
            "DIAMCYCOF",
            // one of each group of the list (statement::SINUMERIK_INSTRUCTIONS)
            "STARTFIFO",
            "SUPD",
            "TOROT",
            "DYNPREC",
            "LFPOS",
            "CUT3DFD",
            "ORIANGLE",
            "COMPPATH",
            "DIAMCHAN",
            "RMNBL",
            "PONS",
            "STOPRE",
            // predefined procedures with their arguments, of class (a): nothing the checker
            // follows changes (SETMS changes the speed alone)
            "SETMS(2)",
            "SETAL(61000)",
            "MMC(\"CYCLES,PICTURE_ON,T_SK.COM\",\"A\")",
            "WAITM(1,1,2)",
            "WRITE(_ERR,\"LOG\",\"DONE\")",
            "COUPDEF(S2,S1,1,1,\"FINE\",\"DV\")",
            "BRISKA(A)",
            "GETSELT(_T)",
            "msg(\"ROUGHING\")",
            "EXTERN MYSUB(REAL)",
            "DEF REAL _X",
            "dynnorm ; in lower case",
        ] {
            let text = format!("G0 X0 Y0 Z5\n{instruction}\nG1 X10\nM30\n");
            assert_eq!(
                fired(sinumerik(), &text, Rule::NoFeedRate),
                [(3, 4)],
                "{instruction}"
            );
            assert_eq!(
                fired(sinumerik(), &text, Rule::NotFollowed),
                [],
                "{instruction}"
            );
        }
        // a name the list does not hold is a subprogram's, called: the position is unknown
        let call = "G0 X0 Y0 Z5\nMYSUB\nG1 X10\nM30\n";
        let found = findings(sinumerik(), call, Rule::NotFollowed);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (2, 1));
        assert!(
            found[0].message.starts_with("MYSUB (call)"),
            "{}",
            found[0].message
        );
    }

    /// A motion of G group 1 the checker does not model (splines, `CIP`, `CT`: Programming
    /// Manual Fundamentals, "List of G functions", group 1) is no call, and its points are no
    /// arcs or lines to check: after `BSPLINE` the points of a program in G2 are not arcs
    /// without a centre; G1 brings a checked motion back.
    #[test]
    fn a_sinumerik_motion_by_name_leaves_the_motion_unknown() {
        let sinumerik = || of_family(Family::Sinumerik);
        for motion in ["BSPLINE", "CIP X20 Y5 I1=15 J1=2", "ct", "POLY"] {
            let text = format!(
                "G0 X0 Y0 Z5\nG2 X10 Y0 CR=5 F100\n{motion}\nX20 Y5\nX30 Y0\nG1 X40\nG2 X50\nM30\n"
            );
            assert_eq!(
                fired(sinumerik(), &text, Rule::ArcCentreMissing),
                [(7, 1)],
                "{motion}"
            );
            assert_eq!(fired(sinumerik(), &text, Rule::NotFollowed), [], "{motion}");
            assert_eq!(
                fired(sinumerik(), &text, Rule::NoMotionMode),
                [],
                "{motion}"
            );
        }
        // a program's name that happens to begin so is a call, as before
        let call = "G0 X0 Y0 Z5\nBSPLINE_ROUGH\nG1 X10\nM30\n";
        assert_eq!(fired(sinumerik(), call, Rule::NotFollowed), [(2, 1)]);
    }

    /// `REPOSA` returns to where an interrupted program left the path (Fundamentals, "List of
    /// G functions", group 2): the position is unknown after it, the feed kept.
    #[test]
    fn a_sinumerik_repositioning_forgets_the_position_alone() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text = |between: &str| {
            format!("G0 X0 Y0 Z5\nG1 X10 F100\n{between}\nG2 X40 Y0 CR=5\nG1 X50\nM30\n")
        };
        // from X10 the chord is 30, longer than the diameter: from an unknown point, no check
        assert_eq!(
            fired(sinumerik(), &text("REPOSA"), Rule::ArcRadiusTooShort),
            []
        );
        assert_eq!(fired(sinumerik(), &text("REPOSA"), Rule::NoFeedRate), []);
        assert_eq!(fired(sinumerik(), &text("REPOSA"), Rule::NotFollowed), []);
        assert_eq!(
            fired(sinumerik(), &text("STOPRE"), Rule::ArcRadiusTooShort),
            [(4, 1)]
        );
    }

    /// A positioning axis moves on its own (Fundamentals, "Traversing positioning axes (POS,
    /// POSA, POSP, FA, WAITP, WAITMC)"): after `POS[X]=35` or `POSA[X]=35`, with or without
    /// the `WAITP(X)` that waits for it, X is not where the path left it (X10), so the arc
    /// after it is not checked from there (from X35 it is a half circle, from X10 its chord of
    /// 30 is longer than the diameter); Y, an axis not named, is still known. A spindle
    /// positioned (`SPOS=90`) may be the rotary axis C: C is unknown, X kept.
    #[test]
    fn a_sinumerik_positioning_axis_forgets_its_position() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text =
            |between: &str| format!("G0 X0 Y0 Z5\nG1 X10 F100\n{between}\nG2 X40 Y0 CR=5\nM30\n");
        assert_eq!(
            fired(sinumerik(), &text("WAITP(X)"), Rule::ArcRadiusTooShort),
            [(4, 1)]
        );
        for between in [
            "POSA[X]=35\nWAITP(X)",
            "POSA[X]=35",
            "POS[X]=35\nWAITP(X)",
            "POS[X]=35",
            "G1 Y0 POSA[X]=35",
            "pos[ x ]=IC(25)",
            "POSP[X]=(35,10,0)",
            "POS[AX1]=35",
            "POS[_AXIS]=35",
        ] {
            let program = text(between);
            assert_eq!(
                fired(sinumerik(), &program, Rule::ArcRadiusTooShort),
                [],
                "{between}"
            );
            assert_eq!(
                fired(sinumerik(), &program, Rule::NotFollowed),
                [],
                "{between}"
            );
        }
        // another axis positioned: X and Y are where the path left them, the arc checked
        let other =
            |between: &str| format!("G0 X0 Y0 Z5\nG1 X10 F100\n{between}\nG2 X40 CR=5\nM30\n");
        for between in [
            "POSA[Z]=100\nWAITP(Z)",
            "POS[U]=10",
            "SPOS=90",
            "SPOSA[2]=IC(90)",
        ] {
            let line = 4 + between.matches('\n').count();
            assert_eq!(
                fired(sinumerik(), &other(between), Rule::ArcRadiusTooShort),
                [(line, 1)],
                "{between}"
            );
        }
        // Y positioned: the arc ends at the Y in force, unknown
        assert_eq!(
            fired(sinumerik(), &other("POS[Y]=20"), Rule::ArcRadiusTooShort),
            []
        );
        // what is forgotten, axis by axis
        let dialect = super::super::testing::dialect(Family::Sinumerik);
        let after = |between: &str| {
            let text = format!("G0 X1 Y2 Z3 A4 B5 C6\n{between}\n");
            let (checker, _) = super::super::testing::run(sinumerik(), &dialect, &text);
            b"XYZABC"
                .iter()
                .map(|&axis| checker.machine.state.axis(axis).map(|v| v.to_string()))
                .collect::<Vec<_>>()
        };
        let known = |axes: &str| {
            b"XYZABC"
                .iter()
                .zip(["1", "2", "3", "4", "5", "6"])
                .map(|(axis, value)| axes.as_bytes().contains(axis).then(|| value.to_string()))
                .collect::<Vec<_>>()
        };
        assert_eq!(after("WAITP(X)"), known("XYZABC"));
        assert_eq!(after("POSA[X]=35"), known("YZABC"));
        assert_eq!(after("POS[b]=35"), known("XYZAC"));
        assert_eq!(after("POS[X1]=35"), known(""));
        assert_eq!(after("SPOS=90"), known("XYZ"));
        assert_eq!(after("SPOS[2]=90"), known("XYZ"));
        assert_eq!(after("FA[X]=100"), known("XYZABC"));
    }

    /// A predefined procedure that couples, reconfigures or sets axes, or defines a table from
    /// the blocks after it (list of operations, type P; docs/dialects.md, class (b)): the
    /// position is unknown after it, the feed kept, and TG140 names the procedure. A procedure
    /// whose effect is unclear (class (c)) and a name no source lists stay calls.
    #[test]
    fn a_sinumerik_procedure_that_changes_the_axes_forgets_the_position() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text = |between: &str| {
            format!("G0 X0 Y0 Z5\nG1 X10 F100\n{between}\nG2 X40 Y0 CR=5\nG1 X50\nM30\n")
        };
        for (procedure, what) in [
            ("LEADON(A,X,1)", "couples axes or spindles"),
            ("TRAILOF(V,Y)", "couples axes or spindles"),
            ("GEOAX(1,XX)", "changes the axis configuration"),
            ("PRESETON(X,0)", "sets actual values"),
            ("CTABDEF(Y,X,1,0)", "begins or ends a table"),
            // overlaid motions: ended (DRFOF, CORROF) or an online tool offset written
            (
                "DRFOF",
                "sets actual values or moves the axes by an overlaid motion",
            ),
            (
                "CORROF(X,\"DRF\")",
                "sets actual values or moves the axes by an overlaid motion",
            ),
            (
                "PUTFTOC(0.1,3,1)",
                "sets actual values or moves the axes by an overlaid motion",
            ),
            (
                "PUTFTOCF(1,$AA_IW[V],3,1)",
                "sets actual values or moves the axes",
            ),
            (
                "FTOC(1,$AA_IW[V],3,1)",
                "sets actual values or moves the axes",
            ),
        ] {
            // from X10 the chord is 30, longer than the diameter: from an unknown point, none
            let program = text(procedure);
            assert_eq!(
                fired(sinumerik(), &program, Rule::ArcRadiusTooShort),
                [],
                "{procedure}"
            );
            assert_eq!(
                fired(sinumerik(), &program, Rule::NoFeedRate),
                [],
                "{procedure}"
            );
            let found = findings(sinumerik(), &program, Rule::NotFollowed);
            assert_eq!(found.len(), 1, "{found:?}");
            assert_eq!((found[0].line, found[0].column), (3, 1));
            let named = format!("{procedure} (predefined procedure): it {what}");
            assert!(found[0].message.starts_with(&named), "{}", found[0].message);
        }
        // said once per file, as a call is; the position is forgotten at each
        let twice =
            "G0 X0 Y0 Z5\nG1 X10 F100\nLEADON(A,X,1)\nG1 X10\nLEADOF(A,X)\nG2 X40 Y0 CR=5\nM30\n";
        assert_eq!(fired(sinumerik(), twice, Rule::NotFollowed), [(3, 1)]);
        assert_eq!(fired(sinumerik(), twice, Rule::ArcRadiusTooShort), []);
        // class (c), and a user's subprogram: a call, the feed forgotten too
        for call in ["NEWCONF", "TCA(\"DRILL\",1,1)", "MYSUB(1,2)", "GWPSON(1)"] {
            let found = findings(sinumerik(), &text(call), Rule::NotFollowed);
            assert_eq!(found.len(), 1, "{found:?}");
            assert!(
                found[0].message.starts_with(&format!("{call} (call)")),
                "{}",
                found[0].message
            );
        }
    }

    /// A procedure's argument may be a variable it writes (`GETSELT(_T)` returns the selected
    /// T number, `READ(_ERR,..,_LINES)` the lines read): every parameter or variable written
    /// alone as an argument is no longer known, whichever procedure it is (`SETAL(R1)` only
    /// reads R1, and R1 is forgotten too), so a value read from it is TG141; an argument that
    /// is an expression (`SETAL(R1+1)`) and a variable not among the arguments stay known.
    /// One program a case: TG141 is said once per file.
    #[test]
    fn a_sinumerik_procedure_may_write_its_arguments() {
        let sinumerik = || of_family(Family::Sinumerik);
        let set = "R1=10 R2=20\n_A=1\n_B=2\n";
        for (procedure, read, found) in [
            ("GETSELT(R1)", "X=R1", true),
            ("GETSELT(r1)", "X=R1", true),
            ("SETAL(R1)", "X=R1", true),
            ("SETAL(R1)", "X=R2", false),
            ("SETAL(R1+1)", "X=R1", false),
            ("READ(_A,\"LOG\",1,1,_B)", "X=_A", true),
            ("READ(_A,\"LOG\",1,1,_B)", "X=_B", true),
            ("READ(_A,\"LOG\",1,1,_B)", "X=R1", false),
            ("WRITE(_A,\"LOG\",\"DONE\")", "X=_A", true),
            ("WRITE(_A,\"LOG\",\"DONE\")", "X=_B", false),
        ] {
            let text = format!("{set}{procedure}\nG0 {read} Y0\nM30\n");
            let expected: &[(usize, usize)] = if found { &[(5, 4)] } else { &[] };
            assert_eq!(
                fired(sinumerik(), &text, Rule::NotEvaluated),
                expected,
                "{procedure} then {read}"
            );
        }
    }

    /// A kinematic transformation (`TRACYL(400)`) programs the axes in other coordinates, and
    /// the `TRAFOOF` that ends it returns to the machine's: the position is unknown after
    /// either. A `TRAFOOF` with none in force (a program's opening line) changes nothing.
    #[test]
    fn a_sinumerik_transformation_forgets_the_position() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text = |between: &str| {
            format!("G0 X0 Y0 Z5\nG1 X10 F100\n{between}\nG2 X40 Y0 CR=5\nG1 X50\nM30\n")
        };
        for between in [
            "TRACYL(400)",
            "TRAORI",
            "TRANSMIT(1)",
            "TRACYL(400) G1 X10 Y0 TRAFOOF",
        ] {
            let text = text(
                &between
                    .replace(" G1", "\nG1")
                    .replace(" TRAFOOF", "\nTRAFOOF"),
            );
            assert_eq!(
                fired(sinumerik(), &text, Rule::ArcRadiusTooShort),
                [],
                "{between}"
            );
            assert_eq!(fired(sinumerik(), &text, Rule::NotFollowed), []);
        }
        assert_eq!(
            fired(sinumerik(), &text("TRAFOOF"), Rule::ArcRadiusTooShort),
            [(4, 1)]
        );
    }

    /// `PROC NAME` opens the subprogram's own definition, no call of it: the note of the
    /// first jump the checker does not follow names the jump.
    #[test]
    fn a_sinumerik_proc_is_no_call_of_itself() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text = "PROC MYSUB(REAL _D) SAVE DISPLOF\nG0 X0 Y0 Z5\nGOTOF END1\nG1 X5\n\
                    END1:\nRET\n";
        let found = findings(sinumerik(), text, Rule::NotFollowed);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (3, 1));
        assert!(
            found[0].message.starts_with("GOTOF END1 (flow)"),
            "{}",
            found[0].message
        );
        let bare = "PROC MYSUB\nG0 X0 Y0 Z5\nM17\n";
        assert_eq!(fired(sinumerik(), bare, Rule::NotFollowed), []);
    }

    /// A SINUMERIK's call by number is its L word (`N50 L54`): the note names it, where the
    /// block's first word is its number.
    #[test]
    fn a_sinumerik_l_call_is_named_by_its_l_word() {
        let sinumerik = || of_family(Family::Sinumerik);
        let text = "N10 G0 X0 Y0 Z5 F100\nN50 L54\nM30\n";
        let found = findings(sinumerik(), text, Rule::NotFollowed);
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!((found[0].line, found[0].column), (2, 5));
        assert!(
            found[0].message.starts_with("L54 (subprogram call)"),
            "{}",
            found[0].message
        );
        // an indexed L1=5 is no call; the L100 after it is
        let indexed = "N10 G0 X0 Y0 Z5 F100\nN20 L1=5 L100 P2\nM30\n";
        assert_eq!(fired(sinumerik(), indexed, Rule::NotFollowed), [(2, 10)]);
    }

    #[test]
    fn a_sinumerik_extended_address_with_an_expression_leaves_its_address_unknown() {
        // S1=INI[53] (Programming Manual Fundamentals, "Extended addresses"): a spindle's
        // speed, set but unknown (TG141, a note) and no word format read into it
        let sinumerik = || of_family(Family::Sinumerik);
        let text = program("G0 X0 Y0\nS1=INI[53] M1=3\nX1=_X_HOME S2=(R1+20)*2");
        let rules: Vec<_> = super::super::testing::check(sinumerik(), &text)
            .iter()
            .map(|f| (f.rule, f.line, f.column))
            .collect();
        assert_eq!(rules, [(Rule::NotEvaluated, 3, 1)]);
        // nor evaluated: spindle 2's limit is not the profile's spindle's
        let known = program("G0 X0 Y0\n_SPEED=6000\nS2=_SPEED*2 M2=3");
        let rules: Vec<_> = super::super::testing::check(sinumerik(), &known)
            .iter()
            .map(|f| (f.rule, f.line, f.column))
            .collect();
        assert_eq!(rules, [(Rule::NotEvaluated, 4, 1)]);
        // a plain number after an extension is another spindle's or axis's too: not the
        // profile's spindle speed (TG606), not X's start of an arc (TG403), and M1=3 M2=4
        // are two spindles' codes, not one modal group's (TG304)
        let plain =
            program("G0 X0 Y0 F100\nS2=30000 M3\nX4=100\nG2 X10 Y0 I5 J0\nM1=3 M2=4\nS9000");
        let found: Vec<_> = super::super::testing::check(sinumerik(), &plain)
            .iter()
            .map(|f| (f.rule, f.line, f.column))
            .collect();
        assert_eq!(
            found,
            [(Rule::NotEvaluated, 3, 1), (Rule::SpeedLimited, 7, 1)]
        );
        let master = program("G0 X0 Y0\n_SPEED=6000\nS=_SPEED*2 M3");
        assert_eq!(fired(sinumerik(), &master, Rule::SpeedLimited), [(4, 1)]);
        // elsewhere an index sets a parameter, not the address (ISO 6983-1 6.4.7)
        let iso = program("G0 X0 Y0\nS1=R1+2");
        assert_eq!(fired(of_family(Family::Iso), &iso, Rule::NotEvaluated), []);
    }

    #[test]
    fn a_value_the_checker_cannot_evaluate_is_said_once() {
        let macro_b = || of_family(Family::MacroB);
        let text = program("G01 X[#1+#2] F100.\nG01 Y#3");
        assert_eq!(fired(macro_b(), &text, Rule::NotEvaluated), [(2, 5)]);
        assert_eq!(
            fired(macro_b(), &program("G01 X1. F100."), Rule::NotEvaluated),
            []
        );
    }
}

#[cfg(test)]
mod kept_tests {
    use super::super::testing::{dialect, iso_mill, of_family};
    use super::super::{Checker, Config};
    use crate::lex::{Dialect, Family};
    use crate::rules::Selection;
    use std::sync::Arc;

    /// The findings of `program` checked line by line as the binding checks a run
    /// (`Checker::check_next_line`), with the verdicts kept or asked afresh of every block.
    fn findings(config: &Config, program: &str, keep: bool) -> Vec<(String, usize, usize)> {
        // (lower case read as plain words)
        let d = Dialect {
            lowercase: true,
            ..dialect(config.family)
        };
        let mut checker = Checker::new(Arc::new(config.clone()), Selection::all(), false);
        checker.keep_verdicts(keep);
        let mut tokens = Vec::new();
        let mut found = Vec::new();
        let (text, mut start) = (program.as_bytes(), 0);
        for line in 1.. {
            let length = checker.check_next_line(&text[start..], line, &d, &mut tokens);
            found.extend(checker.take());
            if start + length >= text.len() {
                break;
            }
            start += length + 1;
        }
        checker.finish();
        found.extend(checker.take());
        found
            .into_iter()
            .map(|f| (format!("{:?} {}", f.rule, f.message), f.line, f.column))
            .collect()
    }

    /// A line of plain words has its addresses' key from its letters and its words' addresses
    /// (`Checker::plain_addresses_key`): a block whose words' verdicts would differ from a
    /// kept block's if that key missed a part -- a repeated letter (a macro call's argument
    /// sets, `G65 I1. I2.`, are clean; `G01 I1. I2.` repeats I), a letter the classification
    /// lacks (a macro call's argument, `G65 X1. E1.`, is clean; `G01 X1. E1.` names an
    /// address outside it), an address in lower case (`x1. y2.` after `X1. Y2.`) --
    /// gets its own verdict: the same findings with the verdicts kept as asked afresh, and
    /// the findings the later block has.
    #[test]
    fn a_plain_blocks_addresses_key_holds_what_its_verdict_reads() {
        let program = "%\nG65 I1. I2.\nG01 I1. I2.\nG65 X1. E1.\nG01 X1. E1.\nX1. Y2.\n\
                       x1. y2.\nG02 X1. Y1. I1.\nG18\nG02 X1. Y1. I1.\nM30\n%";
        for config in [of_family(Family::MacroB), iso_mill()] {
            let kept = findings(&config, program, true);
            let afresh = findings(&config, program, false);
            assert_eq!(kept, afresh, "{:?}", config.family);
            if config.family == Family::MacroB {
                for line in [3, 5, 7] {
                    assert!(
                        kept.iter().any(|(_, l, _)| *l == line),
                        "{kept:?}: line {line}"
                    );
                }
            }
        }
    }
}

/// LinuxCNC 2.9: a bare O word is a FANUC-style program's number, which `M98 P..` calls and
/// `M99` closes (interp_read.cc `read_o`, bare O-word: the label is `read_integer_value`'s, a
/// whole number of any size, signed or not, or a parameter or expression of one), no address
/// of the classification's; one with a point (`O300.5`) is no whole number ("Non integer value
/// for integer"), said as an address not classified as before.
fn linuxcnc_program_number(family: crate::lex::Family, w: &Word<'_>) -> bool {
    family == crate::lex::Family::LinuxCnc
        && w.letter == b'O'
        && (!w.expression.is_empty() || !w.number.contains(&b'.'))
}
