//! Every tilted-plane command of the dialects as one uniform pair of functions: a *form*
//! (the command as written), its one integer selector (`_MODE`, `Q`, `P`, the angle mode)
//! and its real-valued words in a fixed order, to a frame, and back.
//!
//! This is what the C boundary exports (`cncrot_form_frame`, `cncrot_form_values`) and what
//! a program-line reader or writer of any dialect turns its words into.

pub use super::family::{Form, MAX_VALUES};
use crate::{Error, Frame};

/// The frame of a form's words. `words` must hold exactly [`Form::count`] finite numbers
/// ([`Error::BadArgument`], [`Error::NotFinite`]); the selector is checked per form.
pub fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
    let (owner, info) = form.owner().ok_or(Error::BadArgument)?;
    if words.len() != info.words {
        return Err(Error::BadArgument);
    }
    if !words.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    let frame = owner.form_frame(form, selector, words)?;
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
/// ([`Error::HasOrigin`]; give the rotation alone, and the datum in that dialect's own
/// command), a selector whose mode cannot express frames (direct modes:
/// [`Error::NotAvailable`]; G158 mode 0: [`Error::BadArgument`]), and what the form cannot
/// express (projection modes: [`Error::OutOfRange`]). `words` is untouched on an error.
pub fn form_values(
    form: Form,
    selector: i32,
    frame: &Frame,
    words: &mut [f64],
) -> Result<bool, Error> {
    let (owner, info) = form.owner().ok_or(Error::BadArgument)?;
    if words.len() != info.words || !info.writable {
        return Err(Error::BadArgument);
    }
    crate::check_rotation(&frame.rotation)?;
    if !info.origin && frame.translation != [0.0; 3] {
        return Err(Error::HasOrigin);
    }
    let mut out = [0.0; MAX_VALUES];
    let singular = owner.form_values(form, selector, frame, &mut out)?;
    if !out.iter().all(|x| x.is_finite()) {
        return Err(Error::OutOfRange);
    }
    // Near a form's singularity its words can be right to the last bit and still not give
    // the frame back (a projection's tangent multiplies the rounding of its angles by up to
    // 1e13): words that do not read back are refused, never written.
    let back = form_frame(form, selector, out.get(..words.len()).unwrap_or(&[]))
        .map_err(|_| Error::OutOfRange)?;
    if !reads_back(&back, frame) {
        return Err(Error::OutOfRange);
    }
    for (w, o) in words.iter_mut().zip(out) {
        *w = o + 0.0;
    }
    Ok(singular)
}

/// How far the frame of written words may be from the frame they were written for: each
/// rotation element, and each origin coordinate relative to the origin's size (at least
/// 1 mm) \[choice\]. The words of a well-conditioned form read back to a few ulps.
pub const READ_BACK_TOLERANCE: f64 = 1e-12;

/// Whether `back` is `frame` within [`READ_BACK_TOLERANCE`] (NaN is not).
fn reads_back(back: &Frame, frame: &Frame) -> bool {
    let scale = frame
        .translation
        .iter()
        .fold(1.0f64, |a, &x| a.max(crate::math::abs(x)));
    let rotation = back
        .rotation
        .iter()
        .flatten()
        .zip(frame.rotation.iter().flatten())
        .all(|(a, b)| crate::math::abs(a - b) <= READ_BACK_TOLERANCE);
    let origin = back
        .translation
        .iter()
        .zip(&frame.translation)
        .all(|(a, b)| crate::math::abs(a - b) <= READ_BACK_TOLERANCE * scale);
    rotation && origin
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every writable form, with the selectors that can express any frame.
    const WRITABLE: [(Form, &[i32]); 12] = [
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

    /// Every writable form, with the selectors that can express any frame, writes words
    /// that read back to the same frame.
    #[test]
    fn every_form_round_trips() {
        let cases = WRITABLE;
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

    /// PLANE POINTS tilts about the active datum: P1 is a point of the plane, not its
    /// origin (every Heidenhain manual: "the position of the active datum is not changed").
    #[test]
    fn points_do_not_move_the_datum() {
        let f = form_frame(
            Form::PlanePoints,
            0,
            &[10.0, 0.0, 0.0, 10.0, 5.0, 0.0, 0.0, 0.0, 0.0],
        )
        .unwrap();
        assert_eq!(f.translation, [0.0; 3]);
        // X' along +Y, P3 on its +Y' side (towards -X): Z' = +Z, a turn of 90° about Z.
        assert_eq!(f.rotation, crate::elementary(crate::Axis::Z, 90.0));
        assert!(!Form::PlanePoints.has_origin());
        let mut w = [7.0; 9];
        let moved = Frame::with_translations([1e60; 3], crate::IDENTITY, [0.0; 3]);
        assert_eq!(
            form_values(Form::PlanePoints, 0, &moved, &mut w),
            Err(Error::HasOrigin)
        );
        assert_eq!(w, [7.0; 9]);
        form_values(Form::PlanePoints, 0, &Frame::IDENTITY, &mut w).unwrap();
        assert_eq!(w, [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    }

    /// Every form's writer against its reader on frames approaching each of its
    /// singularities: words that read back within the tolerance, or `OutOfRange`.
    #[test]
    fn writers_near_singularities_read_back_or_refuse() {
        use crate::{elementary, mul, Axis};
        let cases = WRITABLE;
        let mut refused = 0;
        let mut written = 0;
        for e in 3..=16 {
            let eps = 10f64.powi(-e);
            for (a, b) in [
                (Axis::X, Axis::Y),
                (Axis::Y, Axis::X),
                (Axis::Y, Axis::Z),
                (Axis::Z, Axis::X),
                (Axis::X, Axis::Z),
            ] {
                for base in [0.0, 90.0, 180.0] {
                    for sign in [1.0, -1.0] {
                        let m = mul(
                            &mul(
                                &elementary(b, 30.0),
                                &elementary(a, base + sign * (90.0 - eps)),
                            ),
                            &elementary(b, 30.0),
                        );
                        for t in [[0.0; 3], [10.0, -20.0, 5.0]] {
                            let f = Frame::with_translations(t, m, [0.0; 3]);
                            for (form, selectors) in cases {
                                if !form.has_origin() && t != [0.0; 3] {
                                    continue;
                                }
                                for &sel in selectors {
                                    let n = form.count();
                                    let mut w = [0.0; MAX_VALUES];
                                    match form_values(form, sel, &f, &mut w[..n]) {
                                        Ok(_) => {
                                            written += 1;
                                            let g = form_frame(form, sel, &w[..n]).unwrap();
                                            let d = distance(&g, &f);
                                            assert!(d <= 1e-12, "{form:?} {sel} {e}: {d:e}");
                                        }
                                        Err(err) => {
                                            refused += 1;
                                            assert_eq!(err, Error::OutOfRange, "{form:?} {sel}");
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        assert!(
            written > 10 * refused,
            "{written} written, {refused} refused"
        );
    }

    /// The read-back rule itself: rotation elements within 1e-12, origin coordinates within
    /// 1e-12 of the origin's size (at least 1 mm).
    #[test]
    fn reads_back_is_the_documented_tolerance() {
        let m = crate::elementary(crate::Axis::X, 30.0);
        let f = Frame::with_translations([100.0, 0.0, 0.0], m, [0.0; 3]);
        let moved = |dx: f64| Frame::with_translations([100.0 + dx, 0.0, 0.0], m, [0.0; 3]);
        assert!(reads_back(&moved(5e-11), &f));
        assert!(!reads_back(&moved(2e-10), &f));
        assert!(!reads_back(&moved(0.5), &f));
        let mut r = m;
        r[0][1] += 2e-12;
        assert!(!reads_back(
            &Frame::with_translations([100.0, 0.0, 0.0], r, [0.0; 3]),
            &f
        ));
        r[0][1] -= 1.5e-12;
        assert!(reads_back(
            &Frame::with_translations([100.0, 0.0, 0.0], r, [0.0; 3]),
            &f
        ));
        let near = Frame::with_translations([0.0, 5e-13, 0.0], m, [0.0; 3]);
        assert!(reads_back(&near, &Frame::from_rotation(m)));
        let far = Frame::with_translations([0.0, 2e-12, 0.0], m, [0.0; 3]);
        assert!(!reads_back(&far, &Frame::from_rotation(m)));
    }

    /// The largest difference of two frames' elements (the tests' own measure, independent
    /// of `reads_back`).
    fn distance(a: &Frame, b: &Frame) -> f64 {
        let (a, b) = (a.to_homogeneous(), b.to_homogeneous());
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    }

    /// The frame: `Ry(90° − 1e-13°)·Rx(30°)` as PLANE PROJECTED read back 3.9e-3
    /// off with success.
    #[test]
    fn projection_near_its_singularity_is_refused() {
        use crate::{elementary, mul, Axis};
        for eps in [1e-13, 1e-14] {
            let m = mul(&elementary(Axis::Y, 90.0 - eps), &elementary(Axis::X, 30.0));
            let f = Frame::from_rotation(m);
            let mut w = [0.0; 9];
            for (form, sel) in [(Form::PlaneProjected, 0), (Form::Cycle800, 128 + 57)] {
                let n = form.count();
                match form_values(form, sel, &f, &mut w[..n]) {
                    Ok(_) => {
                        let g = form_frame(form, sel, &w[..n]).unwrap();
                        let d = distance(&g, &f);
                        assert!(d <= 1e-12, "{form:?} {eps:e}: {d:e}");
                    }
                    Err(e) => assert_eq!(e, Error::OutOfRange),
                }
            }
        }
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
            Err(Error::HasOrigin)
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
