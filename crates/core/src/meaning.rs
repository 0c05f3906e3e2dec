//! What a word's number means where a code of the control gives it a meaning of its own: a
//! length, an angle, a direction, a factor or a selector. One table, read by every reader:
//! the converter scales a length with the units and keeps the others as written (through
//! [`crate::convert::cycle_roles`], which the diff and verify reader reads too), and the
//! checker takes none of the others for a position, a radius or a word read in increments.
//!
//! The roles are those of [`Role`]: `Length` (converted with the units), `Other` (an angle in
//! degrees, a direction's component, a scale factor, a time: the number as written) and
//! `Selector` (a whole number that selects a mode or a function: written as it is, and no
//! word a control reads in least input increments). A code not in the table leaves its words
//! to the profile (`checks.pqr`) and to the cycle tables.
//!
//! Sources, by family (docs/convert.md, "Words a code gives another meaning"):
//! - FANUC (Series 16/18/160/180-MC and 30i-B operator's manuals, Custom Macro B; Haas reads the
//!   same where it has the code): `G68 X Y R` (R the rotation angle), its 3D form
//!   `G68 X Y Z I J K R` (I J K the direction of the rotation axis), `G68.2`/`G68.4`
//!   (tilted working plane: X Y Z the feature's origin, I J K Euler or projection angles or a
//!   vector's components by P, P and Q selectors), `G68.3 X Y Z R` (R an angle), `G51 X Y Z I J
//!   K` (I J K each axis's scaling magnification), `G05 P`, `G05.1 Q R`, `G08 P` (high-speed
//!   machining and AI contour control on and off, and their levels), `G07.1 C r` (cylindrical
//!   interpolation: the rotary axis's address carries the cylinder's radius, a length, and the
//!   block moves nothing); `G15`/`G16` polar coordinates, by [`polar_code`] and [`polar_axes`].
//! - Haas mill (the mill operator's manual, "G-codes"): `G187 P E` (smoothness P1-P3, E the
//!   corner rounding, a length), `G47` engraving (P what is engraved, I the text's angle, J its
//!   height), bolt hole patterns `G70 I J L`, `G71 I J K L`, `G72 I J L` (I a radius or a
//!   distance, J a start angle, K an angular spacing). `G268` (feature coordinate system, group
//!   02, named by a public editor's table of the Haas list; its words from the Autodesk Haas
//!   post's `setWorkPlane`): X Y Z the origin (data, no move), I J K angles, Q the rotation
//!   order; any other word of its block `Role::Parameter`.
//! - LinuxCNC (G-code and M-code references): `G10 L2`/`L20 ... R` (the coordinate system's
//!   rotation about Z, degrees), `G10 L1`/`L10`/`L11 ... Q I J` (a lathe tool's orientation
//!   and its front and back angles),
//!   `G33.1 I` (the spindle speed multiplier of the return), `G41.1`/`G42.1 D L` (the cutter's
//!   diameter, a length, and a lathe tool's orientation), `M19 R Q P` (orientation angle,
//!   timeout, direction), `M66 P E L Q` and `M67`/`M68 E Q` (input and output numbers, a wait
//!   mode, a timeout in seconds, an output value), `M61 Q` (the tool number taken as loaded), `M100`-`M199 P Q` (numbers a
//!   user M code's program is passed).
//! - Okuma OSP lathe (OSP-P200L Programming Manual, 5238-E; the threading manual 3277-E):
//!   `G31`-`G33 ... F J` (J the number of threads within F, the lead being F/J), the compound
//!   thread cycles `G71`/`G72 D H L A B J Q`, the LAP cycles' depth of cut (`G84`-`G86 D`,
//!   `G88 D H B`), the M-tool key way cutting `G178 D E` and drilling cycles `G180`-`G189 D L E
//!   J` ([`okuma`]); a word no page at hand explains (the turning tool's `G73`/`G74 D E`, an OSP
//!   mill's cycle `E`, Haas and OSP `M19 R`) is `Role::Parameter`: refused under a change of units.
//! - FANUC lathe: polar coordinate interpolation `G12.1`/`G112` ... `G13.1`/`G113`, under which C
//!   is a length ([`polar_interpolation`]), and `G07.1 H r` (the cylinder's radius by C's
//!   incremental address).
//! - SINUMERIK (Programming Manual Fundamentals, "Inch or metric dimensions: G70/G71" lists what
//!   the units apply to: positions, I J K, CR, the programmable zero offset TRANS/ATRANS, the
//!   polar radius RP; "Frames", "Polar coordinates", "Chamfer, rounding"): its statements, read
//!   by [`sinumerik_statement`].
//!
//! A lathe's G68/G69 (FANUC: mirror image for double turrets, balance cutting) and G15/G16
//! (Haas lathe: the secondary spindle) are other codes: a lathe is left out of those rows.

use crate::lex::Family;
use crate::word::Role;

// A FANUC lathe's G code systems, with the lexer's primitives (every reader asks for them):
// re-exported here, where the codes' meanings are.
pub use crate::lex::{
    system_function, GCodeSystem, ABSOLUTE, INCREMENTAL, NO_CODE, RETURN_INITIAL, RETURN_R_POINT,
};

/// A code as written after its letter (`68.2`, `05.1`, `68`): its whole number and the digits
/// of its fraction as a number (`G68.2` is (68, 2), `G05.1` (5, 1), `G68` and `G68.0` (68, 0)).
/// None for anything but digits with at most one point.
pub fn code(number: &[u8]) -> Option<(i64, u32)> {
    let (whole, fraction) = match number.iter().position(|&c| c == b'.') {
        Some(p) => (&number[..p], &number[p + 1..]),
        None => (number, &b""[..]),
    };
    let kept = fraction.len() - fraction.iter().rev().take_while(|&&c| c == b'0').count();
    let fraction = &fraction[..kept];
    let digits = |d: &[u8]| d.iter().all(u8::is_ascii_digit);
    if whole.is_empty() || whole.len() > 6 || fraction.len() > 3 || !digits(whole) {
        return None;
    }
    if !digits(fraction) {
        return None;
    }
    let n = |d: &[u8]| d.iter().fold(0i64, |n, &c| n * 10 + i64::from(c - b'0'));
    Some((n(whole), n(fraction) as u32))
}

/// The meanings a block's codes give its words.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Meanings {
    /// The role of each letter A-Z that a code of the block gives one; None: the profile's.
    pub roles: [Option<Role>; 26],
    /// The block's axis words are data of its code (a tilted plane's origin, a cylinder's
    /// radius), not a move: `G68.2`, `G68.3`, `G68.4`, `G07.1`.
    pub data: bool,
    /// Q is a thread's start angle in 0.001 deg, 0 to 360000: six whole digits, whatever the
    /// address's format holds (a Fanuc or Haas lathe's G32 and G92 and a block repeating
    /// them, Haas's one-block G76): the cycle tables' (`convert::cycle_table`), not this
    /// module's.
    pub start_angle: bool,
    /// The letters (bit `letter - b'A'`) of [`Meanings::cycle_count`] that measure rather than
    /// count: a time, an angle, a ratio (the cycle tables', `convert::CycleTable`).
    pub measures: u32,
    /// The letters (bit `letter - b'A'`) whose role is no length: asked of every word.
    others: u32,
    /// The letters given a role at all.
    given: u32,
}

impl Meanings {
    fn set(&mut self, letters: &[u8], role: Role) {
        for &l in letters {
            let i = usize::from(l - b'A');
            self.roles[i] = Some(role);
            self.given |= 1 << i;
            if matches!(role, Role::Other | Role::Selector) {
                self.others |= 1 << i;
            } else {
                self.others &= !(1 << i);
            }
        }
    }

    /// The letters (bit `letter - b'A'`) the table itself makes no length (an angle, a
    /// direction, a factor, a selector), whatever a cycle table merged in later says.
    pub fn table_others(&self) -> u32 {
        self.others
    }

    /// Whether a code of the block gives any word a role of its own.
    pub fn any(&self) -> bool {
        self.given != 0
    }

    /// Whether `letter` is a count or an angle of a cycle's table in this block (`G81 K3`
    /// repeats, `G73 R3` divisions, Haas `G76 A60`, `G71 R1`, `G84 J2`): a number the control
    /// reads whole, which the converter keeps as written -- unlike an angle of the meaning
    /// table itself (`G68 R45`, [`Meanings::table_others`]), which a FANUC reads in 0.001 deg.
    /// The one rule the checker (`Checker::selector`) and the diff's reader (ncread.rs) ask.
    pub fn cycle_count(&self, letter: u8) -> bool {
        self.role(letter) == Some(Role::Other) && self.others & 1 << (letter - b'A') == 0
    }

    /// Whether `letter`, a number of a cycle's table ([`Meanings::cycle_count`]), measures: a
    /// time, an angle or a ratio (a drilling cycle's dwell P, a lathe's G32/G92 Q start angle,
    /// Haas G76's A tool nose angle, LinuxCNC G76's Q and R). The control reads it as the
    /// count is read, whole where it has no point, but the diff compares it within its
    /// tolerance, where a count, a block number or a selector is compared exactly (review
    /// 56a F5; issue 32). The one rule the diff's reader (ncread.rs) asks.
    pub fn cycle_measure(&self, letter: u8) -> bool {
        self.cycle_count(letter) && self.measures & 1 << (letter - b'A') != 0
    }

    /// The role a code of the block gives `letter` (upper case), if any.
    pub fn role(&self, letter: u8) -> Option<Role> {
        letter
            .is_ascii_uppercase()
            .then(|| self.roles[usize::from(letter - b'A')])
            .flatten()
    }

    /// Whether `letter`'s number in this block is no length: an angle, a direction, a factor,
    /// a selector (it is never a position nor a radius).
    pub fn not_length(&self, letter: u8) -> bool {
        self.others != 0 && letter.is_ascii_uppercase() && self.others & (1 << (letter - b'A')) != 0
    }
}

/// The meanings the codes of one block give its words, from its words as (address, number
/// as written): `(b'G', b"68.2")`. Families other than Custom Macro B and LinuxCNC have no
/// such code among their words (a SINUMERIK writes them as statements, [`sinumerik_statement`]).
pub fn block<'a, I>(family: Family, lathe: bool, words: I) -> Meanings
where
    I: Iterator<Item = (u8, &'a [u8])> + Clone,
{
    let mut m = Meanings::default();
    if !matches!(family, Family::MacroB | Family::LinuxCnc | Family::Okuma) {
        return m;
    }
    let has = |letter: u8| words.clone().any(|(a, _)| a.to_ascii_uppercase() == letter);
    let value = |letter: u8| {
        words
            .clone()
            .find(|(a, _)| a.to_ascii_uppercase() == letter)
            .and_then(|(_, n)| code(n))
    };
    let (length, other, selector) = (Role::Length, Role::Other, Role::Selector);
    for (address, number) in words.clone() {
        let address = address.to_ascii_uppercase();
        if address != b'G' && address != b'M' {
            continue;
        }
        let Some(c) = code(number) else { continue };
        let g = address == b'G';
        if family == Family::Okuma {
            if g {
                okuma(&mut m, lathe, c);
            } else if c == (19, 0) {
                // M19 R: no OSP page at hand says what R is to the spindle orientation (an
                // angle, as Haas's, is likely, but nothing shows it): unknown, refused under a
                // change of units rather than scaled as a length
                m.set(b"R", Role::Parameter);
            }
            continue;
        }
        if family == Family::MacroB {
            match c {
                (5, 0) if g => m.set(b"P", selector),
                (5, 1) if g => m.set(b"PQR", selector),
                (8, 0) if g => m.set(b"P", selector),
                (7, 1) if g => {
                    // the radius by the rotary axis (C) or, in G code system A, by its
                    // incremental address H (the lathe manual's `G07.1 H57299`)
                    m.set(b"ABC", length);
                    if lathe {
                        m.set(b"H", length);
                    }
                    m.data = true;
                }
                (51, 0) if g && !lathe => m.set(b"IJKP", other),
                (68, 0) if g && !lathe => {
                    m.set(b"R", other);
                    if has(b'I') || has(b'J') || has(b'K') {
                        m.set(b"IJK", other);
                    }
                }
                (68, 2) | (68, 4) if g && !lathe => {
                    m.set(b"IJK", other);
                    m.set(b"PQ", selector);
                    m.data = true;
                }
                (68, 3) if g && !lathe => {
                    m.set(b"R", other);
                    m.data = true;
                }
                // spindle speed fluctuation detection on: P the time in ms before the check
                // starts, Q the tolerance and R the fluctuation in percent of the commanded
                // speed, D the fluctuation in min-1 (FANUC 0i-MF/0i-TF, "Spindle speed
                // fluctuation detection (G25, G26)"): whole numbers, no lengths
                (26, 0) if g => m.set(b"PQRD", selector),
                // polygon turning G51.2 P Q: the spindle's and the tool's rotation ratio, whole
                // numbers (0i-TF, "Polygon turning"); its R is not explained by the pages at
                // hand: refused under a change of units
                (51, 2) if g && lathe => {
                    m.set(b"PQ", selector);
                    m.set(b"R", Role::Parameter);
                }
                (187, 0) if g && !lathe => {
                    m.set(b"P", selector);
                    m.set(b"E", length);
                }
                (47, 0) if g && !lathe => {
                    m.set(b"P", selector);
                    m.set(b"I", other);
                    m.set(b"J", length);
                }
                // Haas mill G268, feature coordinate system on (group 02, a public editor's
                // table of the Haas G-code list). Its words as the Autodesk Haas post writes
                // them (`setWorkPlane`: `G268 X0. Y0. Z0. I0. J-90. K0. Q123`): X Y Z the
                // feature's origin (lengths, data as G68.2's, no move), I J K its angles in
                // degrees, Q the rotation order (123, Euler ZYX), a whole selector. Any other
                // word of the block is no word the post writes: unknown, refused under a
                // change of units (the block's G, M, N and O aside). A FANUC list lacks it.
                (268, 0) if g && !lathe => {
                    m.set(b"ABCDEFHLPRSTUVW", Role::Parameter);
                    m.set(b"IJK", other);
                    m.set(b"Q", selector);
                    m.data = true;
                }
                // M19 R: Haas's spindle orientation angle, by what is known of its manual, but
                // no manual page at hand says so: unknown, refused under a change of units
                (19, 0) if !g => m.set(b"R", Role::Parameter),
                (70 | 72, 0) if g && !lathe => {
                    m.set(b"I", length);
                    m.set(b"J", other);
                }
                (71, 0) if g && !lathe => {
                    m.set(b"I", length);
                    m.set(b"JK", other);
                }
                _ => {}
            }
        } else {
            match (g, c) {
                (true, (10, 0)) => match value(b'L') {
                    Some((2 | 20, 0)) => m.set(b"R", other),
                    Some((1 | 10 | 11, 0)) => {
                        // Q a lathe tool's orientation, I J its front and back angles
                        m.set(b"Q", selector);
                        m.set(b"IJ", other);
                    }
                    _ => {}
                },
                (true, (33, 1)) => m.set(b"I", other),
                (true, (41 | 42, 1)) => {
                    m.set(b"D", length);
                    m.set(b"L", selector);
                }
                (false, (19, 0)) => {
                    m.set(b"RQ", other);
                    m.set(b"P", selector);
                }
                (false, (66, 0)) => {
                    m.set(b"PEL", selector);
                    m.set(b"Q", other);
                }
                (false, (67 | 68, 0)) => {
                    m.set(b"E", selector);
                    m.set(b"Q", other);
                }
                // M61 Q: the number of the tool taken as loaded
                (false, (61, 0)) => m.set(b"Q", selector),
                // a user M code M100-M199 passes P and Q to its program as numbers
                (false, (100..=199, 0)) => m.set(b"PQ", other),
                _ => {}
            }
        }
    }
    m
}

/// The words an Okuma OSP code gives a meaning of its own (OSP-P200L Programming Manual,
/// 5238-E; docs/convert.md, "Words a code gives another meaning"). A word marked
/// `Role::Parameter` is one the manual at hand does not explain for that code: under a change
/// of units the converter refuses it rather than guess whether it is a length.
fn okuma(m: &mut Meanings, lathe: bool, c: (i64, u32)) {
    let (length, other, selector) = (Role::Length, Role::Other, Role::Selector);
    if !lathe {
        // an OSP mill's fixed cycles (G73-G89): E is a dwell on the lathe's drilling cycles,
        // but no mill manual was at hand to say so for the mill
        if matches!(c, (73..=89, 0)) {
            m.set(b"E", Role::Parameter);
        }
        return;
    }
    match c {
        // fixed thread cutting cycles, longitudinal G31/G33 and transverse G32: J the number
        // of threads within the distance F gives (the lead is F/J), a count (5238-E, P-97)
        (31..=33, 0) => m.set(b"J", selector),
        // compound fixed thread cutting cycles G71 (longitudinal) and G72 (end face): D the
        // first cut's depth, H the thread height, L the overcut, lengths; B the cut angle and
        // A the taper angle, degrees; J the threads within F and Q the number of starts,
        // counts (Okuma threading manual 3277-E, P-166 to P-169; okumacnc "G72")
        (71 | 72, 0) => {
            m.set(b"DHL", length);
            m.set(b"AB", other);
            m.set(b"JQ", selector);
        }
        // LAP: G84 (change of cutting conditions), G85 (bar turning), G86 (copy turning): D
        // the depth of cut (5238-E section 8: "D, DA, DB, U, W and H ... incremental values",
        // the rough turning's tool path D/2 deep, P-205)
        (84..=86, 0) => m.set(b"D", length),
        // LAP threading G88: D the first cut, H the thread height, lengths; B the tool tip's
        // angle, degrees
        (88, 0) => {
            m.set(b"DH", length);
            m.set(b"B", other);
        }
        // M-tool key way cutting G178: D the depth of cut per pass and E the infeed, lengths
        // (5238-E section 7, "8-3. Address Characters", P-139)
        (178, 0) => m.set(b"DE", length),
        // M-tool drilling, boring and tapping cycles G180-G189 (P-139): D the depth of cut per
        // peck and L the axis relieving amount of deep-hole drilling, lengths; E the dwell at
        // the end point, a time; J the number of threads, a count
        (180..=189, 0) => {
            m.set(b"DL", length);
            m.set(b"E", other);
            m.set(b"J", selector);
        }
        // automatic chamfering G75 and corner rounding G76 in a G01 block: L the chamfer's
        // size or the corner's radius (the P200L manual's G code list, as NC-PB/gEdit's OSP
        // lathe notes give it: "Automatic chamfer / corner rounding in a G01 block, size in L")
        (75 | 76, 0) => m.set(b"L", length),
        // the turning tool's drilling and grooving cycles G73/G74 (`G73 X Z K D F E`): their
        // D and E are not explained by the pages at hand
        (73 | 74, 0) => m.set(b"DE", Role::Parameter),
        _ => {}
    }
}

/// The polar coordinate command of a FANUC (or Haas) mill: Some(true) for G16, which makes
/// the plane's axis words a radius and an angle until G15, Some(false) for G15. None for any
/// other code, and on a lathe (Haas: G15/G16 swap the spindles) or another family (Okuma's
/// G15 selects a work coordinate system, HEIDENHAIN's G15/G16 are polar moves of their own).
pub fn polar_code(family: Family, lathe: bool, g: i64) -> Option<bool> {
    match g {
        15 | 16 if family == Family::MacroB && !lathe => Some(g == 16),
        _ => None,
    }
}

/// The codes of rs274ngc's motion group (modal group 1), in tenths of a G code (G73 is 730,
/// G71.1 is 711): G0-G3, G5 splines, G33 and G33.1, the probes G38.2-G38.5, the lathe cycles
/// G70-G72, the canned cycles and G80 (interp_array.cc, `_gees`).
pub fn linuxcnc_motion_code(tenths: i64) -> bool {
    matches!(
        tenths,
        0 | 10 | 20 | 30 | 50..=52 | 60..=62 | 330 | 331 | 382..=385 | 700 | 710..=712
            | 720..=722 | 730 | 740 | 760 | 800..=890
    ) && (tenths < 800 || tenths % 10 == 0)
}

/// The codes of modal group 0 that take a block's axis words as their data (G10, G28, G30,
/// G52, G53, G92), in tenths: no motion mode in force runs such a block.
pub fn linuxcnc_takes_axes(tenths: i64) -> bool {
    matches!(tenths, 100 | 280 | 300 | 520 | 530 | 920)
}

/// rs274ngc's message for an E word that no code of its block uses (interp_check.cc
/// `check_other_codes`).
pub const LINUXCNC_E_UNUSED: &str = "E word with no G70, G76, M66, M67 or M68 to use it";

/// Whether rs274ngc lets a block have an E word: its motion (`motion_to_be`, in tenths: the
/// block's motion code, or the mode in force where it moves axes) is G33, G33.1, G70 or G76,
/// or an M66, M67 or M68 of the block (`analog`) reads E as its input or output number.
/// Anywhere else rs274 refuses the whole block: the E word has no meaning to convert.
pub fn linuxcnc_e_used(motion: Option<i64>, analog: bool) -> bool {
    analog || matches!(motion, Some(330 | 331 | 700 | 760))
}

/// rs274ngc's refusal of a D word no code of its block uses (interp_check.cc
/// `check_other_codes`).
pub const LINUXCNC_D_UNUSED: &str =
    "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it";

/// rs274ngc's refusal of an H word no code of its block uses (interp_check.cc
/// `check_other_codes`).
pub const LINUXCNC_H_UNUSED: &str = "H word with no G43 or G76 to use it";

/// Whether rs274ngc lets a block have a D word: its codes (`codes`, in tenths) hold G41,
/// G41.1, G42, G42.1 or G96 (cutter compensation's tool or diameter, G96's speed limit), or
/// its motion (`motion`, in tenths) is a lathe cycle G70-G72 (its depth).
pub fn linuxcnc_d_used(codes: &[i64], motion: Option<i64>) -> bool {
    codes
        .iter()
        .any(|c| matches!(c, 410 | 411 | 420 | 421 | 960))
        || matches!(motion, Some(700 | 710 | 711 | 712 | 720..=722))
}

/// Whether rs274ngc lets a block have an H word: its codes (in tenths) hold G43 or G43.2 (the
/// tool length offset), or its motion is G76 (the spring passes).
pub fn linuxcnc_h_used(codes: &[i64], motion: Option<i64>) -> bool {
    codes.iter().any(|c| matches!(c, 430 | 432)) || motion == Some(760)
}

/// The letters whose word rs274ngc refuses in a block where no code uses it, beside D, E and
/// H ([`linuxcnc_word_used`]): an arc's or cycle's data that a straight move, or a block
/// without motion, does not take.
pub const LINUXCNC_DATA_LETTERS: [u8; 7] = *b"IJKLPQR";

/// rs274ngc's refusal of an I, J, K, L, P, Q or R word no code of its block uses
/// (interp_check.cc `check_other_codes`, as rs274 2.9 words it); "" for another letter.
pub fn linuxcnc_unused(letter: u8) -> &'static str {
    match letter {
        b'I' => "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it",
        b'J' => "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it",
        b'K' => "K word with no G2, G3, G33, G33.1, G76, or G87 to use it",
        b'L' => {
            "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 \
             or NURBS code"
        }
        b'P' => {
            "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 \
             M62 M63 M64 M65 M66 M98 or user M code to use it"
        }
        b'Q' => {
            "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code \
             that uses it"
        }
        b'R' => "R word with no g code that uses it",
        _ => "",
    }
}

/// LinuxCNC's M98 (the FANUC-style call, LinuxCNC 2.8 on) is read where an O word stands:
/// as the block's first word, after its N alone (rs274ngc interp_read.cc `read_o`, which then
/// reads the rest of the line for the call's P and L). Given the block's letters in order
/// (comments and statements before the M98 as a letter other than N), the M98 word's index
/// `m98`: the first word out of place and whether it stands before M98 (rs274 refuses the
/// block, "Unknown m code used: M98": `G1 X10. M98 P100`, `M8 M98 P100`) or after it (a word
/// other than P and L: rs274 refuses it -- "Cannot use axis values without a g code that uses
/// them" for `M98 P100 X5` -- or runs the call alone and not the word: `M98 P100 G1 X10. M8`
/// moves nowhere and turns no coolant on, as `rs274 -g` shows). Review 28, finding 3.
pub fn linuxcnc_m98_stray(letters: &[u8], m98: usize) -> Option<(usize, bool)> {
    if let Some(i) = letters[..m98].iter().position(|&l| l != b'N') {
        return Some((i, true));
    }
    letters
        .get(m98 + 1..)?
        .iter()
        .position(|&l| !matches!(l, b'P' | b'L'))
        .map(|i| (m98 + 1 + i, false))
}

/// Whether rs274ngc lets a block have an I, J, K, L, P, Q or R word (interp_check.cc
/// `check_other_codes`): its G codes (`codes`, in tenths) or M codes (`ms`) use it, or the
/// motion it runs (`motion`, in tenths: its own motion code, or the mode in force where it
/// moves axes; None: no motion) does. I J K: an arc's centre (G2, G3), a spline's (G5, G5.1),
/// G33.1's, G76's and G87's data, G10's tool data; L: G10's data type, cutter compensation's,
/// a canned cycle's repeats, M66's wait type, M98's repeats, NURBS; P: G4's time, an arc's
/// turns, G10's number, G64's tolerance, a cycle's dwell, the M codes'; Q: a peck, a spline's
/// point, G64's, the M codes' data; R: an arc's radius, a cycle's retract plane, G10's and
/// dynamic compensation's, M19's angle. The caller says nothing where the motion is in doubt
/// (after a call or jump it does not follow).
pub fn linuxcnc_word_used(letter: u8, codes: &[i64], ms: &[i64], motion: Option<i64>) -> bool {
    let g = |c: i64| codes.contains(&c);
    let m = |c: i64| ms.contains(&c);
    let runs = |set: &[i64]| motion.is_some_and(|r| set.contains(&r));
    let cycle = motion.is_some_and(|r| matches!(r, 730 | 740 | 810..=890));
    match letter {
        b'I' => g(100) || runs(&[20, 30, 50, 51, 331, 710, 711, 712, 720, 721, 722, 760, 870]),
        b'J' => g(100) || runs(&[20, 30, 50, 51, 760, 870]),
        b'K' => runs(&[20, 30, 330, 331, 760, 870]),
        b'L' => {
            g(100)
                || codes.iter().any(|&c| matches!(c, 410 | 411 | 420 | 421))
                || m(66)
                || m(98)
                || cycle
                || runs(&[52, 760])
        }
        b'P' => {
            g(40)
                || g(100)
                || g(640)
                || ms
                    .iter()
                    .any(|&c| matches!(c, 19 | 50..=53 | 62..=66 | 98 | 100..=199))
                || runs(&[
                    20, 30, 50, 52, 60, 62, 700, 740, 760, 820, 840, 860, 880, 890,
                ])
        }
        b'Q' => {
            g(100)
                || g(640)
                || ms
                    .iter()
                    .any(|&c| matches!(c, 19 | 61 | 66..=68 | 100..=199))
                || runs(&[50, 700, 710, 711, 712, 720, 721, 722, 730, 760, 830])
        }
        b'R' => {
            g(100)
                || g(411)
                || g(421)
                || m(19)
                || cycle
                || runs(&[20, 30, 710, 711, 712, 720, 721, 722, 760])
        }
        _ => true,
    }
}

/// A FANUC lathe's polar coordinate interpolation (FANUC 0i-TF / 30i-TB lathe manuals, "Polar
/// coordinate interpolation (G12.1, G13.1)", in system A also G112/G113): Some(true) for the
/// code that turns it on, Some(false) for the one that turns it off, None for any other. While
/// it is on, the rotary axis's address (C) is the hypothetical axis of a Cartesian plane, a
/// length (the FeatureCAM post reference's `{X<X-COORD>}{C<Y-Coord>}` for a Fanuc 16/18/21),
/// not degrees. From the words of a block as (address, number as written).
pub fn polar_interpolation<'a, I>(family: Family, lathe: bool, words: I) -> Option<bool>
where
    I: Iterator<Item = (u8, &'a [u8])>,
{
    if family != Family::MacroB || !lathe {
        return None;
    }
    let mut found = None;
    for (address, number) in words {
        if !address.eq_ignore_ascii_case(&b'G') {
            continue;
        }
        match code(number) {
            Some((12, 1) | (112, 0)) => found = Some(true),
            Some((13, 1) | (113, 0)) => found = Some(false),
            _ => {}
        }
    }
    found
}

/// Under G16, the plane's first axis is the radius and its second the angle: the modal state
/// machine's ([`crate::modal::polar_axes`], which follows G16/G15 as the one state machine).
pub use crate::modal::polar_axes;

/// One number of a SINUMERIK statement: its byte span in the statement's text, the address
/// it belongs to (`X` of `TRANS X10`; `R` for a radius or a distance given by name, `CR=5`),
/// and whether it is a length.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StatementNumber {
    pub start: usize,
    pub end: usize,
    pub address: u8,
    pub length: bool,
}

/// The numbers of a SINUMERIK statement whose every value is a plain number and whose meaning
/// is documented, or None for any other statement (the converter then refuses a number it
/// holds, as before):
/// - `TRANS`/`ATRANS X Y Z ...`: the programmable zero offset, a length on a linear axis (an
///   offset of A B C is in degrees);
/// - `ROT`/`AROT`/`ROTS`/`AROTS`/`CROTS` (angles, `RPL=` too), `SCALE`/`ASCALE` (factors),
///   `MIRROR`/`AMIRROR` (the axes mirrored): no length;
/// - `CR=` (a circle's radius), `RP=` (the polar radius), `RND=`, `RNDM=`, `CHF=`, `CHR=`
///   (rounding and chamfer): lengths; `AP=` (the polar angle), `AR=` (an arc's opening angle),
///   `ANG=` (a contour's angle): angles, no length.
pub fn sinumerik_statement(text: &[u8]) -> Option<Vec<StatementNumber>> {
    let name_end = text
        .iter()
        .position(|c| !c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    let name = text[..name_end].to_ascii_uppercase();
    let frame = match name.as_slice() {
        b"TRANS" | b"ATRANS" => true,
        b"ROT" | b"AROT" | b"ROTS" | b"AROTS" | b"CROTS" | b"SCALE" | b"ASCALE" | b"MIRROR"
        | b"AMIRROR" => false,
        b"CR" | b"RP" | b"RND" | b"RNDM" | b"CHF" | b"CHR" | b"AP" | b"AR" | b"ANG" => {
            let length = matches!(
                name.as_slice(),
                b"CR" | b"RP" | b"RND" | b"RNDM" | b"CHF" | b"CHR"
            );
            let mut at = skip_blanks(text, name_end);
            if text.get(at) != Some(&b'=') {
                return None;
            }
            at = skip_blanks(text, at + 1);
            let end = number_end(text, at)?;
            if skip_blanks(text, end) != text.len() {
                return None;
            }
            return Some(vec![StatementNumber {
                start: at,
                end,
                address: b'R',
                length,
            }]);
        }
        _ => return None,
    };
    // the frame's words: an axis (X, X1, RPL for a rotation in the plane), '=' or not, a number
    let mut numbers = Vec::new();
    let mut at = skip_blanks(text, name_end);
    while at < text.len() {
        let letters = text[at..]
            .iter()
            .take_while(|c| c.is_ascii_alphabetic())
            .count();
        if letters == 0 {
            return None;
        }
        let address = text[at].to_ascii_uppercase();
        let word = text[at..at + letters].to_ascii_uppercase();
        let axis = letters == 1 && b"XYZUVWABC".contains(&address);
        if !axis && word != b"RPL" {
            return None;
        }
        at += letters;
        // X10 is X's value, X1=10 the value of the axis named X1
        let digits = text[at..].iter().take_while(|c| c.is_ascii_digit()).count();
        let assigned = skip_blanks(text, at + digits);
        if text.get(assigned) == Some(&b'=') {
            at = skip_blanks(text, assigned + 1);
        }
        let end = number_end(text, at)?;
        numbers.push(StatementNumber {
            start: at,
            end,
            address,
            length: frame && axis && b"XYZUVW".contains(&address),
        });
        at = skip_blanks(text, end);
    }
    Some(numbers)
}

/// Whether a SINUMERIK statement is a programmable zero offset (`TRANS`, `ATRANS`), whose
/// values are lengths whatever [`sinumerik_statement`] can read of them.
pub fn sinumerik_shift(text: &[u8]) -> bool {
    let end = text
        .iter()
        .position(|c| !c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    let name = &text[..end];
    name.eq_ignore_ascii_case(b"TRANS") || name.eq_ignore_ascii_case(b"ATRANS")
}

/// The number of a FANUC or Haas corner statement, `,C2.` (a chamfer's length) or `,R1.5` (a
/// rounding's radius), written after a linear move or an arc (FANUC Series 0i-F operator's
/// manuals, "Chamfering and corner R"; Haas mill operator's manual, "Corner rounding and
/// chamfering"): a length, as the axis words beside it. None for any other statement (`,A30.`
/// is an angle) or a value that is no plain number (`,C#1`, `,R[#2/2]`).
pub fn corner_length(text: &[u8]) -> Option<StatementNumber> {
    let (b',', [letter, ..]) = (*text.first()?, text.get(1..)?) else {
        return None;
    };
    let address = letter.to_ascii_uppercase();
    if !matches!(address, b'C' | b'R') {
        return None;
    }
    let start = skip_blanks(text, 2);
    let end = number_end(text, start)?;
    (skip_blanks(text, end) == text.len()).then_some(StatementNumber {
        start,
        end,
        address: b'R',
        length: true,
    })
}

/// The role of each word of an Okuma OSP machining centre's coordinate calculation statement
/// (a hole pattern for the fixed cycle in force), where the sources at hand give it (the
/// OSP's "coordinate calculation function", as docs/dialects.md names it):
/// - `BHC Hp Vp I J K` (bolt hole circle): Hp Vp the circle's centre, I its radius, J the
///   first hole's angle, K the number of holes;
/// - `LAA Hp Vp I K [I K ...] J` (line at angle): Hp Vp the reference point, each I a pitch
///   and its K the number of holes at that pitch, J the line's angle;
/// - `GRDX`/`GRDY Hp Vp I J K P` (grid): Hp Vp the reference point, I and J the pitches along
///   the horizontal and the vertical axis, K and P the numbers of holes along them.
///
/// Hp and Vp are the plane's axis words (X Y, Z X or Y Z, and U V W), lengths in every plane.
/// None for a statement of no other name; Err with the offset of the first word whose role
/// the sources do not give (any word of `ARC`, `SQRX`/`SQRY` but the axes, whose forms were
/// not found), or whose value is no plain number (`X=XPOS`), and why.
pub fn okuma_pattern(text: &[u8]) -> Option<Result<Vec<StatementNumber>, (usize, String)>> {
    let name_end = text
        .iter()
        .position(|c| !c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    let name = text[..name_end].to_ascii_uppercase();
    // the letters that are lengths, and those that are counts or angles, by the statement
    let (lengths, others): (&[u8], &[u8]) = match name.as_slice() {
        b"BHC" => (b"I", b"JK"),
        b"LAA" => (b"I", b"JK"),
        b"GRDX" | b"GRDY" => (b"IJ", b"KP"),
        b"ARC" | b"SQRX" | b"SQRY" => (b"", b""),
        _ => return None,
    };
    let shown = String::from_utf8_lossy(&name).into_owned();
    let mut numbers = Vec::new();
    let mut at = skip_blanks(text, name_end);
    while at < text.len() {
        let address = text[at].to_ascii_uppercase();
        let axis = b"XYZUVW".contains(&address);
        if !address.is_ascii_alphabetic()
            || !(axis || lengths.contains(&address) || others.contains(&address))
        {
            return Some(Err((
                at,
                format!(
                    "the sources at hand do not give the role of {}'s word {} (a length, an \
                     angle or a count)",
                    shown,
                    char::from(text[at])
                ),
            )));
        }
        let start = skip_blanks(text, at + 1);
        let Some(end) = number_end(text, start) else {
            return Some(Err((
                at,
                format!(
                    "{}'s word {} is no plain number (a variable or an expression), whose \
                     units the converter does not follow",
                    shown,
                    char::from(text[at])
                ),
            )));
        };
        numbers.push(StatementNumber {
            start,
            end,
            address,
            length: axis || lengths.contains(&address),
        });
        at = skip_blanks(text, end);
    }
    Some(Ok(numbers))
}

fn skip_blanks(text: &[u8], mut at: usize) -> usize {
    while at < text.len() && matches!(text[at], b' ' | b'\t') {
        at += 1;
    }
    at
}

/// The end of a plain number at `at` (a sign, digits, a point): None where there is none, or
/// where a name, a parameter or an operator follows it (`R1`, `10+R2`).
fn number_end(text: &[u8], at: usize) -> Option<usize> {
    let mut end = at;
    if matches!(text.get(end), Some(b'+' | b'-')) {
        end += 1;
    }
    let start = end;
    let mut point = false;
    while end < text.len() && (text[end].is_ascii_digit() || (text[end] == b'.' && !point)) {
        point |= text[end] == b'.';
        end += 1;
    }
    let digits = text[start..end].iter().any(u8::is_ascii_digit);
    let next = text.get(end).copied();
    let ends = next.is_none_or(|c| matches!(c, b' ' | b'\t'));
    (digits && ends).then_some(end)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(family: Family, lathe: bool, words: &[&str]) -> Meanings {
        let pairs: Vec<(u8, &[u8])> = words
            .iter()
            .map(|w| (w.as_bytes()[0], &w.as_bytes()[1..]))
            .collect();
        block(family, lathe, pairs.iter().copied())
    }

    #[test]
    fn a_code_is_its_number_and_its_fraction() {
        assert_eq!(code(b"68.2"), Some((68, 2)));
        assert_eq!(code(b"05.1"), Some((5, 1)));
        assert_eq!(code(b"68"), Some((68, 0)));
        assert_eq!(code(b"68.0"), Some((68, 0)));
        assert_eq!(code(b"#1"), None);
        assert_eq!(code(b""), None);
    }

    #[test]
    fn fanuc_rotation_tilted_planes_and_selectors() {
        let mill = Family::MacroB;
        let rotation = of(mill, false, &["G68", "X0", "Y0", "R45."]);
        assert_eq!(rotation.role(b'R'), Some(Role::Other));
        assert_eq!(rotation.role(b'I'), None); // the 2D form has no I J K
        assert!(!rotation.data);
        let three_d = of(
            mill,
            false,
            &["G68", "X0", "Y0", "Z0", "I0", "J1", "K0", "R30."],
        );
        assert!(three_d.not_length(b'I') && three_d.not_length(b'K'));
        let tilted = of(
            mill,
            false,
            &["G68.2", "X10.", "Y0", "Z0", "I0.", "J45.", "K0."],
        );
        assert!(tilted.data && tilted.not_length(b'J') && tilted.role(b'X').is_none());
        let ai = of(mill, false, &["G05.1", "Q1"]);
        assert_eq!(ai.role(b'Q'), Some(Role::Selector));
        assert_eq!(
            of(mill, false, &["G05", "P10000"]).role(b'P'),
            Some(Role::Selector)
        );
        assert_eq!(
            of(mill, true, &["G08", "P1"]).role(b'P'),
            Some(Role::Selector)
        );
        let cylinder = of(mill, true, &["G07.1", "C57.3"]);
        assert!(cylinder.data && cylinder.role(b'C') == Some(Role::Length));
        // a lathe's G68 is the double turret's mirror image: no angle
        assert_eq!(of(mill, true, &["G68"]).role(b'R'), None);
        // lower case and another family
        assert_eq!(
            of(mill, false, &["g68", "r45."]).role(b'R'),
            Some(Role::Other)
        );
        assert_eq!(of(Family::Iso, false, &["G68", "R45."]).role(b'R'), None);
    }

    #[test]
    fn a_haas_feature_coordinate_system_has_the_posts_words() {
        let feature = of(
            Family::MacroB,
            false,
            &["G268", "X1.", "Y2.", "Z0", "I0", "J45.", "K0", "Q123", "R1"],
        );
        // X Y Z the origin: data, no move, lengths by their address; I J K angles; Q the
        // rotation order; a word the post never writes unknown
        assert!(feature.data);
        for letter in *b"XYZ" {
            assert_eq!(feature.role(letter), None, "{}", letter as char);
        }
        for letter in *b"IJK" {
            assert_eq!(
                feature.role(letter),
                Some(Role::Other),
                "{}",
                letter as char
            );
            assert!(feature.not_length(letter));
        }
        assert_eq!(feature.role(b'Q'), Some(Role::Selector));
        assert_eq!(feature.role(b'R'), Some(Role::Parameter));
        assert!(!feature.not_length(b'R'));
        assert_eq!(
            of(Family::Okuma, false, &["M19", "R90."]).role(b'R'),
            Some(Role::Parameter)
        );
        assert_eq!(feature.role(b'G'), None);
        assert_eq!(feature.role(b'N'), None);
        // G269 (off) takes none; a lathe has no such code
        assert!(!of(Family::MacroB, false, &["G269"]).any());
        assert!(!of(Family::MacroB, true, &["G268", "X1."]).any());
    }

    #[test]
    fn haas_codes_with_angles_and_selectors() {
        let m = of(Family::MacroB, false, &["G187", "P2", "E0.05"]);
        assert_eq!(
            (m.role(b'P'), m.role(b'E')),
            (Some(Role::Selector), Some(Role::Length))
        );
        let holes = of(Family::MacroB, false, &["G71", "I2.", "J45.", "K30.", "L4"]);
        assert_eq!(holes.role(b'I'), Some(Role::Length));
        assert!(holes.not_length(b'J') && holes.not_length(b'K'));
        let engrave = of(Family::MacroB, false, &["G47", "P0", "I45.", "J0.5"]);
        assert!(engrave.not_length(b'I') && engrave.role(b'J') == Some(Role::Length));
        // a lathe's G71 is the stock removal cycle: the cycle table's
        assert_eq!(of(Family::MacroB, true, &["G71", "I2."]).role(b'I'), None);
    }

    #[test]
    fn linuxcnc_rotation_orientation_and_io_words() {
        let l = Family::LinuxCnc;
        assert_eq!(
            of(l, false, &["G10", "L2", "P1", "R45"]).role(b'R'),
            Some(Role::Other)
        );
        assert_eq!(
            of(l, false, &["G10", "L20", "P1", "R45"]).role(b'R'),
            Some(Role::Other)
        );
        // G10 L1 R is the tool's radius, a length by the profile; its Q an orientation
        let tool = of(l, false, &["G10", "L1", "P1", "R0.5", "Q3"]);
        assert_eq!(
            (tool.role(b'R'), tool.role(b'Q')),
            (None, Some(Role::Selector))
        );
        let comp = of(l, false, &["G41.1", "D0.25", "L3"]);
        assert_eq!(comp.role(b'D'), Some(Role::Length));
        assert!(of(l, false, &["G33.1", "Z-1", "K0.05", "I2"]).not_length(b'I'));
        let wait = of(l, false, &["M66", "P0", "L3", "Q5"]);
        assert!(wait.not_length(b'Q') && wait.not_length(b'P'));
        assert!(of(l, false, &["M19", "R90", "Q2"]).not_length(b'R'));
        assert_eq!(
            of(l, false, &["M61", "Q3"]).role(b'Q'),
            Some(Role::Selector)
        );
        let angles = of(l, true, &["G10", "L1", "P1", "Z0.5", "I80", "J30", "Q2"]);
        assert!(angles.not_length(b'I') && angles.not_length(b'J'));
        assert_eq!(angles.role(b'Z'), None);
        let user = of(l, false, &["M100", "P1.5", "Q2"]);
        assert!(user.not_length(b'P') && user.not_length(b'Q'));
    }

    #[test]
    fn okuma_lathe_thread_cycles_count_their_threads() {
        let o = Family::Okuma;
        let thread = ["G33", "X28.", "Z-20.", "F1.5", "J1", "L1.5"];
        assert_eq!(of(o, true, &thread).role(b'J'), Some(Role::Selector));
        assert_eq!(of(o, false, &thread).role(b'J'), None);
    }

    #[test]
    fn okuma_lathe_chamfer_and_rounding_size_their_corner_by_l() {
        let o = Family::Okuma;
        for code in ["G75", "G76"] {
            let corner = of(o, true, &["G01", code, "X60.", "L2."]);
            assert_eq!(corner.role(b'L'), Some(Role::Length), "{code}");
        }
        // an OSP mill's G76 is another code: no role of the lathe's
        assert_eq!(of(o, false, &["G76", "X60.", "L2."]).role(b'L'), None);
    }

    #[test]
    fn fanuc_fluctuation_detection_and_polygon_turning_take_no_lengths() {
        let f = Family::MacroB;
        let detect = of(f, false, &["G26", "P1000", "Q10", "R5", "D50"]);
        assert!(b"PQRD"
            .iter()
            .all(|&l| detect.role(l) == Some(Role::Selector)));
        let polygon = of(f, true, &["G51.2", "P1", "Q2", "R10."]);
        assert_eq!(polygon.role(b'P'), Some(Role::Selector));
        assert_eq!(polygon.role(b'R'), Some(Role::Parameter));
        // a mill's G51.2 is no code of its list: no role
        assert_eq!(of(f, false, &["G51.2", "P1", "Q2"]).role(b'P'), None);
    }

    #[test]
    fn okuma_lathe_cycles_give_depths_heights_counts_and_dwells() {
        let o = Family::Okuma;
        let lap = of(o, true, &["G85", "D4.", "F0.3", "U0.4", "W0.1"]);
        assert_eq!(lap.role(b'D'), Some(Role::Length));
        assert_eq!(lap.role(b'U'), None); // the profile's: a length
        let thread = of(o, true, &["G88", "H1.083", "B60", "D0.4"]);
        assert_eq!(
            (thread.role(b'H'), thread.role(b'D')),
            (Some(Role::Length), Some(Role::Length))
        );
        assert!(thread.not_length(b'B'));
        let compound = of(
            o,
            true,
            &["G71", "X27.835", "Z-25.", "B60", "H1.083", "J1", "Q2"],
        );
        assert_eq!(compound.role(b'J'), Some(Role::Selector));
        assert_eq!(compound.role(b'Q'), Some(Role::Selector));
        assert_eq!(compound.role(b'H'), Some(Role::Length));
        assert_eq!(
            of(o, true, &["G32", "X10.", "F1.5", "J2"]).role(b'J'),
            Some(Role::Selector)
        );
        let peck = of(o, true, &["G183", "X0", "Z-30.", "D5.", "E0.5", "L1."]);
        assert_eq!(
            (peck.role(b'D'), peck.role(b'L')),
            (Some(Role::Length), Some(Role::Length))
        );
        assert!(peck.not_length(b'E')); // the dwell, seconds
        let keyway = of(o, true, &["G178", "D0.5", "E0.2"]);
        assert_eq!(keyway.role(b'E'), Some(Role::Length)); // the infeed
                                                           // unexplained by the pages at hand: the turning tool's G73, an OSP mill's cycle E
        assert_eq!(
            of(o, true, &["G73", "D4", "E0.14"]).role(b'D'),
            Some(Role::Parameter)
        );
        assert_eq!(
            of(o, false, &["G82", "E0.5"]).role(b'E'),
            Some(Role::Parameter)
        );
        // a mill's G71 is no thread cycle
        assert_eq!(of(o, false, &["G71", "Z5."]).role(b'H'), None);
    }

    #[test]
    fn fanuc_lathe_polar_interpolation_cylinder_h_and_orientation_r() {
        let on = |words: &[&str]| {
            let pairs: Vec<(u8, &[u8])> = words
                .iter()
                .map(|w| (w.as_bytes()[0], &w.as_bytes()[1..]))
                .collect();
            polar_interpolation(Family::MacroB, true, pairs.into_iter())
        };
        assert_eq!(on(&["G12.1"]), Some(true));
        assert_eq!(on(&["G112"]), Some(true));
        assert_eq!(on(&["G13.1"]), Some(false));
        assert_eq!(on(&["G113"]), Some(false));
        assert_eq!(on(&["G12"]), None); // a Haas mill's circular pocket elsewhere
        let mill: Vec<(u8, &[u8])> = vec![(b'G', b"12.1")];
        assert_eq!(
            polar_interpolation(Family::MacroB, false, mill.into_iter()),
            None
        );
        let cylinder = of(Family::MacroB, true, &["G07.1", "H57299"]);
        assert_eq!(cylinder.role(b'H'), Some(Role::Length));
        assert_eq!(of(Family::MacroB, false, &["G07.1", "H1"]).role(b'H'), None);
        assert_eq!(
            of(Family::MacroB, false, &["M19", "R90."]).role(b'R'),
            Some(Role::Parameter)
        );
    }

    #[test]
    fn polar_coordinates_by_plane() {
        assert_eq!(polar_code(Family::MacroB, false, 16), Some(true));
        assert_eq!(polar_code(Family::MacroB, false, 15), Some(false));
        assert_eq!(polar_code(Family::MacroB, true, 16), None);
        assert_eq!(polar_code(Family::Okuma, false, 15), None);
        assert_eq!(polar_axes(17), (b'X', b'Y'));
        assert_eq!(polar_axes(18), (b'Z', b'X'));
        assert_eq!(polar_axes(19), (b'Y', b'Z'));
    }

    #[test]
    fn sinumerik_frames_and_named_values() {
        let numbers = |t: &str| {
            sinumerik_statement(t.as_bytes()).map(|v| {
                v.iter()
                    .map(|n| (t[n.start..n.end].to_string(), n.length))
                    .collect::<Vec<_>>()
            })
        };
        assert_eq!(
            numbers("TRANS X10 Y-2.5 A90"),
            Some(vec![
                ("10".into(), true),
                ("-2.5".into(), true),
                ("90".into(), false)
            ])
        );
        assert_eq!(numbers("ATRANS Z=5"), Some(vec![("5".into(), true)]));
        assert_eq!(numbers("TRANS X1=5"), Some(vec![("5".into(), true)]));
        assert_eq!(numbers("ROT Z45"), Some(vec![("45".into(), false)]));
        assert_eq!(numbers("AROT RPL=30"), Some(vec![("30".into(), false)]));
        assert_eq!(
            numbers("SCALE X2 Y2"),
            Some(vec![("2".into(), false), ("2".into(), false)])
        );
        assert_eq!(numbers("CR=5"), Some(vec![("5".into(), true)]));
        assert_eq!(numbers("RP = 12.5"), Some(vec![("12.5".into(), true)]));
        assert_eq!(numbers("AP=45"), Some(vec![("45".into(), false)]));
        assert_eq!(numbers("TRANS"), Some(vec![]));
        // a value the statement computes, or a statement of no documented meaning: None
        assert_eq!(numbers("TRANS X=R1"), None);
        assert_eq!(numbers("CR=5+R2"), None);
        assert_eq!(numbers("TURN=2"), None);
        assert_eq!(numbers("TRANS X10 TOFRAME"), None);
        assert!(sinumerik_shift(b"TRANS X=R1") && sinumerik_shift(b"atrans"));
        assert!(!sinumerik_shift(b"TRANSMIT(1)") && !sinumerik_shift(b"ROT Z45"));
    }

    #[test]
    fn corner_words_and_okuma_patterns_give_their_numbers_by_role() {
        let corner = |t: &str| corner_length(t.as_bytes()).map(|n| t[n.start..n.end].to_string());
        assert_eq!(corner(",C2."), Some("2.".into()));
        assert_eq!(corner(",r 1.5"), Some("1.5".into()));
        // an angle, and values the text does not give as a number
        assert_eq!(corner(",A30."), None);
        assert_eq!(corner(",C#101"), None);
        assert_eq!(corner(",R[#1/2]"), None);
        let roles = |t: &str| {
            okuma_pattern(t.as_bytes()).map(|r| {
                r.map(|v| {
                    v.iter()
                        .map(|n| (t[n.start..n.end].to_string(), n.length))
                        .collect::<Vec<_>>()
                })
                .map_err(|(at, _)| at)
            })
        };
        let l = |s: &str| (s.to_string(), true);
        let k = |s: &str| (s.to_string(), false);
        assert_eq!(
            roles("BHC X100 Y50 I50 J0 K6"),
            Some(Ok(vec![l("100"), l("50"), l("50"), k("0"), k("6")]))
        );
        assert_eq!(
            roles("LAA X10 Y10 I10 K2 I-25.4 K3 J30"),
            Some(Ok(vec![
                l("10"),
                l("10"),
                l("10"),
                k("2"),
                l("-25.4"),
                k("3"),
                k("30")
            ]))
        );
        assert_eq!(
            roles("GRDY Z5 X0 I20 J-15 K4 P3"),
            Some(Ok(vec![l("5"), l("0"), l("20"), l("-15"), k("4"), k("3")]))
        );
        // undocumented letters, a variable: the offset of the word refused
        assert_eq!(roles("ARC X100 Y50 I50 J0 P30 K4"), Some(Err(13)));
        assert_eq!(roles("SQRX X1 Y1 I2"), Some(Err(11)));
        assert_eq!(roles("BHC X=XPOS Y50 I50 J0 K6"), Some(Err(4)));
        assert_eq!(roles("BHC X1 Y1 I5 J0 K6 R2"), Some(Err(19)));
        assert_eq!(roles("CALL OSUB"), None);
    }
    #[test]
    fn linuxcnc_reads_m98_first_with_its_p_and_l_alone() {
        assert_eq!(linuxcnc_m98_stray(b"MP", 0), None);
        assert_eq!(linuxcnc_m98_stray(b"NMPL", 1), None);
        assert_eq!(linuxcnc_m98_stray(b"GXFMP", 3), Some((0, true)));
        assert_eq!(linuxcnc_m98_stray(b"NMMP", 2), Some((1, true)));
        assert_eq!(linuxcnc_m98_stray(b"MPGX", 0), Some((2, false)));
        assert_eq!(linuxcnc_m98_stray(b"MPLM", 0), Some((3, false)));
    }
}
