//! Exports of the homogeneous frames (4x4, row-major `double[16]`).

use super::{cncrot_status, guard, kind, non_null, read_finite, write};
use crate::{AxisCode, Frame};

/// # Safety
/// `p` is non-NULL and points to 16 readable doubles.
pub(super) unsafe fn read_frame(p: *const f64) -> Result<Frame, cncrot_status> {
    let v: [f64; 16] = read_finite(p)?;
    let h: [[f64; 4]; 4] = core::array::from_fn(|i| core::array::from_fn(|j| v[4 * i + j]));
    Ok(Frame::from_homogeneous(&h)?)
}

/// A 4x4 frame read as [`read_frame`] reads it, but with its rotation left to be checked
/// by the Rust function it goes to (which checks it anyway): so that a call in the
/// interpolation cycle checks it once.
///
/// # Safety
/// `p` is non-NULL and points to 16 readable doubles.
pub(super) unsafe fn read_frame_unchecked(p: *const f64) -> Result<Frame, cncrot_status> {
    // Row by row into the frame, so that no copy of the 16 doubles stays in the caller's
    // frame (stack bound of the hot path).
    let row = |i: usize| read_finite::<4>(p.add(4 * i));
    let (r0, r1, r2, r3) = (row(0)?, row(1)?, row(2)?, row(3)?);
    if r3 != [0.0, 0.0, 0.0, 1.0] {
        return Err(cncrot_status::NotARotation);
    }
    Ok(Frame {
        rotation: [
            [r0[0], r0[1], r0[2]],
            [r1[0], r1[1], r1[2]],
            [r2[0], r2[1], r2[2]],
        ],
        translation: [r0[3], r1[3], r2[3]],
    })
}

/// # Safety
/// `p` is non-NULL and points to 16 writable doubles.
pub(super) unsafe fn write_frame(p: *mut f64, f: &Frame) -> Result<(), cncrot_status> {
    let h = f.to_homogeneous();
    write::<16>(p, core::array::from_fn(|k| h[k / 4][k % 4]))
}

/// The frame `Trans(before)·Rot·Trans(after)` (CYCLE600 `_POS_*` / `_POS_*_R`, CYCLE800
/// `X0..Z0` / `X1..Z1`, G158 `X Y Z` / `U V W`): a point q of the new system lies at
/// `before + R·(after + q)`. Rotation as `cncrot_matrix_from_angles`; `frame` is the 4x4
/// homogeneous matrix, row-major.
///
/// Returns 0, or with `frame` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE` (translations whose sum overflows).
///
/// # Safety
/// `angles_deg`, `before` and `after` point to 3 readable, `frame` to 16 writable doubles
/// (or NULL: error).
///
/// ```c
/// double a[3] = {0, 0, 90}, p0[3] = {10, 0, 0}, p1[3] = {5, 0, 0}, f[16];
/// cncrot_frame_from_angles(1, 57, a, p0, p1, f);   // origin at (10, 5, 0)
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_frame_from_angles(
    intrinsic: i32,
    sequence: i32,
    angles_deg: *const f64,
    before: *const f64,
    after: *const f64,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            angles_deg.is_null(),
            before.is_null(),
            after.is_null(),
            frame.is_null(),
        ])?;
        let kind = kind(intrinsic)?;
        let code = AxisCode::new(sequence)?;
        let angles = read_finite::<3>(angles_deg)?;
        let before = read_finite::<3>(before)?;
        let after = read_finite::<3>(after)?;
        let r = crate::matrix_from_angles(kind, code, angles);
        write_frame(frame, &Frame::with_translations(before, r, after))?;
        Ok(cncrot_status::Ok)
    })
}

/// The frame of a rotation about the point `center` (paper eq. 35):
/// `Trans(center)·Rot·Trans(−center)`.
///
/// Returns 0, or with `frame` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE` (a center whose frame overflows).
///
/// # Safety
/// `angles_deg` and `center` point to 3 readable, `frame` to 16 writable doubles (or NULL:
/// error).
///
/// ```c
/// double a[3] = {90, 0, 0}, c[3] = {1, 0, 0}, f[16];
/// cncrot_frame_about_point(1, 3, a, c, f);   // Z90 about (1, 0, 0)
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_frame_about_point(
    intrinsic: i32,
    sequence: i32,
    angles_deg: *const f64,
    center: *const f64,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[angles_deg.is_null(), center.is_null(), frame.is_null()])?;
        let kind = kind(intrinsic)?;
        let code = AxisCode::new(sequence)?;
        let angles = read_finite::<3>(angles_deg)?;
        let center = read_finite::<3>(center)?;
        let r = crate::matrix_from_angles(kind, code, angles);
        write_frame(frame, &Frame::about_point(r, center))?;
        Ok(cncrot_status::Ok)
    })
}

/// `out = a·b`: frame `b` given in the system of frame `a` (chaining `AROT`-like offsets).
/// The rotation part is brought back to orthonormal (to 2 ulp), so chains do not drift.
/// Both inputs must be frames: rotation part a rotation, last row exactly 0 0 0 1.
///
/// Returns 0, or with `out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION` (a rotation part that is
/// none, or a last row other than 0 0 0 1), `CNCROT_STATUS_OUT_OF_RANGE` (a translation
/// that overflows).
///
/// # Safety
/// `a` and `b` point to 16 readable, `out` to 16 writable doubles (or NULL: error); `out`
/// may alias either input.
///
/// ```c
/// cncrot_frame_compose(f, f, f2);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_frame_compose(a: *const f64, b: *const f64, out: *mut f64) -> i32 {
    guard(|| {
        non_null(&[a.is_null(), b.is_null(), out.is_null()])?;
        let fa = read_frame(a)?;
        let fb = read_frame(b)?;
        write_frame(out, &fa.compose(&fb))?;
        Ok(cncrot_status::Ok)
    })
}

/// The inverse frame `[Rᵀ, −Rᵀ·t]`, `R` first brought to orthonormal (to 2 ulp); never -0.
///
/// Returns 0, or with `out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION`,
/// `CNCROT_STATUS_OUT_OF_RANGE`.
///
/// # Safety
/// `frame` points to 16 readable, `out` to 16 writable doubles (or NULL: error); they may be
/// the same array.
///
/// ```c
/// cncrot_frame_inverse(f, finv);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_frame_inverse(frame: *const f64, out: *mut f64) -> i32 {
    guard(|| {
        non_null(&[frame.is_null(), out.is_null()])?;
        let f = read_frame(frame)?;
        write_frame(out, &f.inverse())?;
        Ok(cncrot_status::Ok)
    })
}

/// `R·p + t`: a point of the frame's system in the original one.
///
/// Returns 0, or with `out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION`,
/// `CNCROT_STATUS_OUT_OF_RANGE`.
///
/// # Safety
/// `frame` points to 16 and `point` to 3 readable doubles, `out` to 3 writable doubles (or
/// NULL: error); `point` and `out` may be the same array.
///
/// ```c
/// double p[3] = {0, 0, 0}, q[3];
/// cncrot_frame_transform_point(f, p, q);   // the frame's origin
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_frame_transform_point(
    frame: *const f64,
    point: *const f64,
    out: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[frame.is_null(), point.is_null(), out.is_null()])?;
        let f = read_frame(frame)?;
        let p = read_finite::<3>(point)?;
        write(out, f.transform_point(p))?;
        Ok(cncrot_status::Ok)
    })
}
