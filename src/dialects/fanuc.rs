//! Fanuc-style tilted working plane `G68.2`, `G68.3`, `G68.4`, `G69`: what Fanuc, Mazak,
//! Okuma, Brother, Syntec's G68.2 mode and LinuxCNC's remap accept.
//!
//! Confidence as in [`crate::dialects::sinumerik`].

use crate::vector::{cross, dot};
use crate::{
    angles_from_matrix, elementary, matrix_from_angles, mul, Axis, Convention, Decomposition,
    Error, Frame, Kind, Matrix, Sequence, Vector,
};

/// `G68.2 X Y Z I J K`: the new origin `X Y Z`, then Euler angles `I, J, K` about Z, the new
/// X and the new Z (`F = Rz(I)·Rx(J)·Rz(K)`, intrinsic code 55) \[3rd, strong: four
/// independent implementations agree, one commissioned on a real machine\]. Omitted words
/// are 0. [`g68_2_ordered`] takes LinuxCNC's other Euler orders (`Q`).
///
/// ```
/// use cncrot::dialects::fanuc::g68_2;
/// let f = g68_2([10.0, 0.0, 0.0], [0.0, 30.0, 0.0]); // tilt about X by 30°
/// assert_eq!(f.translation, [10.0, 0.0, 0.0]);
/// assert!((f.rotation[2][1] - 0.5).abs() < 1e-15);
/// ```
pub fn g68_2(origin: Vector, ijk: [f64; 3]) -> Frame {
    Frame::with_translations(
        origin,
        matrix_from_angles(Kind::Intrinsic, Sequence::ZXZ.into(), ijk),
        [0.0; 3],
    )
}

/// `G68.2 Q<order> X Y Z I J K`, LinuxCNC's Euler form in another proper Euler order: `order`
/// the axes of the three rotations as digits (1 X, 2 Y, 3 Z) — 121, 131, 212, 232, 313 (the
/// default, [`g68_2`]) or 323 —, `I, J, K` the angles about them, each about the axis as
/// turned by the ones before (`F = R_q1(I)·R_q2(J)·R_q3(K)`) \[3rd: LinuxCNC's
/// tilted-work-plane remap, `twp_calc_euler_rot_matrix`, the one public implementation; Fanuc's
/// Euler form has no `Q`\]. Another order: [`Error::BadSequence`].
///
/// ```
/// use cncrot::dialects::fanuc::{g68_2, g68_2_ordered};
/// // Q313 is the default order.
/// let f = g68_2_ordered([0.0; 3], 313, [10.0, 20.0, 30.0]).unwrap();
/// assert_eq!(f, g68_2([0.0; 3], [10.0, 20.0, 30.0]));
/// // Q232: I about Y, J about the new Z, K about the new Y; here 90° about Y alone.
/// let g = g68_2_ordered([0.0; 3], 232, [90.0, 0.0, 0.0]).unwrap();
/// assert!((g.rotation[0][2] - 1.0).abs() < 1e-15); // Z' along +X
/// assert!(g68_2_ordered([0.0; 3], 123, [0.0; 3]).is_err()); // not a proper Euler order
/// ```
pub fn g68_2_ordered(origin: Vector, order: i32, ijk: [f64; 3]) -> Result<Frame, Error> {
    if ![121, 131, 212, 232, 313, 323].contains(&order) {
        return Err(Error::BadSequence);
    }
    let (a, b, c) = (order / 100, order / 10 % 10, order % 10);
    let code = crate::AxisCode::new(a | b << 2 | c << 4)?;
    Ok(Frame::with_translations(
        origin,
        matrix_from_angles(Kind::Intrinsic, code, ijk),
        [0.0; 3],
    ))
}

/// The rotation order of a roll-pitch-yaw `Q` word (`G68.2 P1`, Haas `G268`): three
/// different digits naming the fixed axes in the order the rotations are made (1 X, 2 Y,
/// 3 Z); another `Q` is [`Error::BadSequence`].
///
/// ```
/// use cncrot::dialects::fanuc::fixed_order;
/// assert_eq!(fixed_order(321).unwrap(), cncrot::Sequence::ZYX);
/// assert!(fixed_order(313).is_err()); // an Euler order: the P0 form's
/// ```
pub fn fixed_order(q: i32) -> Result<Sequence, Error> {
    if !(111..=333).contains(&q) {
        return Err(Error::BadSequence);
    }
    let digits = [q / 100, (q / 10) % 10, q % 10];
    if !digits.iter().all(|d| (1..=3).contains(d)) {
        return Err(Error::BadSequence);
    }
    let code = digits[0] + 4 * digits[1] + 16 * digits[2];
    match Sequence::from_code(code)? {
        s if !s.is_proper_euler() => Ok(s),
        _ => Err(Error::BadSequence),
    }
}

/// `G68.2 P1 Q<order> X Y Z I J K`, the roll-pitch-yaw form: origin `X Y Z`, then rotations
/// about the fixed (workpiece) axes in the order `Q` names, each by its own letter's angle —
/// `I` about X (roll), `J` about Y (pitch), `K` about Z (yaw) whatever the order; `Q123`:
/// `F = Rz(K)·Ry(J)·Rx(I)`. Sources: the letters tied to their axes and `Q` as the order of
/// the rotations \[doc: Mazak's Fanuc-style supplement, "I: angle of rotation around the
/// X-axis [roll angle]", "q: order of rotations"\]; fixed axes \[3rd: a native LinuxCNC
/// implementation's test (`P1 Q123 I30 J20 K0` is `Ry(20)·Rx(30)`), Haas's `G268` as CAM
/// writes it, and roll-pitch-yaw as robotics names fixed-axis angles\]; LinuxCNC's Python
/// remap alone turns the axes with the rotations. Another order: [`Error::BadSequence`].
///
/// ```
/// use cncrot::dialects::fanuc::g68_2_rpy;
/// // I30 about X, then J20 about the fixed Y: the tool axis (0.2962, -0.5, 0.8138).
/// let f = g68_2_rpy([0.0; 3], 123, [30.0, 20.0, 0.0]).unwrap();
/// let z = [f.rotation[0][2], f.rotation[1][2], f.rotation[2][2]];
/// assert!((z[0] - 20f64.to_radians().sin() * 30f64.to_radians().cos()).abs() < 1e-15);
/// assert!((z[1] + 0.5).abs() < 1e-15);
/// assert!(g68_2_rpy([0.0; 3], 313, [0.0; 3]).is_err());
/// ```
pub fn g68_2_rpy(origin: Vector, order: i32, ijk: [f64; 3]) -> Result<Frame, Error> {
    let s = fixed_order(order)?;
    let angles = s.axes().map(|a| ijk[a.index()]);
    let r = matrix_from_angles(Kind::Extrinsic, crate::AxisCode::from(s), angles);
    Ok(Frame::with_translations(origin, r, [0.0; 3]))
}

/// `I, J, K` of a rotation: J in [0, 180] (as post-processors keep J ≥ 0), I and K in
/// (-180, 180]; at J = 0 or 180 K = 0 (`singular`).
pub fn g68_2_angles(m: &Matrix) -> Result<Decomposition, Error> {
    angles_from_matrix(Convention::new(Kind::Intrinsic, Sequence::ZXZ), m)
}

/// `G68.3 R`: the plane from the tool axis \[doc\]: the new Z is the tool direction `tool`,
/// the new X is `P × Z` with `P` the vertical axis's direction (a machine parameter, +Z on
/// most machines), the new Y is `Z × X`; then `R` turns about the new Z. When the tool is
/// along `P` the cross product vanishes and the new X is the machine's X \[choice\]. A zero
/// or non-finite `tool` or `vertical` is refused ([`Error::Degenerate`]).
///
/// ```
/// use cncrot::dialects::fanuc::g68_3;
/// // Tool tilted about Y: X' = P × Z' lies along +Y.
/// let f = g68_3([1.0, 0.0, 1.0], [0.0, 0.0, 1.0], 0.0).unwrap();
/// assert!((f[1][0] - 1.0).abs() < 1e-15 && (f[0][2] - 0.5f64.sqrt()).abs() < 1e-15);
/// ```
pub fn g68_3(tool: Vector, vertical: Vector, r: f64) -> Result<Matrix, Error> {
    let z = crate::unit_vector(tool)?;
    let p = crate::unit_vector(vertical)?;
    let c = cross(p, z);
    // Along P (a sine of at most MIN_SINE): the machine's X instead.
    let hint = if dot(c, c) > crate::MIN_SINE * crate::MIN_SINE {
        c
    } else {
        [1.0, 0.0, 0.0]
    };
    let f = crate::rotation_from_z_x(z, hint)?;
    Ok(mul(&f, &elementary(Axis::Z, r)))
}

/// The `R` of `G68.3` that gives the rotation `m` (whose Z axis is the tool direction): the
/// turn about Z' from the plane `G68.3` builds with `R = 0` to `m`'s X axis, in (-180, 180].
///
/// ```
/// use cncrot::dialects::fanuc::{g68_3, g68_3_r};
/// let m = g68_3([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 40.0).unwrap();
/// assert!((g68_3_r(&m, [0.0, 0.0, 1.0]).unwrap() - 40.0).abs() < 1e-12);
/// ```
pub fn g68_3_r(m: &Matrix, vertical: Vector) -> Result<f64, Error> {
    let base = g68_3([m[0][2], m[1][2], m[2][2]], vertical, 0.0)?;
    let x = [m[0][0], m[1][0], m[2][0]];
    let bx = [base[0][0], base[1][0], base[2][0]];
    let by = [base[0][1], base[1][1], base[2][1]];
    Ok(crate::math::atan2_deg(dot(x, by), dot(x, bx)))
}

/// `G68.4`: the same words as `G68.2`, applied incrementally on the active plane, in its
/// system: `active · call` \[derived\].
pub fn g68_4(active: &Frame, call: &Frame) -> Frame {
    active.compose(call)
}

/// `G69`: no tilted plane.
pub const G69: Frame = Frame::IDENTITY;

// Program lines.

use super::family::{
    no_selector, put, v3, AxisChoice, Block, Family, Form, FormInfo, FormSpec, Modal, Motion,
    Plane, Positioning, MAX_VALUES,
};
use crate::text::number::{write_word, Out, Style};
use crate::text::scan::{address_words, whole, Comments, Cursor, LineError, Syntax, Tokens};

const SYNTAX: Syntax = crate::text::scan::ISO_WORDS;

/// The vertical axis of the `G68.3` form.
const VERTICAL: Vector = [0.0, 0.0, 1.0];

/// How Fanuc-style controls spell numbers: always with a point (`30.`: without one they read
/// the least input increment unless a parameter says otherwise).
pub(crate) const STYLE: Style = Style {
    plus: false,
    point: true,
};

/// The Fanuc family: `G68.2`, `G68.3`, `G68.4`, `G69`.
pub(crate) struct Fanuc;

/// `G68.2`, `G68.4`, `G69`, `G53.1`/`G53.6` at the cursor (also Syntec's `G68.2` mode):
/// `None` when none of them stands there.
///
/// `G68.2 P0` is the Euler form (as `G68.2` without `P`), with LinuxCNC's `Q` for another
/// proper Euler order ([`g68_2_ordered`]; `G68.4` too); `P1` the roll-pitch-yaw form
/// ([`g68_2_rpy`], `G68.4 P1` incrementally). `P2` (three points), `P3` (two vectors), `P4`
/// (projection angles) and LinuxCNC's `R` are forms whose words the library does not read
/// (their blocks are defined in no text found): such a block is [`Block::NotFollowed`],
/// never a guessed frame. So is `G68.3 X Y Z R`, the plane of the tool direction where the
/// machine stands (its rotary positions are not the program's).
/// `G53.1`/`G53.6 P`: the direction the priority (master) axis turns, kept as the
/// state's choice ([`g53_choice`]).
pub(crate) fn read_g68(m: &Modal, c: &mut Cursor) -> Option<Result<Block, LineError>> {
    let column = c.column();
    let incremental = if c.code(b"G68.2") {
        false
    } else if c.code(b"G68.4") {
        true
    } else if c.code(b"G69") {
        // With other words on the block, the cancel is found among them (`iso_block`); an
        // unclosed comment is malformed text.
        return match c.end(true, true) {
            Ok(()) => Some(Ok(Block::Frame(m.with_frame(G69)))),
            Err(e) if e.error == Error::Parse => Some(Err(e)),
            Err(_) => None,
        };
    } else if let Some((positioning, moves)) = turn_code(c) {
        // Turns the tool to the plane: no frame change.
        let p = g53_words(c, positioning, moves);
        return Some(p.and_then(|(p, column)| {
            let allowed = "P: 0 (shortest), 1 (positive turn) or 2 (negative turn)";
            let choice =
                g53_choice(whole(p, column)?).ok_or(LineError::bad_value(column, allowed))?;
            // A direct mode (Syntec's `G158` mode 2) states the positions themselves: `P`
            // names no solution there; checked, not kept [choice].
            let choice = if m.direct.is_some() { m.choice } else { choice };
            Ok(Block::Frame(Modal {
                positioning,
                choice,
                ..*m
            }))
        }));
    } else if c.code(b"G52") {
        return Some(read_g52(m, c));
    } else if c.code(b"G68.3") {
        return Some(read_g68_3(c));
    } else {
        return None;
    };
    // `F`: the modal feed rate a post may write on the block; not the frame's.
    let words = address_words(c, *b"XYZIJKPQRF", SYNTAX, false, (true, true));
    Some(words.and_then(|w| {
        let form = whole(w.values[6], w.column(6))?;
        if !(0..=4).contains(&form) {
            return Err(LineError {
                error: Error::BadArgument,
                column: w.column(6),
                expected: None,
            });
        }
        if form > 1 || w.given[8] {
            return Ok(Block::NotFollowed);
        }
        let call = if form == 1 {
            // Without `Q`: X, then Y, then Z [choice: the first order of Mazak's list and
            // LinuxCNC's default; a post writing `P1` from a B/C machine's angles means it].
            let order = if w.given[7] {
                whole(w.values[7], w.column(7))?
            } else {
                123
            };
            g68_2_rpy(v3(&w.values, 0), order, v3(&w.values, 3)).map_err(|e| LineError {
                error: e,
                column: w.column(7),
                expected: Some("Q: 123, 132, 213, 231, 312 or 321"),
            })?
        } else if w.given[7] {
            let order = whole(w.values[7], w.column(7))?;
            g68_2_ordered(v3(&w.values, 0), order, v3(&w.values, 3)).map_err(|e| LineError {
                error: e,
                column: w.column(7),
                expected: Some("Q: 121, 131, 212, 232, 313 or 323"),
            })?
        } else {
            g68_2(v3(&w.values, 0), v3(&w.values, 3))
        };
        let tilt = if incremental {
            g68_4(&LineError::at(column, m.tilt_base())?, &call)
        } else {
            call
        };
        Ok(Block::Frame(m.with_tilt(tilt, incremental)))
    }))
}

/// `G68.3 X Y Z R` after its code: the plane of the tool direction where the machine stands,
/// a frame the program does not state (the rotary positions are the machine's): not followed
/// \[choice: never a guessed frame\], its words checked as those of a command the family
/// reads. Not inlined: its words stay out of the reader's frame (stack bound).
#[inline(never)]
fn read_g68_3(c: &mut Cursor) -> Result<Block, LineError> {
    address_words(c, *b"XYZRF", SYNTAX, false, (true, true)).map(|_| Block::NotFollowed)
}

/// `G68` at the cursor (`rest`: the block from the cursor, `block`: the whole block):
///
/// - With `I J K` (Fanuc only, `spatial`): the three-dimensional coordinate conversion
///   \[doc: Fanuc 16i/18i/30i "three-dimensional coordinate conversion"\]: the program's
///   coordinates turn by `R` degrees about the direction `I J K` (any length; right-handed,
///   "clockwise looking along the axis of rotation") through the centre `X Y Z`. A second
///   `G68` converts again in the converted system \[doc\]: here every such `G68` composes on
///   the active tilt, also on a `G68.2` \[choice\]. `I J K` all 0 is `BAD_ARGUMENT` at `I`,
///   a missing `R` a missing word (the control's alarm 5044). A centre not wholly given is
///   the tool's position or the previous conversion's centre, which the state does not
///   keep: not followed \[choice\].
/// - Without: the rotation in the working plane \[doc: "α β: two of X, Y, Z that correspond
///   to the current plane; a positive R is counterclockwise"\]: by `R` about the plane's
///   normal through the centre its two words give (`G17 G68 X Y R`, `G18 G68 Z X R`,
///   `G19 G68 Y Z R`; a plane word on the block selects the plane first). It replaces the
///   rotation in the plane before it (a `G68` again changes centre and angle). Not followed
///   \[choice\]: a centre word missing (the tool's position), no `R` (a parameter's angle), the
///   third axis' word, `G91` on the block (an incremental angle, by a parameter), and an
///   active tilt that is not a rotation in the same plane (how the control composes them is
///   in no text found).
///
/// `None` when no `G68` stands here or (not `spatial`) it has `I J K`: the block is then
/// not followed ([`ISO_NOT_FOLLOWED`]).
pub(crate) fn read_rotation(
    m: &Modal,
    c: &mut Cursor,
    rest: &[u8],
    block: &[u8],
    spatial: bool,
) -> Option<Result<Block, LineError>> {
    let comments = Comments {
        semicolon: true,
        parens: true,
    };
    let ijk = Tokens::new(rest, comments, true).any(|t| matches!(t.letter, b'I' | b'J' | b'K'));
    let column = c.column();
    if (ijk && !spatial) || !c.code(b"G68") {
        return None;
    }
    let (plane, incremental) = plane_words(m, block);
    Some(if ijk {
        conversion(m, c, column)
    } else {
        in_plane(m, c, column, plane, incremental)
    })
}

/// The plane a block selects (its last plane word, else `m`'s) and whether it names `G91`.
fn plane_words(m: &Modal, block: &[u8]) -> (Plane, bool) {
    let comments = Comments {
        semicolon: true,
        parens: true,
    };
    let (mut plane, mut incremental) = (m.plane, false);
    for t in Tokens::new(block, comments, true) {
        if let (b'G', Some(code)) = (t.letter, t.code()) {
            plane = Plane::of_code(code).unwrap_or(plane);
            incremental |= code == 910;
        }
    }
    (plane, incremental)
}

/// A block's result with the plane its words select (`G18 G68.2 …`, `G17 G68 X Y R`): the
/// readers of the commands that start a block take the plane words before them.
pub(crate) fn in_block_plane(
    m: &Modal,
    block: &[u8],
    result: Result<Block, LineError>,
) -> Result<Block, LineError> {
    result.map(|b| match b {
        Block::Frame(next) => Block::Frame(Modal {
            plane: plane_words(m, block).0,
            ..next
        }),
        other => other,
    })
}

/// The three-dimensional conversion of [`read_rotation`] after its code.
fn conversion(m: &Modal, c: &mut Cursor, column: usize) -> Result<Block, LineError> {
    let w = address_words(c, *b"XYZIJKR", SYNTAX, false, (true, true))?;
    if !w.given[6] {
        return Err(c.missing("R"));
    }
    let first = (3..6).find(|&k| w.given.get(k) == Some(&true)).unwrap_or(3);
    let axis = crate::unit_vector(v3(&w.values, 3))
        .map_err(|_| LineError::bad_value(w.column(first), "I J K: a direction, not all 0"))?;
    if !w.given[..3].iter().all(|&g| g) {
        return Ok(Block::NotFollowed);
    }
    let step = Frame::about_point(
        crate::rotation::about_axis(axis, w.values[6]),
        v3(&w.values, 0),
    );
    let base = LineError::at(column, m.tilt_base())?;
    Ok(Block::Frame(m.with_frame(base.compose(&step))))
}

/// The rotation in `plane` of [`read_rotation`] after its code.
fn in_plane(
    m: &Modal,
    c: &mut Cursor,
    column: usize,
    plane: Plane,
    incremental: bool,
) -> Result<Block, LineError> {
    let w = address_words(c, *b"XYZR", SYNTAX, false, (true, true))?;
    let [first, second, normal] = plane.axes();
    let given = |k: usize| w.given.get(k) == Some(&true);
    let tilt = LineError::at(column, m.tilt_base())?;
    // The normal as a vector: a rotation in the same plane leaves it exactly.
    let n: Vector = core::array::from_fn(|k| if k == normal { 1.0 } else { 0.0 });
    let in_the_plane = crate::rotate(&tilt.rotation, n) == n;
    if !(given(first) && given(second) && w.given[3])
        || given(normal)
        || incremental
        || !in_the_plane
    {
        return Ok(Block::NotFollowed);
    }
    let centre: Vector = core::array::from_fn(|k| {
        if k == first || k == second {
            w.values.get(k).copied().unwrap_or(0.0)
        } else {
            0.0
        }
    });
    let turn = crate::elementary(plane.normal(), w.values[3]);
    Ok(Block::Frame(m.with_frame(Frame::about_point(turn, centre))))
}

/// `G53.1` (the rotary axes turn the tool to the plane), `G53.6` (the same, the tool tip
/// kept in place \[3rd: LinuxCNC's remap, "with TCP"; Fanuc's tool center point
/// retention\]) or LinuxCNC's `G53.3` (the turn with a move to `X Y Z` in the plane) at the
/// cursor, and whether the block moves to a point too.
fn turn_code(c: &mut Cursor) -> Option<(Positioning, bool)> {
    if c.code(b"G53.1") {
        Some((Positioning::Turn, false))
    } else if c.code(b"G53.6") {
        Some((Positioning::Move, false))
    } else if c.code(b"G53.3") {
        // LinuxCNC's: "same as G53.1 but with simultaneous move to the XYZ coords on the
        // twp plane" [3rd: its tilted-work-plane remap]; the move is no frame word.
        Some((Positioning::Turn, true))
    } else {
        None
    }
}

/// The words of `G53.1 P` / `G53.6 P H` after the code: `P`'s value (0 when not given) and
/// column. `H` on `G53.6` is the tool length offset whose tool tip stays in place (a
/// generator writes `G53.6 H<tool>` \[3rd\]; Fanuc's tool center point retention needs the
/// tool's length): checked as an offset number (a whole number, 0 or more), not kept (no
/// frame word). Not on `G53.1`, which turns about the pivot.
fn g53_words(
    c: &mut Cursor,
    positioning: Positioning,
    moves: bool,
) -> Result<(f64, usize), LineError> {
    if moves {
        // `G53.3 P X Y Z`: the point moved to in the plane (a move, not kept).
        let w = address_words(c, *b"PXYZ", SYNTAX, false, (true, true))?;
        return Ok((w.values[0], w.column(0)));
    }
    if positioning != Positioning::Move {
        let w = address_words(c, *b"P", SYNTAX, false, (true, true))?;
        return Ok((w.values[0], w.column(0)));
    }
    let w = address_words(c, *b"PH", SYNTAX, false, (true, true))?;
    if w.given[1] && whole(w.values[1], w.column(1))? < 0 {
        return Err(LineError::bad_value(
            w.column(1),
            "H: a tool offset number (0 or more)",
        ));
    }
    Ok((w.values[0], w.column(0)))
}

/// The choice of `G53.1 P<p>` / `G53.6 P<p>` \[3rd: LinuxCNC's tilted-work-plane remap,
/// the one public text with a meaning for `P`: "0 (default) shortest distance, 1 positive
/// rotation only, 2 negative rotation only", of the primary rotary axis, the other axis the
/// shortest way\]: the primary axis taken as the master axis \[choice\]. `None`: another
/// value.
fn g53_choice(p: i32) -> Option<AxisChoice> {
    match p {
        0 => Some(AxisChoice::Closest),
        1 => Some(AxisChoice::PositiveTurn(0)),
        2 => Some(AxisChoice::NegativeTurn(0)),
        _ => None,
    }
}

/// `G53.1` or `G53.6` after a tilt, as `how` says (nothing for [`Positioning::Stay`]), with
/// `P1`/`P2` for a direction of travel of the master axis; the other choices have no word
/// here (not written).
pub(crate) fn g53(how: Motion) -> Option<&'static [u8]> {
    let turn: &[&'static [u8]; 3] = match how.positioning {
        Positioning::Stay => return None,
        Positioning::Turn => &[b"G53.1", b"G53.1 P1", b"G53.1 P2"],
        Positioning::Move => &[b"G53.6", b"G53.6 P1", b"G53.6 P2"],
    };
    Some(match how.choice {
        AxisChoice::PositiveTurn(0) => turn[1],
        AxisChoice::NegativeTurn(0) => turn[2],
        _ => turn[0],
    })
}

/// `G52 X Y Z` after its code: the local coordinate system, a datum shift along the
/// workpiece axes before the tilt; the axes it names are set, the others keep their shift
/// \[choice: as Heidenhain's cycle 7; the manuals cancel with `G52 X0 Y0 Z0`\]; `G52`
/// alone cancels \[choice\]. A `G68.2` that follows tilts about the shifted datum, its
/// own origin taken in the local system \[choice\].
pub(crate) fn read_g52(m: &Modal, c: &mut Cursor) -> Result<Block, LineError> {
    let w = address_words(c, *b"XYZ", SYNTAX, false, (true, true))?;
    let mut shift = m.shift;
    if !w.given.contains(&true) {
        shift = [0.0; 3];
    }
    for ((s, v), given) in shift.iter_mut().zip(w.values).zip(w.given) {
        if given {
            *s = v;
        }
    }
    Ok(Block::Frame(m.with_shift(shift)))
}

/// Skips the modal words a post may write before the tilt on its block (`N50 G90 G68.2 …`,
/// `N30 G0 G90 G68.2 …`): plane selection (kept by [`in_block_plane`]), absolute positions,
/// the cancels of cutter and length compensation and of canned cycles, units, feed per
/// minute, the motion mode (`G0`, `G1`: the tilt's `X Y Z` are its origin, not a move).
/// None of them changes the frame. Whether any was skipped.
pub(crate) fn skip_leading(c: &mut Cursor) -> bool {
    const LEADING: [&[u8]; 15] = [
        b"G17", b"G18", b"G19", b"G90", b"G40", b"G49", b"G80", b"G94", b"G20", b"G21", b"G15",
        b"G0", b"G00", b"G1", b"G01",
    ];
    let mut any = false;
    while LEADING.iter().any(|k| c.code(k)) {
        c.spaces();
        any = true;
    }
    any
}

/// G-codes (in tenths: `G54.1` is 541) that change the frame in ways the library does not
/// follow, in every ISO-style dialect: `G10` (offset tables), `G50`/`G51` (scaling),
/// `G50.1`/`G51.1` (mirroring), `G52` (the local coordinate system, followed where it stands
/// alone: `read_g52`), `G54`–`G59`,
/// `G54.1`, `G54.2` (work offsets, fixture offsets), `G68`/`G69.1` (rotations; Fanuc's and
/// Syntec's `G68` are followed where they start the block and the state knows enough:
/// [`read_rotation`]), `G92`, `G92.1` (coordinate system setting).
pub(crate) const ISO_NOT_FOLLOWED: &[u32] = &[
    100, 500, 501, 510, 511, 520, 540, 541, 542, 550, 560, 570, 580, 590, 680, 691, 920, 921,
];

/// Whether variable `#n` (its number as a code in tenths, `Token::code`) holds a work
/// offset (Fanuc and Haas: `#2500`–`#2999`, `#5201`–`#5335`, `#7001`–`#7999`,
/// `#14001`–`#19999`).
fn offset_variable(code: u32) -> bool {
    code % 10 == 0 && matches!(code / 10, 2500..=2999 | 5201..=5335 | 7001..=7999 | 14001..=19999)
}

/// What a block of an ISO-style program (Fanuc, Haas, Syntec) does when it does not start
/// with a command its family reads: a plane selection (`G17`–`G19`) and a cancel among
/// other words (`cancels`) apply; a command the family reads standing elsewhere
/// (`commands`) is refused at its column, unless the block holds a word not followed (`G54
/// G68.2 …`: then the whole block is not followed); a
/// G-code of [`ISO_NOT_FOLLOWED`] or `more`, or a write to a work-offset variable (or to a
/// variable whose number is computed, `#[5220+1]=`, which may be one), is
/// [`Block::NotFollowed`] (it wins over a cancel on the same block: the library's state is
/// then not the control's either way); anything else is [`Block::Passed`].
#[inline(never)]
pub(crate) fn iso_block(
    m: &Modal,
    text: &[u8],
    commands: &[u32],
    cancels: &[u32],
    more: &[u32],
) -> Result<Block, LineError> {
    let comments = Comments {
        semicolon: true,
        parens: true,
    };
    let (mut cancel, mut not_followed) = (false, false);
    let mut misplaced = None;
    let mut plane = m.plane;
    for t in Tokens::new(text, comments, true) {
        match (t.letter, t.code()) {
            (b'G', Some(code)) if cancels.contains(&code) => cancel = true,
            (b'G', Some(code)) if Plane::of_code(code).is_some() => {
                plane = Plane::of_code(code).unwrap_or(plane)
            }
            (b'G', Some(code)) if commands.contains(&code) => {
                misplaced = misplaced.or(Some(t.column));
            }
            (b'G', Some(code)) if ISO_NOT_FOLLOWED.contains(&code) || more.contains(&code) => {
                not_followed = true
            }
            (b'#', Some(code)) if t.assigned && offset_variable(code) => not_followed = true,
            // A variable whose number is computed (`#[5220+1]=-100.`, as probing and shop
            // macros write the work offsets): it may be one.
            (b'#', None) if t.assigned && t.value.is_empty() => not_followed = true,
            _ => {}
        }
    }
    // A command after a word not followed (`G54 G68.2 …`: a work offset and a tilt in one
    // block) leaves the frame one the library does not follow: the block is not followed as
    // a whole, as a cancel beside one is. Elsewhere it is misplaced.
    if let (Some(column), false) = (misplaced, not_followed) {
        return Err(LineError {
            error: Error::UnknownWord,
            column,
            expected: None,
        });
    }
    Ok(if not_followed {
        Block::NotFollowed
    } else if cancel {
        Block::Frame(Modal {
            plane,
            ..m.with_frame(Frame::IDENTITY)
        })
    } else if plane != m.plane {
        // A plane selection: the frame stays, the rotations in the plane turn otherwise.
        Block::Frame(Modal { plane, ..*m })
    } else {
        Block::Passed
    })
}

/// Writes `G68.2 X Y Z I J K` (Syntec's `G68.2` mode too).
/// `G68.4` with the same words where `relative`: the increment on the active plane.
pub(crate) fn write_g68_2(
    words: &[f64],
    relative: bool,
    decimals: i32,
    out: &mut Out,
) -> Result<(), Error> {
    out.text(if relative { b"G68.4" } else { b"G68.2" });
    for (name, &v) in [b" X", b" Y", b" Z", b" I", b" J", b" K"].iter().zip(words) {
        write_word(out, *name, v, decimals, STYLE)?;
    }
    Ok(())
}

/// `G52 X Y Z` with all three axes (the reader sets the axes a `G52` names, so all three
/// are written; a zero shift is the manuals' own cancel, `G52 X0. Y0. Z0.`).
pub(crate) fn write_g52(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
    out.text(b"G52");
    for (name, &v) in [b" X", b" Y", b" Z"].iter().zip(&shift) {
        write_word(out, *name, v, decimals, STYLE)?;
    }
    Ok(())
}

/// The frame commands a Fanuc-style block may hold among other words (G-codes in tenths,
/// as [`crate::text::scan::Token::code`]), each with the address letters it takes: what
/// [`iso_rest`] leaves out of a block. `G69` takes none (it may stand anywhere).
pub(crate) const FANUC_FRAME_WORDS: &[(u32, &[u8])] = &[
    (682, b"XYZIJKPQR"),
    (684, b"XYZIJKPQR"),
    (680, b"XYZIJKR"),
    (690, b""),
    (531, b"P"),
    (533, b"P"),
    (536, b"PH"),
    (520, b"XYZ"),
];

/// The words of an ISO-style block that are not its frame commands' (`tables`: each
/// command's G-code in tenths with the address letters it takes), appended to `out` as
/// they stand: the motion, feed, compensation and mode words a post writes beside a tilt
/// or a cancel (`G91 G28 Z0.` of `G91 G28 Z0. G69`, `N40 G1 F300.` of `N40 G1 G68.2 …
/// F300.`), comments kept, the blanks around a left-out word made one. A letter a command
/// takes belongs to it up to the next G-code (`F` on a `G68.2` is the feed of the moves
/// that follow: kept). A value after blanks or in brackets (`X 10.`, `J[30.]`) goes with
/// its letter. Whether a word other than the block number is left.
pub(crate) fn iso_rest(text: &[u8], tables: &[&[(u32, &[u8])]], out: &mut Out) -> bool {
    let comments = Comments {
        semicolon: true,
        parens: true,
    };
    let blank = |b: &u8| matches!(b, b' ' | b'\t' | b'\r' | b'\n');
    let (mut from, mut letters, mut words) = (0, &[][..], false);
    // Something written, and blanks left out since: one blank before the next text.
    let (mut written, mut gap) = (false, false);
    let mut put = |segment: &[u8], out: &mut Out, gap: &mut bool| {
        let lead = segment.iter().take_while(|b| blank(b)).count();
        let body = segment.get(lead..).unwrap_or(&[]);
        let trail = body.iter().rev().take_while(|b| blank(b)).count();
        let body = body.get(..body.len() - trail).unwrap_or(&[]);
        if body.is_empty() {
            *gap |= !segment.is_empty();
            return;
        }
        if written && (*gap || lead > 0) {
            out.byte(b' ');
        }
        out.text(body);
        written = true;
        *gap = trail > 0;
    };
    for t in Tokens::new(text, comments, true) {
        let start = t.column - 1;
        // Inside a value left out with its letter (`X [ u. ]`): not a word of its own.
        if start < from {
            continue;
        }
        let command = match (t.letter, t.code()) {
            (b'G', Some(code)) => tables
                .iter()
                .flat_map(|t| t.iter())
                .find(|(c, _)| *c == code)
                .map(|(_, l)| *l),
            _ => None,
        };
        let frame = match command {
            Some(l) => {
                letters = l;
                true
            }
            None if t.letter == b'G' => {
                letters = &[];
                false
            }
            None => letters.contains(&t.letter),
        };
        if !frame {
            words |= t.letter != b'N';
            continue;
        }
        put(text.get(from..start).unwrap_or(&[]), out, &mut gap);
        gap = true;
        from = value_end(text, start + 1 + t.value.len(), t.value.is_empty());
    }
    put(text.get(from..).unwrap_or(&[]), out, &mut gap);
    words
}

/// Where a word's value ends when its token (ending at `end`) has none (`empty`): after
/// blanks, a number or one bracketed constant, as the ISO readers take them.
fn value_end(text: &[u8], end: usize, empty: bool) -> usize {
    if !empty {
        return end;
    }
    let mut k = end;
    while matches!(text.get(k), Some(b' ' | b'\t')) {
        k += 1;
    }
    match text.get(k) {
        // One constant in brackets; a comment or a string opened inside them is the block's
        // (the tokens see it so), and the bracket stays with it.
        Some(b'[') => {
            let rest = text.get(k..).unwrap_or(&[]);
            match rest
                .iter()
                .position(|&c| matches!(c, b']' | b'(' | b'"' | b';'))
            {
                Some(p) if rest.get(p) == Some(&b']') => k + p + 1,
                _ => end,
            }
        }
        Some(b'+' | b'-' | b'.' | b'0'..=b'9') => {
            k += 1;
            while matches!(text.get(k), Some(b'.' | b'0'..=b'9')) {
                k += 1;
            }
            k
        }
        _ => end,
    }
}

/// Fanuc's five-axis programs: `G43.4` (tool centre point, rotary positions `A B C`) and
/// `G43.5` (the tool direction `I J K`) switch the transformation on, `G49` off \[doc\];
/// `G90`/`G91`; arcs, `G28`/`G30` and `G53` moves are not followed.
pub(crate) const FANUC_PATH: super::family::PathWords = super::family::iso_path(
    &[
        super::family::PathCommand::Code(b'G', 434),
        super::family::PathCommand::Code(b'G', 435),
    ],
    [b"I", b"J", b"K"],
);

impl Family for Fanuc {
    const TOOL_PATH: Option<&'static super::family::PathWords> = Some(&FANUC_PATH);
    const MAX_LINE: usize = 256;
    const KEEPS_SHIFT: bool = true;
    const FORMS: &'static [FormInfo] = &[
        FormInfo {
            form: Form::G68_2,
            words: 6,
            origin: true,
            writable: true,
        },
        FormInfo {
            form: Form::G68_3,
            words: 7,
            origin: true,
            writable: true,
        },
    ];

    fn rest(text: &[u8], out: &mut Out) -> bool {
        iso_rest(text, &[FANUC_FRAME_WORDS], out)
    }

    /// One block of a Fanuc-style program: `G68.2 X Y Z I J K` (omitted words are 0; a new
    /// `G68.2` replaces the active plane \[choice\]), `G68.4` (the same, on the active
    /// plane), `G68 X Y Z I J K R` (the 3-D coordinate conversion), `G69` (cancel), `G53.1`/`G53.6` (no frame change), `G68.3` (the plane of
    /// the tool direction where the machine stands, a frame the program does not state: not
    /// followed, its words checked), with a block number, `/`,
    /// `( … )` and `;`. Numbers without a point are whole units (calculator-type input
    /// \[choice: a parameter of the control; write the point to be safe\]). These commands
    /// start the block (after its number); `G69` may stand among other words. Every other
    /// block is passed over, or not followed if it changes the frame otherwise
    /// ([`ISO_NOT_FOLLOWED`], work-offset variables).
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        if c.peek() == Some(b'%') {
            c.bump();
        }
        c.block_number(b'N');
        if let Some(result) = read_g68(m, &mut c) {
            return result;
        }
        let rest = text.get(c.column() - 1..).unwrap_or(&[]);
        if let Some(result) = read_rotation(m, &mut c, rest, text, true) {
            return result;
        }
        if skip_leading(&mut c) {
            if let Some(result) = read_g68(m, &mut c) {
                return in_block_plane(m, text, result);
            }
            let rest = text.get(c.column() - 1..).unwrap_or(&[]);
            if let Some(result) = read_rotation(m, &mut c, rest, text, true) {
                return in_block_plane(m, text, result);
            }
        }
        iso_block(m, text, &[682, 683, 684, 531, 533, 536], &[690], &[])
    }

    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        if !c.keyword(b"G68.2") {
            return Err(Error::BadArgument);
        }
        c.spaces();
        if !c.at_end() {
            return Err(Error::BadArgument);
        }
        Ok(FormSpec {
            form: Form::G68_2,
            selector: 0,
        })
    }

    /// `G69`; none while the axes turn to the untilted plane (`G68.2` of zeros, then
    /// `G53.1`: `G69` turns nothing).
    fn write_cancel(_: &FormSpec, how: Motion, _: i32, out: &mut Out) -> Result<bool, Error> {
        if how.positioning != Positioning::Stay {
            return Ok(false);
        }
        out.text(b"G69");
        Ok(true)
    }

    /// `G68.2 X Y Z I J K`, numbers always with a point.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        match spec.form {
            // The block has no words for the solution: `G53.1` turns the axes.
            Form::G68_2 => write_g68_2(words, how.relative, decimals, out),
            _ => Err(Error::BadArgument),
        }
    }

    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        write_g52(shift, decimals, out)
    }

    fn positioning_block(_: &FormSpec, how: Motion) -> Option<&'static [u8]> {
        g53(how)
    }

    /// `G68.4`: the words of `G68.2`, on the active plane.
    fn relative_form(spec: &FormSpec) -> Option<FormSpec> {
        (spec.form == Form::G68_2).then_some(*spec)
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        no_selector(selector)?;
        match form {
            Form::G68_2 => Ok(g68_2(v3(words, 0), v3(words, 3))),
            Form::G68_3 => {
                // `get`, not indexing: the length is checked by the caller, but the no-panic
                // proof (c_tests/no_panic.sh) must see that no path can panic.
                let angle = words.get(3).copied().ok_or(Error::BadArgument)?;
                let r = g68_3(v3(words, 4), VERTICAL, angle)?;
                Ok(Frame::with_translations(v3(words, 0), r, [0.0; 3]))
            }
            _ => Err(Error::BadArgument),
        }
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        no_selector(selector)?;
        let (m, t) = (&frame.rotation, frame.translation);
        match form {
            Form::G68_2 => {
                let d = g68_2_angles(m)?;
                put(out, 0, t);
                put(out, 3, d.angles);
                Ok(d.singular)
            }
            Form::G68_3 => {
                let r = g68_3_r(m, VERTICAL)?;
                put(out, 0, t);
                put(out, 4, [m[0][2], m[1][2], m[2][2]]);
                if let Some(slot) = out.get_mut(3) {
                    *slot = r;
                }
                Ok(false)
            }
            _ => Err(Error::BadArgument),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialects::close;

    #[test]
    fn g68_2_is_intrinsic_zxz_and_round_trips() {
        let f = g68_2([1.0, 2.0, 3.0], [30.0, 45.0, 60.0]);
        let expect = mul(
            &mul(&elementary(Axis::Z, 30.0), &elementary(Axis::X, 45.0)),
            &elementary(Axis::Z, 60.0),
        );
        assert!(close(&f.rotation, &expect, 1e-15));
        let d = g68_2_angles(&f.rotation).unwrap();
        assert!(d.angles[1] >= 0.0);
        assert!(close(
            &g68_2([0.0; 3], d.angles).rotation,
            &f.rotation,
            2e-15
        ));
        // A tilt with J < 0 reads back with J ≥ 0 (I and K turned by 180°).
        let g = g68_2([0.0; 3], [0.0, -30.0, 0.0]).rotation;
        let d = g68_2_angles(&g).unwrap();
        assert!((d.angles[1] - 30.0).abs() < 1e-12 && (d.angles[0].abs() - 180.0).abs() < 1e-12);
    }

    #[test]
    fn g68_3_builds_the_plane_from_the_tool_axis() {
        for t in [
            [1.0, 2.0, 3.0],
            [0.0, -1.0, 0.2],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -4.0],
        ] {
            let f = g68_3(t, [0.0, 0.0, 1.0], 25.0).unwrap();
            assert!(crate::orthonormality_error(&f) < 1e-15 && crate::determinant(&f) > 0.0);
            let z = crate::unit_vector(t).unwrap();
            assert!((0..3).all(|i| (f[i][2] - z[i]).abs() < 1e-15), "{t:?}");
        }
        // Along P: X' is the machine's X (then R about Z').
        let f = g68_3([0.0, 0.0, 2.0], [0.0, 0.0, 1.0], 0.0).unwrap();
        assert_eq!(f, crate::IDENTITY);
        assert_eq!(
            g68_3([0.0; 3], [0.0, 0.0, 1.0], 0.0),
            Err(Error::Degenerate)
        );
        assert_eq!(
            g68_3([0.0, 0.0, 1.0], [f64::NAN, 0.0, 1.0], 0.0),
            Err(Error::Degenerate)
        );
    }

    /// The threshold itself: a tool at a sine of exactly `MIN_SINE` from the vertical is
    /// along it (X' the machine's X), at twice that it is not (X' = P × Z' along +Y).
    #[test]
    fn g68_3_along_the_vertical_below_min_sine() {
        let p = [0.0, 0.0, 1.0];
        let at = g68_3([crate::MIN_SINE, 0.0, 1.0], p, 0.0).unwrap();
        assert!(
            (at[0][0] - 1.0).abs() < 1e-15 && at[1][0].abs() < 1e-15,
            "{at:?}"
        );
        let off = g68_3([2.0 * crate::MIN_SINE, 0.0, 1.0], p, 0.0).unwrap();
        assert!(
            (off[1][0] - 1.0).abs() < 1e-15 && off[0][0].abs() < 1e-15,
            "{off:?}"
        );
    }

    #[test]
    fn g68_4_is_incremental_and_g69_cancels() {
        let a = g68_2([0.0; 3], [0.0, 30.0, 0.0]);
        let b = g68_2([0.0; 3], [0.0, 15.0, 0.0]);
        let c = g68_4(&a, &b);
        assert!(close(
            &c.rotation,
            &g68_2([0.0; 3], [0.0, 45.0, 0.0]).rotation,
            1e-15
        ));
    }
}
