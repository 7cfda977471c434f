//! Heidenhain TNC: the tilted working plane `PLANE` in its forms `SPATIAL`, `EULER`,
//! `VECTOR`, `POINTS`, `PROJECTED`, `RELATIV` and `RESET`, the inverse of each form that can
//! express a plane (what a writer of a measured plane needs), and its program lines.
//!
//! Confidence as in [`crate::dialects::sinumerik`]: **\[doc\]**, **\[3rd\]**, **\[derived\]**,
//! **\[choice\]**.

use crate::{
    angles_from_matrix, matrix_from_angles, Axis, Convention, Decomposition, Error, Frame, Kind,
    Matrix, Sequence, Vector,
};

/// `PLANE SPATIAL SPA SPB SPC`: about the fixed machine axes, A then B then C \[doc\]:
/// `F = Rz(SPC)·Ry(SPB)·Rx(SPA)` (extrinsic X, Y, Z, exactly the paper's probe angles).
///
/// ```
/// use cncrot::dialects::heidenhain::spatial;
/// // PLANE SPATIAL SPA45 SPB0 SPC90: F = [0 -0.707107 0.707107; 1 0 0; 0 0.707107 0.707107].
/// let f = spatial([45.0, 0.0, 90.0]);
/// assert!(f[0][0] == 0.0 && f[1][0] == 1.0 && (f[2][2] - 0.707107).abs() < 1e-6);
/// ```
pub fn spatial(spa_spb_spc: [f64; 3]) -> Matrix {
    matrix_from_angles(Kind::Extrinsic, Sequence::XYZ.into(), spa_spb_spc)
}

/// `SPA, SPB, SPC` of a rotation: SPB in [-90, 90], SPA and SPC in (-180, 180]; at SPB = ±90
/// only SPA ∓ SPC is determined and SPC = 0 (the last rotation's angle is the free one,
/// `singular`) [choice: the control's own choice between the two solutions follows `SEQ`
/// and the machine's axes; this is the canonical one].
pub fn spatial_angles(m: &Matrix) -> Result<Decomposition, Error> {
    angles_from_matrix(Convention::new(Kind::Extrinsic, Sequence::XYZ), m)
}

/// `PLANE EULER EULPR EULNU EULROT`: `F = Rz(EULPR)·Rx(EULNU)·Rz(EULROT)` (intrinsic Z, X', Z'')
/// \[doc\].
///
/// ```
/// use cncrot::dialects::heidenhain::euler;
/// // PLANE EULER EULPR45 EULNU20 EULROT22: first row (0.406706, -0.880966, 0.241845).
/// let f = euler([45.0, 20.0, 22.0]);
/// assert!((f[0][0] - 0.406706).abs() < 1e-6 && (f[0][1] + 0.880966).abs() < 1e-6);
/// ```
pub fn euler(pr_nu_rot: [f64; 3]) -> Matrix {
    matrix_from_angles(Kind::Intrinsic, Sequence::ZXZ.into(), pr_nu_rot)
}

/// `EULPR, EULNU, EULROT` of a rotation: EULNU in [0, 180]; at EULNU = 0 or 180 EULROT = 0.
pub fn euler_angles(m: &Matrix) -> Result<Decomposition, Error> {
    angles_from_matrix(Convention::new(Kind::Intrinsic, Sequence::ZXZ), m)
}

/// `PLANE VECTOR BX BY BZ NX NY NZ`: `N` is the new Z axis, `B` the new X axis; neither need
/// be of unit length \[doc\]. The manual's own example is not orthogonal (B·N = -0.349) and
/// the control's correction is not documented: `N` is kept and `B` projected onto the plane
/// normal to it \[choice\]. A zero `N`, or `B` parallel to `N` (a sine of at most
/// [`crate::MIN_SINE`]), is refused ([`Error::Degenerate`]).
///
/// ```
/// use cncrot::dialects::heidenhain::vector;
/// let f = vector([1.0, 0.0, 0.5], [0.0, 0.0, 2.0]).unwrap(); // B tilted: only its X part counts
/// assert_eq!(f, cncrot::IDENTITY);
/// ```
pub fn vector(b: Vector, n: Vector) -> Result<Matrix, Error> {
    crate::rotation_from_z_x(n, b)
}

/// `B` and `N` of a rotation (unit vectors: the new X and Z axes).
pub fn vector_of(m: &Matrix) -> (Vector, Vector) {
    ([m[0][0], m[1][0], m[2][0]], [m[0][2], m[1][2], m[2][2]])
}

/// `PLANE POINTS P1 P2 P3`: the new X axis from P1 to P2, the new Z axis
/// `(P2 − P1) × (P3 − P1)` (so P3 lies on the positive-Y side), `Y = Z × X` \[doc\]; the frame's
/// origin is not moved (the control tilts about the active datum) \[doc\]. Coincident or
/// collinear points (a sine of at most [`crate::MIN_SINE`] at P1) are refused
/// ([`Error::Coincident`], [`Error::Collinear`]). Other controls' three-point rules
/// (TwinCAT CNC turns the new Z to positive z) can give the opposite tool axis for the same
/// points.
///
/// ```
/// use cncrot::dialects::heidenhain::points;
/// let f = points([0.0; 3], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]).unwrap();
/// assert!((f[0][0] - 0.5f64.sqrt()).abs() < 1e-15 && (f[2][2] - 1.0).abs() < 1e-15);
/// ```
pub fn points(p1: Vector, p2: Vector, p3: Vector) -> Result<Matrix, Error> {
    let a: Vector = core::array::from_fn(|k| p2[k] - p1[k]);
    let b: Vector = core::array::from_fn(|k| p3[k] - p1[k]);
    if !a.iter().chain(&b).all(|v| v.is_finite()) {
        return Err(Error::OutOfRange);
    }
    if a == [0.0; 3] || b == [0.0; 3] {
        return Err(Error::Coincident);
    }
    // Y' is the direction to P3 made perpendicular to X', so Z' = X' × Y' is along
    // (P2 − P1) × (P3 − P1).
    crate::rotation_from_x_y(a, b).map_err(|_| Error::Collinear)
}

/// `PLANE RELATIV SPA|SPB|SPC angle`: one incremental spatial angle, about the axis of the
/// plane already tilted: `F_new = F_active·R_axis(angle)` \[derived\].
pub fn relativ(active: &Frame, axis: Axis, angle: f64) -> Frame {
    active.compose(&Frame::from_rotation(crate::elementary(axis, angle)))
}

/// `PLANE PROJECTED PROPR PROMIN PROROT`: the plane's line in the ZX plane makes the angle
/// PROPR with X (a turn about Y), its line in the YZ plane the angle PROMIN with Y (a turn
/// about X), X' lies on the first line, and PROROT turns about the new tool axis [doc
/// wording];
/// so `PROPR` and `PROMIN` are SINUMERIK's projection angles `ROTS Y=PROPR X=PROMIN`:
/// `F = Ry(PROPR)·Rx(γ)·Rz(ROT)`, `tan γ = tan PROMIN · cos PROPR` [derived; the signs,
/// right-handed about +Y and +X, are our choice: the manual's figures show no sign].
///
/// ```
/// use cncrot::dialects::heidenhain::projected;
/// use cncrot::{elementary, Axis};
/// assert_eq!(projected([0.0, 30.0, 0.0]), elementary(Axis::X, 30.0));
/// ```
pub fn projected([propr, promin, rot]: [f64; 3]) -> Matrix {
    super::sinumerik::projection(Sequence::XYZ, [promin, propr, rot])
}

/// `PROPR PROMIN PROROT` of a rotation: the inverse of [`projected`]; refused like the
/// projection mode of CYCLE800 when X' has turned onto Z with the plane turned about it
/// ([`Error::OutOfRange`]).
pub fn projected_angles(m: &Matrix) -> Result<Decomposition, Error> {
    let d = super::sinumerik::projection_angles(Sequence::XYZ, m)?;
    let [promin, propr, rot] = d.angles;
    Ok(Decomposition {
        angles: [propr, promin, rot],
        singular: d.singular,
    })
}

/// `PLANE RESET`: no tilt.
pub const RESET: Frame = Frame::IDENTITY;

// Program lines.

use super::family::{
    no_selector, put, v3, AxisChoice, Block, Direct, DirectAxes, Family, Feed, Form, FormInfo,
    FormSpec, Modal, Motion, Positioning, Retract, MAX_VALUES,
};
use crate::text::number::{write_word, Out, Style};
use crate::text::scan::{Comments, Cursor, Exponent, LineError, Syntax, Token, Tokens};

// A comma for the decimal point, as posts written for one put it (`CYCL DEF 19.1 A-8,182 B+0,
// C-90,`): no word of the blocks read here has a comma of another meaning [choice].
const SYNTAX: Syntax = Syntax {
    exponent: Exponent::None,
    ends: b";",
    comma: true,
    iso: false,
};

/// The words of one `PLANE` form, each required, in any order.
fn plane_words<const N: usize>(
    c: &mut Cursor,
    names: [&'static [u8]; N],
) -> Result<[f64; N], LineError> {
    let (values, given) = named_words(c, names)?;
    if given.contains(&false) {
        let first = given.iter().position(|g| !g).and_then(|k| names.get(k));
        let name = first.and_then(|n| core::str::from_utf8(n).ok());
        return Err(not_there(c, name.unwrap_or("a word of the plane")));
    }
    Ok(values)
}

/// The words `names` in any order, each at most once: their values and which were given.
fn named_words<const N: usize>(
    c: &mut Cursor,
    names: [&'static [u8]; N],
) -> Result<([f64; N], [bool; N]), LineError> {
    let mut values = [0.0; N];
    let mut given = [false; N];
    loop {
        c.spaces();
        let column = c.column();
        let hit = names.iter().position(|n| c.word(n));
        let Some(k) = hit else {
            return Ok((values, given));
        };
        if given.get(k).copied().unwrap_or(true) {
            return Err(LineError {
                error: Error::UnknownWord,
                column,
                expected: None,
            });
        }
        c.spaces();
        let v = c.number(SYNTAX)?;
        if let (Some(slot), Some(g)) = (values.get_mut(k), given.get_mut(k)) {
            *slot = v;
            *g = true;
        }
    }
}

/// A word `what` is missing at the cursor if what follows is the line's end or the
/// positioning options; anything else standing there is a word the command does not have
/// (`SPX+10`).
fn not_there(c: &Cursor, what: &'static str) -> LineError {
    if options(&mut c.clone()).is_ok() {
        c.missing(what)
    } else {
        c.error(Error::UnknownWord)
    }
}

/// How a `PLANE` moves the machine: `STAY` tilts the plane without moving; `TURN`, `MOVE`
/// turn the rotary axes (`MOVE` keeping the tool tip), after the retraction (`MB MAX`,
/// `MB n`; CYCLE800's retraction along the machine's Z as `MB MAX` \[choice: the nearest
/// `PLANE` has\]), at rapid (`FMAX`) or a feed (`F n`, `F AUTO`).
fn write_positioning(how: Motion, decimals: i32, out: &mut Out) -> Result<(), Error> {
    out.text(match how.positioning {
        Positioning::Stay => {
            out.text(b" STAY");
            return Ok(());
        }
        Positioning::Turn => b" TURN",
        Positioning::Move => b" MOVE",
    });
    let style = Style {
        plus: false,
        point: false,
    };
    match how.retract {
        Retract::None => {}
        Retract::Tool => write_word(out, b" MB", how.retract_mm, decimals, style)?,
        Retract::ToolMax | Retract::MachineZ | Retract::MachineZThenXy => out.text(b" MB MAX"),
    }
    match how.feed {
        Feed::Rapid => out.text(b" FMAX"),
        Feed::Rate => write_word(out, b" F", how.feed_mm_min, decimals, style)?,
        Feed::Auto => out.text(b" F AUTO"),
    }
    Ok(())
}

/// A `PLANE`'s words after its positioning: `SEQ±` names the master axis' sign; another
/// axis cannot be named on the block. A direction of travel (`G53.1 P1`) has no word here:
/// not written, as `SEQ` is not on a `G68.2` \[choice\]. Then `TABLE ROT`.
fn write_choice(how: Motion, out: &mut Out) -> Result<(), Error> {
    match how.choice {
        AxisChoice::Closest | AxisChoice::PositiveTurn(0) | AxisChoice::NegativeTurn(0) => {}
        AxisChoice::Minus(0) => out.text(b" SEQ-"),
        AxisChoice::Plus(0) => out.text(b" SEQ+"),
        _ => return Err(Error::NotAvailable),
    }
    if how.table_rot {
        out.text(b" TABLE ROT");
    }
    Ok(())
}

/// An increment on the active plane of spatial angles `SPA SPB SPC` (`words`): `PLANE
/// RELATIV` takes one angle, about the axis already turned, so `Rz(SPC)·Ry(SPB)·Rx(SPA)` is
/// three blocks, `SPC`, then `SPB`, then `SPA`; an angle written as 0 is left out (one block
/// at least), the blocks before the last stay where they are, the last moves as `how` says.
/// Not inlined: its locals stay out of the frame of every `PLANE` written (stack bound).
#[inline(never)]
fn write_relativ(words: &[f64], how: Motion, decimals: i32, out: &mut Out) -> Result<(), Error> {
    let &[a, b, c] = words else {
        return Err(Error::BadArgument);
    };
    let steps: [(&[u8], f64); 3] = [(b" SPC", c), (b" SPB", b), (b" SPA", a)];
    let given = |&(_, v): &(&[u8], f64)| !crate::text::number::writes_zero(v, decimals);
    let last = steps.iter().rposition(given).unwrap_or(2);
    let style = Style {
        plus: true,
        point: false,
    };
    let mut first = true;
    for (k, step) in steps.iter().enumerate() {
        if k != last && !given(step) {
            continue;
        }
        if !first {
            out.byte(b'\n');
        }
        first = false;
        out.text(b"PLANE RELATIV");
        write_word(out, step.0, step.1, decimals, style)?;
        if k == last {
            write_positioning(how, decimals, out)?;
            return write_choice(how, out);
        }
        out.text(b" STAY");
    }
    Ok(())
}

/// The rest of a `PLANE AXIAL` block. Not inlined: its state stays out of the reader's
/// frame (stack bound).
#[inline(never)]
fn axial(m: &Modal, c: &mut Cursor) -> Result<Block, LineError> {
    // Incremental (`IB+15`): "the angle by which the axis is to be tilted from its current
    // position", which the program does not state.
    let mut ahead = c.clone();
    ahead.spaces();
    if ahead.peek() == Some(b'I') {
        return Ok(Block::NotFollowed);
    }
    let (direct, positions) = axial_words(c)?;
    let how = options(c)?;
    // The positions are the solution: `SEQ` has nothing to choose.
    Ok(Block::Frame(Modal {
        positioning: how.positioning,
        retract: how.retract,
        retract_mm: how.retract_mm,
        feed: how.feed,
        feed_mm_min: how.feed_mm_min,
        ..m.with_direct([0.0; 3], direct, positions)
    }))
}

/// `PLANE AXIAL`'s words: the positions of the rotary axes `A`, `B`, `C`, in any order, at
/// least one, each once \[doc\]; the axes not named stay at 0 \[choice: the control may
/// keep them where they are\].
fn axial_words(c: &mut Cursor) -> Result<(Direct, [f64; 3]), LineError> {
    let (positions, given) = named_words(c, [b"A", b"B", b"C"])?;
    if !given.contains(&true) {
        return Err(not_there(c, "A, B or C"));
    }
    let d = Direct {
        by: DirectAxes::Letters,
        given: given
            .iter()
            .enumerate()
            .fold(0, |m, (k, &g)| m | (u8::from(g) << k)),
    };
    Ok((d, positions))
}

/// What may follow the plane's words: how to position (`MOVE`, `TURN`, `STAY`, `MB MAX`,
/// `MB n`, `DIST n`, `FMAX`, `F n`, `F AUTO`) and which solution (`SEQ±`, `SYM±`,
/// `TABLE ROT`, `COORD ROT`): they choose motion and machine axes, not the plane. Returns
/// the positioning (`STAY` when none is written \[choice: the control asks for one\]) and
/// the solution `SEQ±` chooses: the master axis at a positive (`+`) or negative angle, as
/// the higher or lower of the pair \[doc\]; `SYM±`, the master axis on that side of its
/// symmetry point, the same for a symmetry point at 0 \[choice\]. `MB MAX` / `MB n` (n > 0
/// mm; `MB0` none) and `FMAX` / `F n` (n > 0 mm/min) / `F AUTO` are kept (the program
/// state drops them with `STAY`, which moves nothing); `DIST n` (also `ABST n`: the pivot's
/// distance from the tool tip for `MOVE`) is read and not kept. `TABLE ROT` turns a free
/// rotary table to the plane, `COORD ROT` (and no word) the coordinate system alone, the
/// table not moved \[doc: "COORD ROT … the rotary table is not moved; the compensation is
/// purely mathematical", "TABLE ROT … position the rotary table to the defined tilting
/// angle"\]; kept even with `STAY` (it says where the axes go, not whether they move now).
fn options(c: &mut Cursor) -> Result<Motion, LineError> {
    let mut how = Motion::default();
    loop {
        c.spaces();
        if c.rest_is_comment(true, false) {
            c.end(true, false)?;
            return Ok(how);
        }
        let positioning = [
            (&b"MOVE"[..], Positioning::Move),
            (b"TURN", Positioning::Turn),
            (b"STAY", Positioning::Stay),
        ];
        if let Some(&(_, p)) = positioning.iter().find(|(k, _)| c.keyword(k)) {
            how.positioning = p;
            continue;
        }
        if c.keyword(b"FMAX") {
            (how.feed, how.feed_mm_min) = (Feed::Rapid, 0.0);
            continue;
        }
        let table = c.keyword(b"TABLE");
        if table || c.keyword(b"COORD") {
            c.spaces();
            if !c.keyword(b"ROT") {
                return Err(c.missing("ROT"));
            }
            how.table_rot = table;
            continue;
        }
        if c.word(b"SEQ") || c.word(b"SYM") {
            how.choice = match c.peek() {
                Some(b'+') => AxisChoice::Plus(0),
                Some(b'-') => AxisChoice::Minus(0),
                _ => return Err(c.missing("'+' or '-'")),
            };
            c.bump();
            continue;
        }
        if c.word(b"MB") {
            c.spaces();
            if c.keyword(b"MAX") {
                (how.retract, how.retract_mm) = (Retract::ToolMax, 0.0);
                continue;
            }
            let (column, mb) = (c.column(), c.number(SYNTAX)?);
            (how.retract, how.retract_mm) = match mb {
                0.0 => (Retract::None, 0.0),
                d if d > 0.0 => (Retract::Tool, d),
                _ => return Err(LineError::bad_value(column, "MB: MAX or a length >= 0")),
            };
            continue;
        }
        if c.word(b"F") {
            c.spaces();
            if c.keyword(b"AUTO") {
                (how.feed, how.feed_mm_min) = (Feed::Auto, 0.0);
                continue;
            }
            let (column, f) = (c.column(), c.number(SYNTAX)?);
            // Written so that NaN refuses.
            (how.feed, how.feed_mm_min) = match f {
                f if f > 0.0 => (Feed::Rate, f),
                _ => return Err(LineError::bad_value(column, "F: AUTO or a feed rate > 0")),
            };
            continue;
        }
        // `ABST`: the German dialog's word for the same distance [choice: accepting it
        // refuses nothing the control accepts; no manual page was found for it].
        if c.word(b"DIST") || c.word(b"ABST") {
            c.spaces();
            c.number(SYNTAX)?;
            continue;
        }
        return Err(c.error(Error::UnknownWord));
    }
}

/// The frame of a `PLANE` form's words: what the reader and `form_frame` both compute.
fn plane_frame(form: Form, w: &[f64]) -> Result<Frame, Error> {
    let rot = Frame::from_rotation;
    Ok(match form {
        Form::PlaneSpatial => rot(spatial(v3(w, 0))),
        Form::PlaneEuler => rot(euler(v3(w, 0))),
        Form::PlaneVector => rot(vector(v3(w, 0), v3(w, 3))?),
        // The points give the plane's orientation only: the control tilts about the active
        // datum and does not move it to P1 [doc].
        Form::PlanePoints => rot(points(v3(w, 0), v3(w, 3), v3(w, 6))?),
        Form::PlaneProjected => rot(projected(v3(w, 0))),
        _ => return Err(Error::BadArgument),
    })
}

/// The datum shifts a program writes before its `PLANE` (CAM output: `CYCL DEF 7.0 DATUM
/// SHIFT`, `CYCL DEF 7.1 X+10`, `7.2 Y+5`, `7.3 Z-3`; `TRANS DATUM AXIS X+10 Y+5 Z-3`,
/// `TRANS DATUM RESET`), or `None` for any other block. Cycle 7's first line only names the
/// cycle (applied: the state unchanged); each further line sets the axes it names (`IX`
/// adds to the shift), the others keep theirs \[doc: "only the programmed axes are
/// shifted"\]; `TRANS DATUM AXIS` sets the shift of the axes it names \[choice: the same
/// rule\]. The shift is taken along the workpiece axes, and a `PLANE` tilts about the shifted
/// datum \[doc\]; programmed under a tilt, along the tilted axes (the TNC 620 manual lists
/// cycle 7 "shifting before tilting the working plane" among the workpiece system's
/// transformations, the TNC7's working plane system takes `TRANS DATUM` "after having
/// tilted the working plane" \[doc\]), then held in the workpiece axes (it stays where it
/// was put when the plane is cancelled \[choice\]).
/// A datum table row (`#5`, `TRANS DATUM TABLE`) or another axis (`A`, `U`) is not
/// followed, nor is a shift under a direct mode (`PLANE AXIAL`: its tilted axes are the
/// machine's); an axis written twice is refused.
fn datum_shift(m: &Modal, c: &mut Cursor) -> Result<Option<Block>, LineError> {
    // `keyword` takes only what it matches: a block that is no `CYCL DEF` still has its
    // `TRANS` at the cursor.
    let cycle = if let Some((number, line)) = cycle_def(c) {
        if number != 7 {
            return Ok(None);
        }
        if line == 0 {
            // `7.0 DATUM SHIFT` (in the program's language) only names the cycle: part of
            // the datum shift, the state unchanged.
            return Ok(Some(Block::Frame(*m)));
        }
        true
    } else if c.keyword(b"TRANS") {
        c.spaces();
        if !c.keyword(b"DATUM") {
            return Ok(None);
        }
        c.spaces();
        if c.keyword(b"RESET") {
            c.end(true, false)?;
            return Ok(Some(Block::Frame(m.with_shift([0.0; 3]))));
        }
        if !c.keyword(b"AXIS") {
            return Ok(None);
        }
        false
    } else {
        return Ok(None);
    };
    // Under a tilt, along the tilted axes: the shift as the tilted axes see it, each axis
    // the block names set there, then back in the workpiece axes.
    // Under a direct mode (`PLANE AXIAL`) the tilted axes are the machine's: not known here.
    if m.direct.is_some() {
        return Ok(Some(Block::NotFollowed));
    }
    let tilted = m.frame.rotation != crate::IDENTITY;
    let r = m.frame.rotation;
    let mut shift = if tilted {
        crate::rotate_inverse(&r, m.shift)
    } else {
        m.shift
    };
    let mut any = false;
    let mut seen = [false; 3];
    loop {
        c.spaces();
        if c.rest_is_comment(true, false) {
            c.end(true, false)?;
            break;
        }
        let column = c.column();
        let incremental = c.peek() == Some(b'I');
        if incremental {
            c.bump();
        }
        let axis = match c.peek() {
            Some(b'X') => 0,
            Some(b'Y') => 1,
            Some(b'Z') => 2,
            // A datum table row, a rotary or parallel axis: not followed.
            Some(b'A'..=b'Z') => return Ok(Some(Block::NotFollowed)),
            _ if cycle || any => return Ok(Some(Block::NotFollowed)),
            _ => return Err(c.missing("X, Y or Z")),
        };
        // An axis twice (`X+10 X+20`) is the control's error, not a value to pick.
        if seen.get(axis).copied().unwrap_or(true) {
            return Err(LineError {
                error: Error::UnknownWord,
                column,
                expected: None,
            });
        }
        if let Some(s) = seen.get_mut(axis) {
            *s = true;
        }
        c.bump();
        let v = c.number(SYNTAX)?;
        if let Some(s) = shift.get_mut(axis) {
            *s = if incremental { *s + v } else { v };
        }
        any = true;
    }
    if !any {
        return Err(c.missing("X, Y or Z"));
    }
    if tilted {
        shift = crate::rotate(&r, shift);
    }
    if !shift.iter().all(|x| x.is_finite()) {
        return Err(c.error(Error::OutOfRange));
    }
    Ok(Some(Block::Frame(m.with_shift(shift))))
}

/// `CYCL DEF n.k` at the cursor: the cycle's number `n` and the line `k` of its definition
/// (the cursor after them), or `None` (the cursor anywhere) when no cycle definition with a
/// line number stands there (`CYCL DEF 200 DRILLING` has none).
fn cycle_def(c: &mut Cursor) -> Option<(u32, u32)> {
    if !c.keyword(b"CYCL") {
        return None;
    }
    c.spaces();
    if !c.keyword(b"DEF") {
        return None;
    }
    c.spaces();
    let digits = |c: &mut Cursor| {
        let mut n: Option<u32> = None;
        while let Some(d) = c.peek().filter(u8::is_ascii_digit) {
            n = Some(
                n.unwrap_or(0)
                    .saturating_mul(10)
                    .saturating_add(u32::from(d - b'0')),
            );
            c.bump();
        }
        n
    };
    let number = digits(c)?;
    if c.peek() != Some(b'.') {
        return None;
    }
    c.bump();
    Some((number, digits(c)?))
}

/// Whether `block` is the first line of a cycle definition the reader follows (`CYCL DEF
/// 7.0 DATUM SHIFT`, `CYCL DEF 19.0 WORKING PLANE`, after a block number): it only names the
/// cycle, whose next lines set it. A translation into Heidenhain that rewrites those lines
/// writes its own first line, so it must not keep this one as well.
///
/// ```
/// use cncrot::dialects::heidenhain::cycle_head;
/// assert!(cycle_head(b"12 CYCL DEF 19.0 WORKING PLANE"));
/// assert!(!cycle_head(b"13 CYCL DEF 19.1 B+30") && !cycle_head(b"CYCL DEF 200 DRILLING"));
/// ```
pub fn cycle_head(block: &[u8]) -> bool {
    let mut c = Cursor::new(block);
    past_block_number(&mut c);
    matches!(cycle_def(&mut c), Some((7 | 19, 0)))
}

/// An `L` block that moves only rotary axes to the positions the active tilt left in
/// `Q120`–`Q122` (`L A+Q120 C+Q122 R0 FMAX M126`, `L B+Q121 C+Q122 F MAX`): the turn to
/// the plane that CAM output writes after `PLANE … STAY` and cycle 19 \[doc: `STAY` "saves
/// the positions in Q120 to Q122", to be approached in a separate positioning block\].
/// Each letter with its own parameter (A Q120, B Q121, C Q122), besides them only `R0`, the
/// feed (`FMAX`, `F MAX`, `F n`, `F AUTO`) and M functions (`M126`/`M127`: which way a
/// rotary axis turns; `M3`, `M8`: switched at the block's start, kept by a translator as
/// the block's rest). Returns the feed, or `None` for any other block (an `L` with `X`,
/// another parameter: passed over as a move). Not inlined (stack bound).
#[inline(never)]
fn turn_to_plane(c: &mut Cursor) -> Option<(Feed, f64)> {
    if !c.keyword(b"L") {
        return None;
    }
    let mut feed = (Feed::Rapid, 0.0);
    let mut rotary = false;
    loop {
        c.spaces();
        if c.at_end() || c.rest_is_comment(true, false) {
            return rotary.then_some(feed);
        }
        let letters = [(&b"A"[..], &b"Q120"[..]), (b"B", b"Q121"), (b"C", b"Q122")];
        if let Some(&(_, q)) = letters.iter().find(|(l, _)| c.word(l)) {
            if c.peek() == Some(b'+') {
                c.bump();
            }
            if !c.code(q) {
                return None;
            }
            rotary = true;
        } else if c.keyword(b"FMAX") {
            feed = (Feed::Rapid, 0.0);
        } else if c.word(b"F") {
            c.spaces();
            feed = if c.keyword(b"MAX") {
                (Feed::Rapid, 0.0)
            } else if c.keyword(b"AUTO") {
                (Feed::Auto, 0.0)
            } else {
                match c.number(SYNTAX) {
                    Ok(f) if f > 0.0 => (Feed::Rate, f),
                    _ => return None,
                }
            };
        } else if c.word(b"M") {
            // An M function (`M126`: which way the rotary axes turn; `M3`, `M8`: the spindle,
            // the coolant, switched at the block's start): the block still turns the axes.
            match c.number(SYNTAX) {
                Ok(m) if m >= 0.0 && m == crate::math::round(m) => {}
                _ => return None,
            }
        } else if !c.code(b"R0") {
            // A word beyond the turn's (R0 changes nothing).
            return None;
        }
    }
}

/// Moves the cursor past a block's start: the block skip mark (`/81 M30`: the block runs
/// while block skip is off, as every dialect's reader takes it) and the block number.
fn past_block_number(c: &mut Cursor) {
    c.spaces();
    if c.peek() == Some(b'/') {
        c.bump();
        c.spaces();
    }
    while c.peek().is_some_and(|b| b.is_ascii_digit()) {
        c.bump();
    }
    c.spaces();
    // The skip mark after the number, where the TNC shows it (`12 /L X+0`).
    if c.peek() == Some(b'/') {
        c.bump();
        c.spaces();
    }
}

/// Cycle 19, WORKING PLANE (`CYCL DEF 19.0 WORKING PLANE`, then `CYCL DEF 19.1 A+0 B+45
/// C+0`), or `None` for any other block. The first line only names the cycle (the state
/// unchanged). The second sets the plane \[doc\]: `A`, `B`, `C` in any order, each at most
/// once, those not written 0 \[choice: as every dialect's examples leave out zero words;
/// posts write only the machine's axes\]; it replaces the active tilt, keeping the datum
/// shift \[choice: the cycle has no incremental form\]. What the angles are is a machine
/// parameter \[doc: iTNC 530 MP7500 bit 1\]: spatial angles by default, the same rotation as
/// `PLANE SPATIAL SPA SPB SPC` \[doc: "the function corresponds to Cycle 19 if the entries in
/// Cycle 19 are set to spatial angles"\] \[choice: the default, as the only reading whose
/// plane follows from the block\]; with [`Modal::axis_angles`] the positions of the rotary
/// axes named so, a direct mode as `PLANE AXIAL`. After the angles, `F n` (the feed for the
/// automatic positioning: the axes then turn \[derived\]), `FMAX`, `MB`, `DIST`/`ABST`, and
/// the `PLANE` options. A second line without angles (`CYCL DEF 19.1`, how a program
/// switches the cycle off after setting every angle to 0 \[doc\]) cancels the tilt. Not
/// inlined: its state stays out of the reader's frame (stack bound).
#[inline(never)]
fn working_plane(m: &Modal, c: &mut Cursor) -> Result<Option<Block>, LineError> {
    let Some((19, line)) = cycle_def(c) else {
        return Ok(None);
    };
    if line == 0 {
        return Ok(Some(Block::Frame(*m)));
    }
    if line != 1 {
        return Err(c.error(Error::UnknownWord));
    }
    let (angles, given) = named_words(c, [b"A", b"B", b"C"])?;
    let mut how = options(c)?;
    if how.positioning == Positioning::Stay && how.feed == Feed::Rate {
        how.positioning = Positioning::Turn;
    }
    let next = if !given.contains(&true) {
        m.with_frame(RESET)
    } else if m.axis_angles {
        let given = given
            .iter()
            .enumerate()
            .fold(0, |bits, (k, &g)| bits | (u8::from(g) << k));
        let d = Direct {
            by: DirectAxes::Letters,
            given,
        };
        m.with_direct([0.0; 3], d, angles)
    } else {
        m.with_frame(Frame::from_rotation(spatial(angles)))
    };
    Ok(Some(Block::Frame(Modal {
        choice: how.choice,
        positioning: how.positioning,
        retract: how.retract,
        retract_mm: how.retract_mm,
        feed: how.feed,
        feed_mm_min: how.feed_mm_min,
        ..next
    })))
}

/// A Heidenhain block (from its first word, after the block number) that is not a `PLANE`:
/// not followed when it shifts, mirrors, rotates, scales or tilts the coordinate system or
/// selects or writes a datum (`CYCL DEF` 7 datum shift, 8 mirror image, 10 rotation, 11 and
/// 26 scaling, 19 working plane, 247 datum setting; the probing cycles that set a datum or
/// a basic rotation, `TCH PROBE 400`–`419` and `1400`–`1499`; `TRANS` datum, mirror and
/// rotation functions; `PRESET`; `FN 17: SYSWRITE`); passed over otherwise (`L`, `C`, `CC`, `TOOL
/// CALL`, `CYCL DEF` of machining cycles, `CALL`, `LBL`, `FN` arithmetic, `Q` parameters,
/// `M` functions, `BEGIN`/`END PGM`, `BLK FORM`, `FUNCTION`, …).
#[inline(never)]
fn other_block(text: &[u8]) -> Block {
    let comments = Comments {
        semicolon: true,
        parens: false,
    };
    let mut t = Tokens::new(text, comments, false);
    let (first, second) = (t.next(), t.next());
    let is = |t: Option<Token>, name: &[u8]| t.is_some_and(|t| t.is(name));
    // A cycle or function number (`7.0` is cycle 7's first line): its whole part.
    let integer = |t: Option<Token>| t.and_then(|t| t.code()).map(|c| c / 10);
    let third = t.next();
    let cycle = is(first, b"CYCL") && is(second, b"DEF");
    let frame_cycle = cycle && matches!(integer(third), Some(7 | 8 | 10 | 11 | 19 | 26 | 247));
    // The probing cycles that set a datum or a basic rotation by what they measure (400–419;
    // the TNC7's 1400s): "If you enter Q305=0, the TNC automatically sets the display so
    // that the new datum is at the center of the pocket" (iTNC 530 cycle 412).
    let probe = is(first, b"TCH")
        && is(second, b"PROBE")
        && matches!(integer(third), Some(400..=419 | 1400..=1499));
    let syswrite = is(first, b"FN17") || (is(first, b"FN") && integer(second) == Some(17));
    if frame_cycle || probe || is(first, b"TRANS") || is(first, b"PRESET") || syswrite {
        Block::NotFollowed
    } else {
        Block::Passed
    }
}

/// The Heidenhain family: `PLANE`.
pub(crate) struct Heidenhain;

/// Heidenhain's five-axis programs: `M128` or `FUNCTION TCPM …` on, `M129` or
/// `FUNCTION RESET TCPM` off \[doc\]; `L` blocks with rotary positions `A B C`, `LN` blocks with
/// the tool vector `TX TY TZ` \[doc\]; under `FUNCTION TCPM … AXIS SPAT` the `A B C` of `L`
/// blocks are spatial angles, as `PLANE SPATIAL`'s `SPA SPB SPC` \[doc: TNC7 user's manual,
/// "FUNCTION TCPM with AXIS SPAT" among the functions that compute with spatial angles;
/// derived: the tool direction `Rz(C)·Ry(B)·Rx(A)·e_z`\]; `IX`… incremental; circles (`C`,
/// `CR`, `CT`, `CP`) and moves in machine coordinates (`M91`, `M92`) not followed.
pub(crate) const HEIDENHAIN_PATH: super::family::PathWords = {
    use super::family::PathCommand::{Code, Name, Phrase};
    super::family::PathWords {
        iso: false,
        spaced: true,
        ex: false,
        on: &[Code(b'M', 1280), Phrase(&[b"FUNCTION", b"TCPM"])],
        off: &[Phrase(&[b"FUNCTION", b"RESET", b"TCPM"])],
        vector: [b"TX", b"TY", b"TZ"],
        angles: None,
        rpy: &[],
        euler: &[],
        incremental: &[],
        absolute: &[],
        spatial: &[Phrase(&[b"AXIS", b"SPAT"])],
        positions: &[Phrase(&[b"AXIS", b"POS"])],
        i_prefix: true,
        moves: &[b"L", b"LN"],
        arcs: &[
            // Machine coordinates for the block.
            Code(b'M', 910),
            Code(b'M', 920),
            // A rounding or a chamfer between two blocks: the corner, not the end point.
            Name(b"RND"),
            Name(b"CHF"),
            // What moves the coordinates the points are read in.
            Phrase(&[b"CYCL", b"DEF", b"DATUM"]),
            Phrase(&[b"TRANS", b"DATUM"]),
            Name(b"PLANE"),
        ],
        // Every contour block names its kind (`L`, `C`, `CR`): no modal mode.
        circular: &[],
        linear: &[],
        canned: &[],
        canned_off: &[],
        still: &[],
        // "M128 becomes effective at the start of block, M129 at the end of block" (TNC
        // 426/430 user's manual).
        off_after: &[Code(b'M', 1290)],
        // Circles, polar, approach and departure and FK contours (an end point the reader
        // does not compute, stated or not), cycle and program calls, the retraction of
        // `M140`, probing (moves of its own, a datum it may set).
        loses: &[
            Name(b"C"),
            Name(b"CR"),
            Name(b"CT"),
            Name(b"CP"),
            Name(b"LP"),
            Name(b"APPR"),
            Name(b"DEP"),
            Name(b"FL"),
            Name(b"FLT"),
            Name(b"FC"),
            Name(b"FCT"),
            Name(b"FPOL"),
            Phrase(&[b"CYCL", b"CALL"]),
            Code(b'M', 990),
            Code(b'M', 890),
            Phrase(&[b"CALL", b"PGM"]),
            Phrase(&[b"CALL", b"LBL"]),
            Phrase(&[b"CALL", b"SELECTED"]),
            Code(b'M', 20),
            Code(b'M', 300),
            Code(b'M', 1400),
            Phrase(&[b"TCH", b"PROBE"]),
            Phrase(&[b"END", b"PGM"]),
        ],
        unread: &[],
        compensation: &[Name(b"RL"), Name(b"RR")],
        compensation_off: &[Code(b'R', 0)],
        // Mirror, rotation and scaling cycles (8, 10, 11, 26), a reference point other than
        // the tip.
        altering: &[
            Phrase(&[b"CYCL", b"DEF", b"MIRROR"]),
            Phrase(&[b"CYCL", b"DEF", b"ROTATION"]),
            Phrase(&[b"CYCL", b"DEF", b"SCALING"]),
            Phrase(&[b"REFPNT", b"CENTER-CENTER"]),
            Phrase(&[b"REFPNT", b"TIP-CENTER"]),
        ],
        unaltering: &[],
        offsets: &[Phrase(&[b"CYCL", b"DEF", b"DATUM", b"SETTING"])],
        inch: &[Name(b"INCH")],
        metric: &[Name(b"MM")],
    }
};

/// The M functions of a block (after its line number, before its comment) as they stand,
/// joined by a blank, the rotary axes' `M126`/`M127` left out (no other control has them:
/// a machine parameter there), when the block is the turn to the plane or holds nothing
/// else; whether one was written. What a translator keeps of a turn block: `M3` of
/// `L B+Q121 C+Q122 R0 FMAX M3`.
fn m_functions(text: &[u8], out: &mut Out) -> bool {
    let mut c = Cursor::new(text);
    past_block_number(&mut c);
    let start = c.column().saturating_sub(1);
    let turn = turn_to_plane(&mut c).is_some();
    let code = text.get(start..).unwrap_or(&[]);
    let code = code.split(|&b| b == b';').next().unwrap_or(&[]);
    let words = || {
        code.split(|b| b.is_ascii_whitespace())
            .filter(|w| !w.is_empty())
    };
    let m_word = |w: &[u8]| {
        w.len() > 1
            && matches!(w.first(), Some(b'M' | b'm'))
            && w.iter().skip(1).all(u8::is_ascii_digit)
    };
    if !(turn || words().all(m_word)) {
        return false;
    }
    let kept = |w: &[u8]| {
        let digits = w.get(1..).unwrap_or(&[]);
        let zeros = digits.iter().take_while(|&&b| b == b'0').count();
        let digits = digits.get(zeros..).unwrap_or(&[]);
        m_word(w) && digits != b"126" && digits != b"127"
    };
    let mut written = false;
    for w in words().filter(|w| kept(w)) {
        if written {
            out.byte(b' ');
        }
        out.text(w);
        written = true;
    }
    written
}

impl Family for Heidenhain {
    const TOOL_PATH: Option<&'static super::family::PathWords> = Some(&HEIDENHAIN_PATH);
    const MAX_LINE: usize = 254;
    const KEEPS_SHIFT: bool = true;
    const POSITIONING_IN_BLOCK: bool = true;

    fn rest(text: &[u8], out: &mut Out) -> bool {
        m_functions(text, out)
    }

    const FORMS: &'static [FormInfo] = &[
        FormInfo {
            form: Form::PlaneSpatial,
            words: 3,
            origin: false,
            writable: true,
        },
        FormInfo {
            form: Form::PlaneEuler,
            words: 3,
            origin: false,
            writable: true,
        },
        FormInfo {
            form: Form::PlaneVector,
            words: 6,
            origin: false,
            writable: true,
        },
        FormInfo {
            form: Form::PlanePoints,
            words: 9,
            origin: false,
            writable: true,
        },
        FormInfo {
            form: Form::PlaneProjected,
            words: 3,
            origin: false,
            writable: true,
        },
    ];

    /// One block of a Heidenhain plain-language program: `PLANE SPATIAL SPA SPB SPC`,
    /// `PLANE PROJECTED PROPR PROMIN PROROT`, `PLANE EULER EULPR EULNU EULROT`,
    /// `PLANE VECTOR BX BY BZ NX NY NZ`, `PLANE POINTS P1X … P3Z` (every word required, in any
    /// order), `PLANE RELATIV SPA|SPB|SPC` (on the active plane), `PLANE RESET`, each with the
    /// positioning and solution options, after a line number, with `;` comments; every other
    /// block is passed over or not followed (`other_block`), but for the datum shifts, cycle
    /// 19 and the turn to the plane through `Q120`–`Q122`; `PLANE AXIAL A B C` keeps the
    /// rotary-axis positions (a [`Direct`] mode: the machine gives the frame). A `PLANE`
    /// replaces the active one; the datum is not part of the plane (`POINTS` too: P1 is a
    /// point of the plane, the datum stays) \[doc\].
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        past_block_number(&mut c);
        if c.at_end() || c.peek() == Some(b'*') || c.rest_is_comment(true, false) {
            return Ok(Block::Passed);
        }
        let column = c.column();
        if let Some(block) = datum_shift(m, &mut c.clone())? {
            return Ok(block);
        }
        if let Some(block) = working_plane(m, &mut c.clone())? {
            return Ok(block);
        }
        if let Some(feed) = turn_to_plane(&mut c.clone()) {
            // The tilt block turned the axes already (`TURN`, cycle 19 with its feed): this
            // block moves them where they are.
            if m.positioning != Positioning::Stay {
                return Ok(Block::Frame(*m));
            }
            // With no tilt active too: the parameters hold the positions of the last
            // `PLANE … STAY`, which may have been a plane of zeros (CAM posts write the pair
            // for every plane): the turn to the untilted plane [choice].
            let (feed, feed_mm_min) = feed;
            return Ok(Block::Frame(Modal {
                positioning: Positioning::Turn,
                feed,
                feed_mm_min,
                ..*m
            }));
        }
        if !c.keyword(b"PLANE") {
            return Ok(other_block(text.get(column - 1..).unwrap_or(&[])));
        }
        c.spaces();
        let at = c.column();
        let mut added = false;
        let frame = if c.keyword(b"SPATIAL") {
            let w = plane_words(&mut c, [b"SPA", b"SPB", b"SPC"])?;
            LineError::at(at, plane_frame(Form::PlaneSpatial, &w))?
        } else if c.keyword(b"PROJECTED") {
            // The TNC's word is `PROROT` (as `EULROT` of `PLANE EULER`); a bare `ROT` is
            // read too, as earlier versions of this library wrote it.
            let (w, given) = named_words(&mut c, [b"PROPR", b"PROMIN", b"PROROT", b"ROT"])?;
            let [pr, min, prorot, rot] = w;
            match given {
                [true, true, true, false] | [true, true, false, true] => {}
                [true, true, true, true] => {
                    return Err(LineError {
                        error: Error::UnknownWord,
                        column: at,
                        expected: Some("PROROT or ROT, not both"),
                    })
                }
                [false, ..] => return Err(not_there(&c, "PROPR")),
                [_, false, ..] => return Err(not_there(&c, "PROMIN")),
                _ => return Err(not_there(&c, "PROROT")),
            }
            let w = [pr, min, prorot + rot];
            LineError::at(at, plane_frame(Form::PlaneProjected, &w))?
        } else if c.keyword(b"EULER") {
            let w = plane_words(&mut c, [b"EULPR", b"EULNU", b"EULROT"])?;
            LineError::at(at, plane_frame(Form::PlaneEuler, &w))?
        } else if c.keyword(b"VECTOR") {
            let w = plane_words(&mut c, [b"BX", b"BY", b"BZ", b"NX", b"NY", b"NZ"])?;
            LineError::at(at, plane_frame(Form::PlaneVector, &w))?
        } else if c.keyword(b"POINTS") {
            let names: [&[u8]; 9] = [
                b"P1X", b"P1Y", b"P1Z", b"P2X", b"P2Y", b"P2Z", b"P3X", b"P3Y", b"P3Z",
            ];
            let w = plane_words(&mut c, names)?;
            LineError::at(at, plane_frame(Form::PlanePoints, &w))?
        } else if c.keyword(b"RELATIV") {
            c.spaces();
            let axis = if c.word(b"SPA") {
                Axis::X
            } else if c.word(b"SPB") {
                Axis::Y
            } else if c.word(b"SPC") {
                Axis::Z
            } else {
                return Err(c.missing("SPA, SPB or SPC"));
            };
            c.spaces();
            let angle = c.number(SYNTAX)?;
            added = true;
            relativ(&LineError::at(at, m.tilt_base())?, axis, angle)
        } else if c.keyword(b"RESET") {
            RESET
        } else if c.keyword(b"AXIAL") {
            return axial(m, &mut c);
        } else {
            return Err(c.error(Error::UnknownWord));
        };
        let how = options(&mut c)?;
        // `PLANE RESET TURN`/`MOVE` turns the axes to the untilted plane, as a zero tilt with
        // `TURN` does: its way of moving is kept.
        Ok(Block::Frame(Modal {
            choice: how.choice,
            positioning: how.positioning,
            retract: how.retract,
            retract_mm: how.retract_mm,
            feed: how.feed,
            feed_mm_min: how.feed_mm_min,
            table_rot: how.table_rot,
            ..m.with_tilt(frame, added)
        }))
    }

    /// `PLANE SPATIAL`, `PLANE EULER`, `PLANE VECTOR`, `PLANE POINTS`, `PLANE PROJECTED`.
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        if !c.keyword(b"PLANE") {
            return Err(Error::BadArgument);
        }
        c.spaces();
        let forms = [
            (&b"SPATIAL"[..], Form::PlaneSpatial),
            (b"EULER", Form::PlaneEuler),
            (b"VECTOR", Form::PlaneVector),
            (b"POINTS", Form::PlanePoints),
            (b"PROJECTED", Form::PlaneProjected),
        ];
        let Some(&(_, form)) = forms.iter().find(|(name, _)| c.keyword(name)) else {
            return Err(Error::BadArgument);
        };
        c.spaces();
        if !c.at_end() {
            return Err(Error::BadArgument);
        }
        Ok(FormSpec { form, selector: 0 })
    }

    /// `PLANE RESET STAY`, or with `TURN`/`MOVE` the reset that turns the axes to the
    /// untilted plane.
    fn write_cancel(
        _: &FormSpec,
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<bool, Error> {
        out.text(b"PLANE RESET");
        write_positioning(how, decimals, out)?;
        Ok(true)
    }

    /// `PLANE <form> <words> STAY`: the words with their signs (`SPA+30`), then the
    /// positioning (`STAY` tilts the plane without moving; `TURN FMAX`, `MOVE FMAX` turn the
    /// rotary axes at rapid, `MOVE` keeping the tool tip), then `SEQ-`/`SEQ+` for a choice of
    /// the master axis' sign.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if how.relative {
            return write_relativ(words, how, decimals, out);
        }
        let (head, names): (&[u8], &[&[u8]]) = match spec.form {
            Form::PlaneSpatial => (b"PLANE SPATIAL", &[b" SPA", b" SPB", b" SPC"]),
            Form::PlaneProjected => (b"PLANE PROJECTED", &[b" PROPR", b" PROMIN", b" PROROT"]),
            Form::PlaneEuler => (b"PLANE EULER", &[b" EULPR", b" EULNU", b" EULROT"]),
            Form::PlaneVector => (
                b"PLANE VECTOR",
                &[b" BX", b" BY", b" BZ", b" NX", b" NY", b" NZ"],
            ),
            Form::PlanePoints => (
                b"PLANE POINTS",
                &[
                    b" P1X", b" P1Y", b" P1Z", b" P2X", b" P2Y", b" P2Z", b" P3X", b" P3Y", b" P3Z",
                ],
            ),
            _ => return Err(Error::BadArgument),
        };
        let style = Style {
            plus: true,
            point: false,
        };
        // Unit vectors and points a millimetre apart: 7 decimals (the TNC's input range
        // ±9.9999999) state the plane as 4 decimals of an angle do (at 4 a vector's plane was
        // 0.0012° off).
        let places = if matches!(spec.form, Form::PlaneVector | Form::PlanePoints) && decimals >= 0
        {
            decimals.max(7)
        } else {
            decimals
        };
        out.text(head);
        for (name, &v) in names.iter().zip(words) {
            write_word(out, name, v, places, style)?;
        }
        write_positioning(how, decimals, out)?;
        write_choice(how, out)
    }

    /// `PLANE RELATIV` from the spatial angles of every `PLANE`.
    fn relative_form(spec: &FormSpec) -> Option<FormSpec> {
        let plane = matches!(
            spec.form,
            Form::PlaneSpatial
                | Form::PlaneProjected
                | Form::PlaneEuler
                | Form::PlaneVector
                | Form::PlanePoints
        );
        plane.then_some(FormSpec {
            form: Form::PlaneSpatial,
            selector: 0,
        })
    }

    /// `PLANE AXIAL` with the positions given (`A`, `B`, `C`), then the positioning: the
    /// axes named by letter; the origin is the datum shift's (the block has none).
    fn write_direct(
        _: &FormSpec,
        origin: Vector,
        (direct, positions): (Direct, [f64; 3]),
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if direct.by != DirectAxes::Letters {
            return Err(Error::NotAvailable);
        }
        if origin != [0.0; 3] {
            return Err(Error::HasOrigin);
        }
        let style = Style {
            plus: true,
            point: false,
        };
        out.text(b"PLANE AXIAL");
        for (k, name) in [b" A", b" B", b" C"].iter().enumerate() {
            if direct.given & (1 << k) != 0 {
                let v = positions.get(k).copied().unwrap_or(0.0);
                write_word(out, *name, v, decimals, style)?;
            }
        }
        write_positioning(how, decimals, out)?;
        Ok(())
    }

    /// Cycle 7 (`CYCL DEF 7.0 DATUM SHIFT`, then `7.1 X`, `7.2 Y`, `7.3 Z`), which every TNC
    /// runs and CAM systems write \[choice: `TRANS DATUM AXIS` is the newer single block\];
    /// all three axes, as the cycle sets only the axes it names. A zero shift is the
    /// manual's reset: the cycle with `X+0 Y+0 Z+0` \[doc\].
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        let style = Style {
            plus: true,
            point: false,
        };
        out.text(b"CYCL DEF 7.0 DATUM SHIFT");
        let lines: [&[u8]; 3] = [
            b"\nCYCL DEF 7.1 X",
            b"\nCYCL DEF 7.2 Y",
            b"\nCYCL DEF 7.3 Z",
        ];
        for (line, &v) in lines.iter().zip(&shift) {
            write_word(out, line, v, decimals, style)?;
        }
        Ok(())
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        no_selector(selector)?;
        plane_frame(form, words)
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        no_selector(selector)?;
        let m = &frame.rotation;
        let d = match form {
            Form::PlaneSpatial => spatial_angles(m)?,
            Form::PlaneEuler => euler_angles(m)?,
            Form::PlaneProjected => projected_angles(m)?,
            Form::PlaneVector => {
                let (b, n) = vector_of(m);
                put(out, 0, b);
                put(out, 3, n);
                return Ok(false);
            }
            Form::PlanePoints => {
                // P1 at the datum, P2 on the new X axis and P3 on the new Y axis, 1 mm from
                // it: the plane needs no origin, and unit vectors read back to 1 ulp.
                put(out, 3, [m[0][0], m[1][0], m[2][0]]);
                put(out, 6, [m[0][1], m[1][1], m[2][1]]);
                return Ok(false);
            }
            _ => return Err(Error::BadArgument),
        };
        put(out, 0, d.angles);
        Ok(d.singular)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialects::close;
    use crate::{elementary, mul};

    /// The worked numbers of docs/dialects.md.
    #[test]
    #[allow(clippy::approx_constant)] // printed to six decimals
    fn worked_numbers() {
        let s = 0.5f64.sqrt();
        assert!(close(
            &spatial([45.0, 0.0, 90.0]),
            &[[0.0, -s, s], [1.0, 0.0, 0.0], [0.0, s, s]],
            1e-15
        ));
        assert!(close(
            &spatial([27.0, 0.0, 45.0]),
            &[
                [0.707107, -0.630037, 0.321020],
                [0.707107, 0.630037, -0.321020],
                [0.0, 0.453990, 0.891007]
            ],
            5e-7
        ));
        assert!(close(
            &euler([45.0, 20.0, 22.0]),
            &[
                [0.406706, -0.880966, 0.241845],
                [0.904530, 0.351193, -0.241845],
                [0.128123, 0.317116, 0.939693]
            ],
            5e-7
        ));
        // SPATIAL is the paper's probe convention: Rz(C)·Ry(B)·Rx(A).
        let f = mul(
            &mul(&elementary(Axis::Z, 60.0), &elementary(Axis::Y, 45.0)),
            &elementary(Axis::X, 30.0),
        );
        assert!(close(&spatial([30.0, 45.0, 60.0]), &f, 1e-15));
    }

    #[test]
    fn inverses() {
        for a in [[30.0, 45.0, 60.0], [-120.0, 10.0, 170.0], [5.0, 90.0, 0.0]] {
            let f = spatial(a);
            let d = spatial_angles(&f).unwrap();
            assert!(close(&spatial(d.angles), &f, 2e-15));
            let g = euler(a);
            let e = euler_angles(&g).unwrap();
            assert!(close(&euler(e.angles), &g, 2e-15));
            let (b, n) = vector_of(&f);
            assert!(close(&vector(b, n).unwrap(), &f, 2e-15));
            let o = [10.0, -20.0, 5.0];
            let p2 = core::array::from_fn(|k| o[k] + 3.0 * b[k]);
            let y = [f[0][1], f[1][1], f[2][1]];
            let p3 = core::array::from_fn(|k| o[k] + 2.0 * y[k] - 7.0 * b[k]);
            assert!(close(&points(o, p2, p3).unwrap(), &f, 1e-14));
        }
        // SPB = 90: SPC = 0, SPA carries the free angle.
        let d = spatial_angles(&spatial([10.0, 90.0, 40.0])).unwrap();
        assert!(d.singular && d.angles[1] == 90.0 && d.angles[2] == 0.0);
    }

    #[test]
    fn vector_keeps_n_and_projects_b() {
        // B not perpendicular to N: N kept, B's component along N dropped.
        let n = [0.0, 0.0, 5.0];
        let f = vector([2.0, 2.0, 9.0], n).unwrap();
        let s = 0.5f64.sqrt();
        assert!(close(
            &f,
            &[[s, -s, 0.0], [s, s, 0.0], [0.0, 0.0, 1.0]],
            1e-15
        ));
        assert_eq!(vector([1.0, 0.0, 0.0], [0.0; 3]), Err(Error::Degenerate));
        assert_eq!(
            vector([0.0, 0.0, 3.0], [0.0, 0.0, 1.0]),
            Err(Error::Degenerate)
        );
        assert_eq!(
            vector([f64::NAN, 0.0, 0.0], [0.0, 0.0, 1.0]),
            Err(Error::Degenerate)
        );
        // Huge and tiny inputs: scaled, not overflowed.
        let f = vector([1e300, 0.0, 0.0], [0.0, 0.0, 1e-300]).unwrap();
        assert_eq!(f, crate::IDENTITY);
    }

    #[test]
    fn points_refuse_what_defines_no_plane() {
        let o = [1.0, 2.0, 3.0];
        assert_eq!(points(o, o, [0.0; 3]), Err(Error::Coincident));
        assert_eq!(points(o, [2.0, 2.0, 3.0], o), Err(Error::Coincident));
        assert_eq!(
            points(o, [2.0, 2.0, 3.0], [5.0, 2.0, 3.0]),
            Err(Error::Collinear)
        );
        assert_eq!(
            points([-f64::MAX, 0.0, 0.0], [f64::MAX, 0.0, 0.0], o),
            Err(Error::OutOfRange)
        );
        // P3 on the negative-Y side turns Z' downwards.
        let f = points([0.0; 3], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]).unwrap();
        assert_eq!(f[2][2], -1.0);
    }

    #[test]
    fn relativ_turns_about_the_tilted_axis() {
        let active = Frame::from_rotation(spatial([0.0, 30.0, 0.0]));
        let f = relativ(&active, Axis::X, 20.0);
        let expect = mul(&elementary(Axis::Y, 30.0), &elementary(Axis::X, 20.0));
        assert!(close(&f.rotation, &expect, 1e-15));
    }
}
