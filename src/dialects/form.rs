//! Every tilted-plane command of the dialects as one uniform pair of functions: a *form*
//! (the command as written), its one integer selector (`_MODE`, `Q`, `P`, the angle mode)
//! and its real-valued words in a fixed order, to a frame, and back.
//!
//! This is what the C boundary exports (`cncrot_form_frame`, `cncrot_form_values`) and what
//! a program-line reader or writer of any dialect turns its words into.

use super::{fanuc, haas, heidenhain, sinumerik, syntec, twincat};
use crate::{Error, Frame, Matrix, Vector};

/// The most words a form has.
pub const MAX_VALUES: usize = 9;

/// A tilted-plane command as written, with the order of its words.
///
/// | form | selector | words, in this order |
/// |---|---|---|
/// | [`Form::Cycle800`] | `_MODE` | `_X0 _Y0 _Z0 _A _B _C _X1 _Y1 _Z1` |
/// | [`Form::SinumerikRot`] | 0 RPY, 1 Euler | `X Y Z` |
/// | [`Form::SinumerikRots`] | 0 `X Y`, 1 `Y Z`, 2 `Z X` | the two angles in that order |
/// | [`Form::PlaneSpatial`] | 0 | `SPA SPB SPC` |
/// | [`Form::PlaneEuler`] | 0 | `EULPR EULNU EULROT` |
/// | [`Form::PlaneVector`] | 0 | `BX BY BZ NX NY NZ` |
/// | [`Form::PlanePoints`] | 0 | `P1X P1Y P1Z P2X P2Y P2Z P3X P3Y P3Z` |
/// | [`Form::G68_2`] | 0 | `X Y Z I J K` |
/// | [`Form::G158`] | `P` | `X Y Z A B C U V W` |
/// | [`Form::TwincatRot`] | 0 | `X Y Z` |
/// | [`Form::G268`] | `Q` | `X Y Z I J K` |
/// | [`Form::G68_3`] | 0 | `X Y Z R TX TY TZ` (the tool direction T; vertical axis +Z) |
/// | [`Form::PlaneProjected`] | 0 | `PROPR PROMIN ROT` |
///
/// ```
/// use cncrot::dialects::form::{form_frame, Form};
/// // G68.2 X10 I0 J30 K0: origin (10, 0, 0), tilted about X by 30°.
/// let f = form_frame(Form::G68_2, 0, &[10.0, 0.0, 0.0, 0.0, 30.0, 0.0]).unwrap();
/// assert_eq!(f.translation, [10.0, 0.0, 0.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// SINUMERIK `CYCLE800` (swivel modes of [`sinumerik::SwivelMode`]).
    Cycle800 = 1,
    /// SINUMERIK `ROT`/`CROT` (and each step of `AROT`).
    SinumerikRot = 2,
    /// SINUMERIK `ROTS` (projection angles).
    SinumerikRots = 3,
    /// Heidenhain `PLANE SPATIAL`.
    PlaneSpatial = 4,
    /// Heidenhain `PLANE EULER`.
    PlaneEuler = 5,
    /// Heidenhain `PLANE VECTOR`.
    PlaneVector = 6,
    /// Heidenhain `PLANE POINTS`.
    PlanePoints = 7,
    /// Fanuc-style `G68.2`.
    G68_2 = 8,
    /// Syntec `G158`.
    G158 = 9,
    /// Beckhoff TwinCAT NC I `ROT`.
    TwincatRot = 10,
    /// Haas `G268`.
    G268 = 11,
    /// Fanuc-style `G68.3` (the plane from the tool direction, on a machine whose vertical
    /// axis is +Z [choice: a parameter of the control; `fanuc::g68_3` takes any]).
    G68_3 = 12,
    /// Heidenhain `PLANE PROJECTED`.
    PlaneProjected = 13,
}

impl Form {
    /// Every form, in code order.
    pub const ALL: [Form; 13] = [
        Form::Cycle800,
        Form::SinumerikRot,
        Form::SinumerikRots,
        Form::PlaneSpatial,
        Form::PlaneEuler,
        Form::PlaneVector,
        Form::PlanePoints,
        Form::G68_2,
        Form::G158,
        Form::TwincatRot,
        Form::G268,
        Form::G68_3,
        Form::PlaneProjected,
    ];

    /// The form of a code (1..=13), else [`Error::BadArgument`].
    pub fn from_code(code: i32) -> Result<Form, Error> {
        usize::try_from(code)
            .ok()
            .and_then(|c| c.checked_sub(1))
            .and_then(|i| Form::ALL.get(i).copied())
            .ok_or(Error::BadArgument)
    }

    /// How many words the form has.
    pub fn count(self) -> usize {
        match self {
            Form::SinumerikRots => 2,
            Form::SinumerikRot
            | Form::PlaneSpatial
            | Form::PlaneEuler
            | Form::TwincatRot
            | Form::PlaneProjected => 3,
            Form::PlaneVector | Form::G68_2 | Form::G268 => 6,
            Form::G68_3 => 7,
            Form::Cycle800 | Form::PlanePoints | Form::G158 => 9,
        }
    }

    /// Whether [`form_values`] can express every frame in this form (`ROTS` cannot: its
    /// projection fixes the new X in a plane).
    pub fn writable(self) -> bool {
        !matches!(self, Form::SinumerikRots)
    }

    /// Whether the form's words carry an origin (the others describe a rotation about the
    /// active datum).
    pub fn has_origin(self) -> bool {
        matches!(
            self,
            Form::Cycle800
                | Form::G68_2
                | Form::G68_3
                | Form::G158
                | Form::G268
                | Form::PlanePoints
        )
    }
}

/// The vertical axis of the `G68.3` form.
const VERTICAL: Vector = [0.0, 0.0, 1.0];

fn angle_mode(selector: i32) -> Result<sinumerik::AngleMode, Error> {
    match selector {
        0 => Ok(sinumerik::AngleMode::Rpy),
        1 => Ok(sinumerik::AngleMode::Euler),
        _ => Err(Error::BadArgument),
    }
}

fn no_selector(selector: i32) -> Result<(), Error> {
    if selector == 0 {
        Ok(())
    } else {
        Err(Error::BadArgument)
    }
}

fn v3(w: &[f64], at: usize) -> Vector {
    core::array::from_fn(|k| w.get(at + k).copied().unwrap_or(0.0))
}

/// The frame of a form's words. `words` must hold exactly [`Form::count`] finite numbers
/// ([`Error::BadArgument`], [`Error::NotFinite`]); the selector is checked per form.
pub fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
    if words.len() != form.count() {
        return Err(Error::BadArgument);
    }
    if !words.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    let rot = |m: Matrix| Frame::from_rotation(m);
    let frame = match form {
        Form::Cycle800 => {
            let mode = sinumerik::SwivelMode::from_mode(selector)?;
            sinumerik::cycle800_frame(mode, v3(words, 3), v3(words, 0), v3(words, 6))?
        }
        Form::SinumerikRot => rot(sinumerik::rot(angle_mode(selector)?, v3(words, 0))),
        Form::SinumerikRots => {
            let plane = match selector {
                0 => sinumerik::RotsPlane::XY,
                1 => sinumerik::RotsPlane::YZ,
                2 => sinumerik::RotsPlane::ZX,
                _ => return Err(Error::BadArgument),
            };
            let [a, b] = [0, 1].map(|k| words.get(k).copied().unwrap_or(0.0));
            rot(sinumerik::rots(plane, a, b))
        }
        Form::PlaneSpatial => {
            no_selector(selector)?;
            rot(heidenhain::spatial(v3(words, 0)))
        }
        Form::PlaneEuler => {
            no_selector(selector)?;
            rot(heidenhain::euler(v3(words, 0)))
        }
        Form::PlaneVector => {
            no_selector(selector)?;
            rot(heidenhain::vector(v3(words, 0), v3(words, 3))?)
        }
        Form::PlanePoints => {
            no_selector(selector)?;
            let p1 = v3(words, 0);
            let r = heidenhain::points(p1, v3(words, 3), v3(words, 6))?;
            Frame::with_translations(p1, r, [0.0; 3])
        }
        Form::G68_2 => {
            no_selector(selector)?;
            fanuc::g68_2(v3(words, 0), v3(words, 3))
        }
        Form::G158 => {
            let p = syntec::PWord::decode(selector)?;
            // Incremental P words apply on an active plane: as a lone block, on none.
            syntec::frame(
                &Frame::IDENTITY,
                p,
                v3(words, 0),
                v3(words, 3),
                v3(words, 6),
            )?
        }
        Form::TwincatRot => {
            no_selector(selector)?;
            rot(twincat::matrix(v3(words, 0)))
        }
        Form::G268 => haas::g268(v3(words, 0), v3(words, 3), selector)?,
        Form::PlaneProjected => {
            no_selector(selector)?;
            rot(heidenhain::projected(v3(words, 0)))
        }
        Form::G68_3 => {
            no_selector(selector)?;
            // `get`, not indexing: the length is checked above, but the no-panic proof
            // (c_tests/no_panic.sh) must see that no path can panic.
            let angle = words.get(3).copied().ok_or(Error::BadArgument)?;
            let r = fanuc::g68_3(v3(words, 4), VERTICAL, angle)?;
            Frame::with_translations(v3(words, 0), r, [0.0; 3])
        }
    };
    // Finite words can still overflow (origins near f64::MAX).
    let h = frame.to_homogeneous();
    if !h.iter().flatten().all(|x| x.is_finite()) {
        return Err(Error::OutOfRange);
    }
    Ok(frame)
}

/// The words of a form that give `frame` (the inverse of [`form_frame`]), written into
/// `words[..count]`; returns whether the decomposition was singular (the free angle in the
/// slot the dialect's rule names). Refused: `ROTS` ([`Error::BadArgument`]: not every frame
/// is a projection), a frame with an origin for a form without origin words
/// ([`Error::BadArgument`]; give the rotation alone, and the datum in that dialect's own
/// command), a selector whose mode cannot express frames (direct modes:
/// [`Error::NotAvailable`]; G158 mode 0: [`Error::BadArgument`]), and what the form cannot
/// express (projection modes: [`Error::OutOfRange`]). `words` is untouched on an error.
pub fn form_values(
    form: Form,
    selector: i32,
    frame: &Frame,
    words: &mut [f64],
) -> Result<bool, Error> {
    if words.len() != form.count() || !form.writable() {
        return Err(Error::BadArgument);
    }
    crate::check_rotation(&frame.rotation)?;
    if !form.has_origin() && frame.translation != [0.0; 3] {
        return Err(Error::BadArgument);
    }
    let m = &frame.rotation;
    let t = frame.translation;
    let mut out = [0.0; MAX_VALUES];
    let singular = match form {
        Form::Cycle800 => {
            let mode = sinumerik::SwivelMode::from_mode(selector)?;
            let d = sinumerik::cycle800_angles(mode, m)?;
            put(&mut out, 0, t);
            put(&mut out, 3, d.angles);
            d.singular
        }
        Form::SinumerikRot => {
            let (xyz, singular) = sinumerik::readback(angle_mode(selector)?, m)?;
            put(&mut out, 0, xyz);
            singular
        }
        Form::PlaneSpatial => {
            no_selector(selector)?;
            let d = heidenhain::spatial_angles(m)?;
            put(&mut out, 0, d.angles);
            d.singular
        }
        Form::PlaneEuler => {
            no_selector(selector)?;
            let d = heidenhain::euler_angles(m)?;
            put(&mut out, 0, d.angles);
            d.singular
        }
        Form::PlaneVector => {
            no_selector(selector)?;
            let (b, n) = heidenhain::vector_of(m);
            put(&mut out, 0, b);
            put(&mut out, 3, n);
            false
        }
        Form::PlanePoints => {
            no_selector(selector)?;
            // P1 at the origin, P2 along the new X, P3 along the new Y, at a distance of at
            // least 1 and at least the origin's largest coordinate: a unit step would be
            // lost in the rounding of an origin far away (found by fuzzing at 1.5e69).
            let step = t.iter().fold(1.0f64, |a, &x| a.max(crate::math::abs(x)));
            put(&mut out, 0, t);
            put(&mut out, 3, core::array::from_fn(|k| t[k] + step * m[k][0]));
            put(&mut out, 6, core::array::from_fn(|k| t[k] + step * m[k][1]));
            false
        }
        Form::G68_2 => {
            no_selector(selector)?;
            let d = fanuc::g68_2_angles(m)?;
            put(&mut out, 0, t);
            put(&mut out, 3, d.angles);
            d.singular
        }
        Form::G158 => {
            let p = syntec::PWord::decode(selector)?;
            if p.incremental {
                return Err(Error::BadArgument);
            }
            let d = match p.mode {
                syntec::Mode::Order(code) => {
                    let seq = crate::Sequence::from_axis_code(code)?;
                    crate::angles_from_matrix(
                        crate::Convention::new(crate::Kind::Intrinsic, seq),
                        m,
                    )?
                }
                syntec::Mode::Direct => return Err(Error::NotAvailable),
                _ => return Err(Error::BadArgument),
            };
            put(&mut out, 0, t);
            put(&mut out, 3, d.angles);
            d.singular
        }
        Form::TwincatRot => {
            no_selector(selector)?;
            let (xyz, singular) = twincat::rot_angles(m)?;
            put(&mut out, 0, xyz);
            singular
        }
        Form::G268 => {
            let (ijk, singular) = haas::g268_angles(m, selector)?;
            put(&mut out, 0, t);
            put(&mut out, 3, ijk);
            singular
        }
        Form::G68_3 => {
            no_selector(selector)?;
            let r = fanuc::g68_3_r(m, VERTICAL)?;
            put(&mut out, 0, t);
            put(&mut out, 4, [m[0][2], m[1][2], m[2][2]]);
            if let Some(slot) = out.get_mut(3) {
                *slot = r;
            }
            false
        }
        Form::PlaneProjected => {
            no_selector(selector)?;
            let d = heidenhain::projected_angles(m)?;
            put(&mut out, 0, d.angles);
            d.singular
        }
        Form::SinumerikRots => return Err(Error::BadArgument),
    };
    if !out.iter().all(|x| x.is_finite()) {
        return Err(Error::OutOfRange);
    }
    for (w, o) in words.iter_mut().zip(out) {
        *w = o + 0.0;
    }
    Ok(singular)
}

fn put(out: &mut [f64; MAX_VALUES], at: usize, v: [f64; 3]) {
    for (k, x) in v.into_iter().enumerate() {
        if let Some(slot) = out.get_mut(at + k) {
            *slot = x;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every writable form, with the selectors that can express any frame, writes words
    /// that read back to the same frame.
    #[test]
    fn every_form_round_trips() {
        let cases: [(Form, &[i32]); 12] = [
            (
                Form::Cycle800,
                &[57, 27, 39, 55, 64, 128 + 57, 128 + 30, 128 + 39],
            ),
            (Form::SinumerikRot, &[0, 1]),
            (Form::PlaneSpatial, &[0]),
            (Form::PlaneEuler, &[0]),
            (Form::PlaneVector, &[0]),
            (Form::PlanePoints, &[0]),
            (Form::G68_2, &[0]),
            (Form::G158, &[10157, 10159, 10139]),
            (Form::TwincatRot, &[0]),
            (Form::G268, &[123, 321, 213]),
            (Form::G68_3, &[0]),
            (Form::PlaneProjected, &[0]),
        ];
        let frames = [
            Frame::with_translations(
                [10.0, -5.0, 2.0],
                crate::matrix_from_angles(
                    crate::Kind::Intrinsic,
                    crate::AxisCode::new(57).unwrap(),
                    [30.0, 45.0, 60.0],
                ),
                [0.0; 3],
            ),
            Frame::from_rotation(crate::matrix_from_angles(
                crate::Kind::Extrinsic,
                crate::AxisCode::new(27).unwrap(),
                [-120.0, 80.0, 170.0],
            )),
        ];
        for (form, selectors) in cases {
            for &sel in selectors {
                for f in frames {
                    let f = if form.has_origin() {
                        f
                    } else {
                        Frame::from_rotation(f.rotation)
                    };
                    let mut w = [0.0; MAX_VALUES];
                    let n = form.count();
                    form_values(form, sel, &f, &mut w[..n]).unwrap();
                    let g = form_frame(form, sel, &w[..n]).unwrap();
                    let d = g
                        .to_homogeneous()
                        .iter()
                        .flatten()
                        .zip(f.to_homogeneous().iter().flatten())
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0, f64::max);
                    assert!(d < 1e-13, "{form:?} {sel}: {d:e}");
                }
            }
        }
    }

    /// Found by fuzzing: P2 = P1 + X' was P1 again for an origin at 1.5e69.
    #[test]
    fn points_far_from_the_origin_read_back() {
        let f = Frame::with_translations([-212.8, 1.47e69, 268.2], crate::IDENTITY, [0.0; 3]);
        let mut w = [0.0; 9];
        form_values(Form::PlanePoints, 0, &f, &mut w).unwrap();
        let g = form_frame(Form::PlanePoints, 0, &w).unwrap();
        assert_eq!(g.rotation, crate::IDENTITY);
        assert_eq!(g.translation, f.translation);
        let far = Frame::with_translations([f64::MAX, 0.0, 0.0], crate::IDENTITY, [0.0; 3]);
        assert_eq!(
            form_values(Form::PlanePoints, 0, &far, &mut w),
            Err(Error::OutOfRange)
        );
    }

    #[test]
    fn refusals() {
        let id = Frame::IDENTITY;
        let mut w = [0.0; 9];
        assert_eq!(Form::from_code(0), Err(Error::BadArgument));
        assert_eq!(Form::from_code(14), Err(Error::BadArgument));
        assert_eq!(Form::from_code(8), Ok(Form::G68_2));
        assert_eq!(
            form_frame(Form::G68_2, 0, &[0.0; 5]),
            Err(Error::BadArgument)
        );
        assert_eq!(
            form_frame(Form::G68_2, 1, &[0.0; 6]),
            Err(Error::BadArgument)
        );
        assert_eq!(
            form_frame(Form::G68_2, 0, &[f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0]),
            Err(Error::NotFinite)
        );
        assert_eq!(
            form_frame(Form::Cycle800, 192, &[0.0; 9]),
            Err(Error::NotAvailable)
        );
        assert_eq!(
            form_values(Form::SinumerikRots, 0, &id, &mut w[..2]),
            Err(Error::BadArgument)
        );
        let moved = Frame::with_translations([1.0, 0.0, 0.0], crate::IDENTITY, [0.0; 3]);
        assert_eq!(
            form_values(Form::PlaneSpatial, 0, &moved, &mut w[..3]),
            Err(Error::BadArgument)
        );
        assert_eq!(
            form_values(Form::G158, 10200, &id, &mut w),
            Err(Error::NotAvailable)
        );
        assert_eq!(
            form_values(Form::G158, 1157, &id, &mut w),
            Err(Error::BadArgument)
        );
        assert_eq!(
            form_values(Form::G268, 313, &id, &mut w[..6]),
            Err(Error::BadSequence)
        );
        let big = [f64::MAX, 0.0, 0.0, 0.0, 0.0, 0.0, f64::MAX, 0.0, 0.0];
        assert_eq!(form_frame(Form::G158, 10157, &big), Err(Error::OutOfRange));
        assert_eq!(w, [0.0; 9]);
    }
}
