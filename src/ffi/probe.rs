//! Exports of probing: measured points to a plane.

use super::frame::{read_frame, write_frame};
use super::{cncrot_status, guard, non_null, read_finite, status_of, write};
use crate::probe;
use crate::Vector;

/// The paper's flange probing: two points along the machine's X (`a1`, `a2`) and two along
/// Y (`b1`, `b2`), probed on the flange in machine coordinates, give the flange's tilt as
/// extrinsic angles about X, Y, Z (for CYCLE600 with `_INEXIN = 0`, `_BIN_IN = 57`; the
/// third is 0 when A1 and A2 differ only in X and Z) and as a rotation frame (no
/// translation: the tilt about the active datum, as CYCLE600 with `_POS = 0`).
///
/// Returns 0 (or `CNCROT_STATUS_SINGULAR` for a vertical flange), or with nothing written:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_COINCIDENT` (A1 = A2 or B1 = B2), `CNCROT_STATUS_COLLINEAR` (both
/// directions parallel), `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`.
///
/// # Safety
/// `a1`, `a2`, `b1`, `b2` point to 3 readable doubles, `angles_deg` to 3 and `frame` to 16
/// writable doubles (or NULL: error).
///
/// ```c
/// double a1[3] = {0, 0, 0}, a2[3] = {100, 0, 10}, b1[3] = {0, 0, 0}, b2[3] = {0, 100, 0};
/// double ang[3], f[16];
/// cncrot_probe_flange(a1, a2, b1, b2, ang, f);   // ang = {0, -5.7106, 0}
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_probe_flange(
    a1: *const f64,
    a2: *const f64,
    b1: *const f64,
    b2: *const f64,
    angles_deg: *mut f64,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            a1.is_null(),
            a2.is_null(),
            b1.is_null(),
            b2.is_null(),
            angles_deg.is_null(),
            frame.is_null(),
        ])?;
        let p: [Vector; 4] = [
            read_finite::<3>(a1)?,
            read_finite::<3>(a2)?,
            read_finite::<3>(b1)?,
            read_finite::<3>(b2)?,
        ];
        let f = probe::flange(p[0], p[1], p[2], p[3])?;
        let fr = crate::Frame::from_rotation(f.rotation);
        // Both outputs are checked before either is written, so that an error writes none.
        let h = fr.to_homogeneous();
        if !h.iter().flatten().chain(&f.angles).all(|x| x.is_finite()) {
            return Err(cncrot_status::OutOfRange);
        }
        write(angles_deg, f.angles)?;
        write_frame(frame, &fr)?;
        Ok(status_of(f.singular))
    })
}

/// The least-squares plane through `n` points (`points` holds `3·n` doubles, x y z for each)
/// and its flatness: `frame` gets the plane (origin at the first point's foot on it, X'
/// along the first two points' direction, Z' on the tool's side: a non-negative component
/// along the machine's +Z, so that the same corners probed clockwise or anticlockwise give
/// the same plane, the right way up), `residual[0]` the flatness (largest minus smallest
/// distance from the plane), `residual[1]` the RMS distance, millimetres. Where the points'
/// order put Z' the other way (`(P2 − P1) × (P3 − P1)`, `PLANE POINTS`'s rule), the plane is
/// turned half a turn about X' and the status says so; `cncrot_probe_plane_toward` takes
/// another side, or the points' order. The normal is the points' direction of least spread
/// from their singular vectors, so a thin set (a strip, an apex just off a line) gets its
/// own plane. The time is linear in `n`, plus at most 10 sweeps of three Jacobi rotations
/// (5 in practice).
///
/// Returns 0, `CNCROT_STATUS_TURNED` (Z' turned to the tool's side), or with nothing
/// written: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_TOO_FEW` (n < 3),
/// `CNCROT_STATUS_COINCIDENT` (all points equal, or the first two closer than 1e-3 of the
/// largest distance of a point from the first: X' would be the probe's noise),
/// `CNCROT_STATUS_COLLINEAR` (the second extent at most 1e-12
/// of the first), `CNCROT_STATUS_DEGENERATE` (n > 3 and the two smallest extents differing
/// by at most 1e-12 of the first, e.g. points spread alike in every direction: no plane is
/// best), `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_BAD_ARGUMENT` (`points` not aligned for
/// doubles, or `n` beyond any array).
///
/// # Safety
/// `points` points to `3·n` readable doubles, `frame` to 16 and `residual` to 2 writable
/// doubles (or NULL: error).
///
/// ```c
/// double pts[12] = {0,0,5.01, 100,100,5.01, 0,100,4.99, 100,0,4.99}, f[16], res[2];
/// cncrot_probe_plane(pts, 4, f, res);   // plane z = 5: res[0] = 0.02 (flatness), res[1] = 0.01
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_probe_plane(
    points: *const f64,
    n: usize,
    frame: *mut f64,
    residual: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[points.is_null(), frame.is_null(), residual.is_null()])?;
        plane_into(points, n, [0.0, 0.0, 1.0], frame, residual)
    })
}

/// `cncrot_probe_plane` with Z' on the side of `toward` (a direction of any length: the
/// side the tool comes from, for a plane probed on a wall or from below), or, with `toward`
/// all zero, on the side the points' order gives (`(P2 − P1) × (P3 − P1)`: three points give
/// `PLANE POINTS`'s rotation; the rule before the tool's side was the default).
///
/// Returns 0, `CNCROT_STATUS_TURNED` (Z' turned to `toward`'s side), or with nothing
/// written the statuses of `cncrot_probe_plane`, `CNCROT_STATUS_NOT_FINITE` for `toward`
/// too.
///
/// # Safety
/// As `cncrot_probe_plane`; `toward` points to 3 readable doubles (or NULL: error).
///
/// ```c
/// double order[3] = {0, 0, 0};
/// cncrot_probe_plane_toward(pts, 4, order, f, res);   // the points' order decides
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_probe_plane_toward(
    points: *const f64,
    n: usize,
    toward: *const f64,
    frame: *mut f64,
    residual: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            points.is_null(),
            toward.is_null(),
            frame.is_null(),
            residual.is_null(),
        ])?;
        let toward = read_finite::<3>(toward)?;
        plane_into(points, n, toward, frame, residual)
    })
}

/// The plane of `n` points with Z' toward `toward`, written; its status.
///
/// # Safety
/// The pointers are non-NULL; `points` to `3·n` readable doubles, `frame` to 16 and
/// `residual` to 2 writable doubles.
#[inline(always)]
unsafe fn plane_into(
    points: *const f64,
    n: usize,
    toward: Vector,
    frame: *mut f64,
    residual: *mut f64,
) -> Result<cncrot_status, cncrot_status> {
    if n < 3 {
        return Err(cncrot_status::TooFew);
    }
    // No array holds more than isize::MAX bytes; and the points are read in place, so
    // they must be aligned as doubles.
    if n > isize::MAX as usize / core::mem::size_of::<Vector>()
        || points.align_offset(core::mem::align_of::<f64>()) != 0
    {
        return Err(cncrot_status::BadArgument);
    }
    // SAFETY: non-NULL, aligned, and (the caller guarantees) 3·n readable doubles, laid
    // out as n arrays of 3; every bit pattern is a double.
    let pts = core::slice::from_raw_parts(points.cast::<Vector>(), n);
    let (p, turned) = probe::plane_toward(pts, toward)?;
    let h = p.frame.to_homogeneous();
    if !h
        .iter()
        .flatten()
        .chain(&[p.flatness, p.rms])
        .all(|x| x.is_finite())
    {
        return Err(cncrot_status::OutOfRange);
    }
    write(residual, [p.flatness, p.rms])?;
    write_frame(frame, &p.frame)?;
    Ok(if turned {
        cncrot_status::Turned
    } else {
        cncrot_status::Ok
    })
}

/// Two points along an edge of the workpiece (E1 → E2, machine coordinates), probed in the
/// tilted plane `frame_in`: the turn about the plane's normal that lays its X' along the
/// edge, in `*angle_deg` (degrees), and the turned plane in `frame_out`
/// (`frame_in · Rz(angle)`, origin unchanged).
///
/// Returns 0, or with nothing written: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_COINCIDENT` (E1 = E2),
/// `CNCROT_STATUS_COLLINEAR` (the edge along the plane's normal),
/// `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`.
///
/// # Safety
/// `frame_in` points to 16 and `e1`, `e2` to 3 readable doubles, `angle_deg` to one and
/// `frame_out` to 16 writable doubles (or NULL: error); `frame_out` may be `frame_in`.
///
/// ```c
/// double a; cncrot_probe_edge(f, e1, e2, &a, f);   // turn the active plane onto the edge
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_probe_edge(
    frame_in: *const f64,
    e1: *const f64,
    e2: *const f64,
    angle_deg: *mut f64,
    frame_out: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            frame_in.is_null(),
            e1.is_null(),
            e2.is_null(),
            angle_deg.is_null(),
            frame_out.is_null(),
        ])?;
        let f = read_frame(frame_in)?;
        let (p, q) = (read_finite::<3>(e1)?, read_finite::<3>(e2)?);
        let (angle, turned) = probe::edge(&f, p, q)?;
        let h = turned.to_homogeneous();
        if !h.iter().flatten().all(|x| x.is_finite()) || !angle.is_finite() {
            return Err(cncrot_status::OutOfRange);
        }
        write_frame(frame_out, &turned)?;
        write(angle_deg, [angle])?;
        Ok(cncrot_status::Ok)
    })
}
