//! Probing: measured points turned into the plane a controller needs, when the workpiece
//! cannot be aligned with the machine (the paper's use case: a flange probed in the
//! machine's basic system, two points along X and two along Y).
//!
//! Points are in machine coordinates (millimetres). Nothing allocates: the caller provides
//! the points.

use crate::math::{atan2_deg, sqrt};
use crate::vector::{cross, dot};
use crate::{
    angles_from_matrix, elementary, rotation_from_z_x, Axis, Convention, Error, Frame, Kind,
    Matrix, Sequence, Vector, MIN_SINE,
};

/// What [`flange`] measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flange {
    /// The plane's rotation: Z' normal to the flange on the +Z side, X' along the probed X
    /// direction (A1 → A2, turned to +X).
    pub rotation: Matrix,
    /// The same rotation as extrinsic angles about the machine's X, Y, Z (code 57, what
    /// CYCLE600 takes with `_INEXIN = 0`, `_BIN_IN = 57`): the flange's tilts about X and Y,
    /// and 0 about Z when A1 and A2 differ only in X and Z.
    pub angles: [f64; 3],
    /// The decomposition was singular (the flange is vertical: Y tilt ±90°).
    pub singular: bool,
}

fn diff(a: Vector, b: Vector) -> Result<Vector, Error> {
    let d: Vector = core::array::from_fn(|k| b[k] - a[k]);
    if d.iter().all(|x| x.is_finite()) {
        Ok(d)
    } else {
        Err(Error::OutOfRange)
    }
}

fn finite(points: &[Vector]) -> Result<(), Error> {
    if points.iter().flatten().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(Error::NotFinite)
    }
}

/// The sine of the angle between two nonzero vectors, without overflow.
fn sine(u: Vector, v: Vector) -> Result<f64, Error> {
    let (u, v) = (crate::unit_vector(u)?, crate::unit_vector(v)?);
    let c = cross(u, v);
    Ok(sqrt(dot(c, c)))
}

/// The paper's flange probing: `a1`, `a2` two points along the machine's X, `b1`, `b2` two
/// along Y, on the flange (the probe's contact points, in machine coordinates).
///
/// The plane through both directions is exact (its normal is `(A2 − A1) × (B2 − B1)`, not
/// two independent slopes: with both tilts, `atan(Δz/Δy)` alone is not the X angle).
/// Refused: [`Error::NotFinite`]; [`Error::Coincident`] when A1 = A2 or B1 = B2;
/// [`Error::Collinear`] when both directions are parallel (a sine of at most
/// [`MIN_SINE`]); [`Error::OutOfRange`] when differences overflow.
///
/// ```
/// use cncrot::probe::flange;
/// // A flange rising 10 mm over 100 mm along X (a tilt of -5.71° about Y), level along Y.
/// let f = flange([0.0; 3], [100.0, 0.0, 10.0], [0.0; 3], [0.0, 100.0, 0.0]).unwrap();
/// assert!((f.angles[1] + 0.1f64.atan().to_degrees()).abs() < 1e-12);
/// assert!(f.angles[0].abs() < 1e-12 && f.angles[2].abs() < 1e-12);
/// ```
pub fn flange(a1: Vector, a2: Vector, b1: Vector, b2: Vector) -> Result<Flange, Error> {
    finite(&[a1, a2, b1, b2])?;
    let u = diff(a1, a2)?;
    let v = diff(b1, b2)?;
    if u == [0.0; 3] || v == [0.0; 3] {
        return Err(Error::Coincident);
    }
    if sine(u, v)? <= MIN_SINE {
        return Err(Error::Collinear);
    }
    let mut n = cross(crate::unit_vector(u)?, crate::unit_vector(v)?);
    // The tool side: the flange is probed from above [choice for a vertical flange: as
    // the cross product gives it].
    if n[2] < 0.0 {
        n = n.map(|x| -x);
    }
    let x_hint = if u[0] < 0.0 { u.map(|x| -x) } else { u };
    let rotation = rotation_from_z_x(n, x_hint).map_err(|_| Error::Collinear)?;
    let d = angles_from_matrix(Convention::new(Kind::Extrinsic, Sequence::XYZ), &rotation)?;
    Ok(Flange {
        rotation,
        angles: d.angles,
        singular: d.singular,
    })
}

/// What [`plane`] measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// The least-squares plane as a frame: origin at the first point's foot on the plane,
    /// X' along the first two points' direction in the plane, Z' on the side of
    /// `(P2 − P1) × (P3 − P1)` (so three points give `PLANE POINTS`'s frame).
    pub frame: Frame,
    /// Flatness: the largest minus the smallest signed distance of the points from the
    /// plane (the zone between two parallel planes that holds them all, about the
    /// least-squares plane), millimetres.
    pub flatness: f64,
    /// The root mean square of the distances, millimetres.
    pub rms: f64,
}

/// The least-squares plane through `points` (at least 3), with its flatness.
///
/// The normal is the eigenvector of the smallest eigenvalue of the points' scatter matrix
/// (about their centroid, scaled to their extent so that nothing overflows), from the
/// closed-form eigenvalues of a symmetric 3x3 matrix; no iteration, so the time depends only
/// on the number of points. Refused: [`Error::TooFew`] (fewer than 3), [`Error::NotFinite`],
/// [`Error::Coincident`] (all points equal), [`Error::Collinear`] (all on one line: the
/// second extent at most [`MIN_SINE`] times the first), [`Error::Degenerate`] (points
/// spread equally in every direction: no plane is best), [`Error::OutOfRange`].
///
/// ```
/// use cncrot::probe::plane;
/// // Two opposite corners 0.01 mm above z = 5, the other two 0.01 below: by symmetry the
/// // fit is z = 5 itself, the flatness 0.02 and the RMS 0.01.
/// let p = plane(&[[0.0, 0.0, 5.01], [100.0, 100.0, 5.01], [0.0, 100.0, 4.99], [100.0, 0.0, 4.99]])
///     .unwrap();
/// assert!((p.flatness - 0.02).abs() < 1e-12 && (p.rms - 0.01).abs() < 1e-12);
/// assert!((p.frame.rotation[2][2] - 1.0).abs() < 1e-15);
/// ```
pub fn plane(points: &[Vector]) -> Result<Plane, Error> {
    if points.len() < 3 {
        return Err(Error::TooFew);
    }
    finite(points)?;
    let p1 = points[0];
    // Centroid as a running mean: no sum that could overflow.
    let mut c = [0.0; 3];
    for (k, p) in points.iter().enumerate() {
        let w = 1.0 / (k + 1) as f64;
        for i in 0..3 {
            c[i] += (p[i] - c[i]) * w;
        }
    }
    let mut scale: f64 = 0.0;
    for p in points {
        for i in 0..3 {
            let d = p[i] - c[i];
            if !d.is_finite() {
                return Err(Error::OutOfRange);
            }
            scale = scale.max(crate::math::abs(d));
        }
    }
    if scale == 0.0 {
        return Err(Error::Coincident);
    }
    let mut m = [[0.0; 3]; 3];
    for p in points {
        let d: Vector = core::array::from_fn(|i| (p[i] - c[i]) / scale);
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] += d[i] * d[j];
            }
        }
    }
    let (largest, middle, smallest) = eigenvalues(&m).ok_or(Error::Degenerate)?;
    if middle <= MIN_SINE * MIN_SINE * largest {
        return Err(Error::Collinear);
    }
    let mut n = eigenvector(&m, smallest).ok_or(Error::Degenerate)?;
    // The side of (P2 − P1) × (P3 − P1), as PLANE POINTS; where those three are collinear,
    // the +Z side, then +Y, then +X [choice].
    let side = cross(diff(p1, points[1])?, diff(p1, points[2])?);
    let s = dot(n, side);
    let s = if s != 0.0 {
        s
    } else if n[2] != 0.0 {
        n[2]
    } else if n[1] != 0.0 {
        n[1]
    } else {
        n[0]
    };
    if s < 0.0 {
        n = n.map(|x| -x);
    }
    // X' along P1 → P2 in the plane; where that is along the normal, the machine's X, then Y.
    let hints = [diff(p1, points[1])?, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let rotation = hints
        .iter()
        .find_map(|&h| rotation_from_z_x(n, h).ok())
        .ok_or(Error::Degenerate)?;
    let z = [rotation[0][2], rotation[1][2], rotation[2][2]];
    // Signed distances from the plane through the centroid.
    let (mut lo, mut hi, mut sq) = (f64::INFINITY, f64::NEG_INFINITY, 0.0);
    for p in points {
        let d = dot(core::array::from_fn(|i| p[i] - c[i]), z);
        lo = lo.min(d);
        hi = hi.max(d);
        sq += d * d / points.len() as f64;
    }
    let h1 = dot(core::array::from_fn(|i| p1[i] - c[i]), z);
    let origin: Vector = core::array::from_fn(|i| p1[i] - h1 * z[i]);
    let out = Plane {
        frame: Frame {
            rotation,
            translation: origin.map(|x| x + 0.0),
        },
        flatness: hi - lo,
        rms: sqrt(sq),
    };
    if out.frame.translation.iter().all(|x| x.is_finite()) && out.flatness.is_finite() {
        Ok(out)
    } else {
        Err(Error::OutOfRange)
    }
}

/// The eigenvalues of a symmetric positive semi-definite 3x3 matrix, largest first, in
/// closed form (the trigonometric solution of the characteristic cubic); `None` when all
/// three are equal (no direction is distinguished).
fn eigenvalues(m: &Matrix) -> Option<(f64, f64, f64)> {
    let q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
    let off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    let p2 = (m[0][0] - q) * (m[0][0] - q)
        + (m[1][1] - q) * (m[1][1] - q)
        + (m[2][2] - q) * (m[2][2] - q)
        + 2.0 * off;
    let p = sqrt(p2 / 6.0);
    if p == 0.0 || p.is_nan() {
        return None;
    }
    let b: Matrix = core::array::from_fn(|i| {
        core::array::from_fn(|j| (m[i][j] - if i == j { q } else { 0.0 }) / p)
    });
    let r = (crate::determinant(&b) / 2.0).clamp(-1.0, 1.0);
    // φ = acos(r)/3 in degrees, from atan2 (the one inverse function the crate uses).
    let phi = atan2_deg(sqrt(1.0 - r * r), r) / 3.0;
    let (_, c1) = crate::math::sin_cos_deg(phi);
    let (_, c3) = crate::math::sin_cos_deg(phi + 120.0);
    let largest = q + 2.0 * p * c1;
    let smallest = (q + 2.0 * p * c3).max(0.0);
    let middle = (3.0 * q - largest - smallest).max(0.0);
    Some((largest, middle, smallest))
}

/// A unit eigenvector of `m` for the eigenvalue `lambda`: the largest cross product of two
/// rows of `m − λI` (each row is perpendicular to it).
fn eigenvector(m: &Matrix, lambda: f64) -> Option<Vector> {
    let a: Matrix = core::array::from_fn(|i| {
        core::array::from_fn(|j| m[i][j] - if i == j { lambda } else { 0.0 })
    });
    let candidates = [cross(a[0], a[1]), cross(a[0], a[2]), cross(a[1], a[2])];
    let best = candidates
        .iter()
        .copied()
        .max_by(|x, y| dot(*x, *x).total_cmp(&dot(*y, *y)))?;
    crate::unit_vector(best).ok()
}

/// Two points along an edge of the workpiece, probed in the tilted plane `active`: the
/// rotation about the plane's normal that turns its X' onto the edge (direction E1 → E2,
/// projected into the plane), in degrees, and the plane turned by it
/// (`active · Rz(angle)`, the origin unchanged).
///
/// Refused: [`Error::NotFinite`], [`Error::Coincident`] (E1 = E2), [`Error::Collinear`]
/// (the edge along the plane's normal: no turn is determined), [`Error::NotARotation`] for
/// an `active` frame that is not one, [`Error::OutOfRange`].
///
/// ```
/// use cncrot::{probe::edge, Frame};
/// let (angle, _) = edge(&Frame::IDENTITY, [0.0, 0.0, 0.0], [100.0, 100.0, 0.0]).unwrap();
/// assert!((angle - 45.0).abs() < 1e-12);
/// ```
pub fn edge(active: &Frame, e1: Vector, e2: Vector) -> Result<(f64, Frame), Error> {
    finite(&[e1, e2])?;
    crate::check_rotation(&active.rotation)?;
    let d = diff(e1, e2)?;
    if d == [0.0; 3] {
        return Err(Error::Coincident);
    }
    let local = crate::rotate_inverse(&active.rotation, crate::unit_vector(d)?);
    if sqrt(local[0] * local[0] + local[1] * local[1]) <= MIN_SINE {
        return Err(Error::Collinear);
    }
    let angle = atan2_deg(local[1], local[0]);
    let turned = active.compose(&Frame::from_rotation(elementary(Axis::Z, angle)));
    Ok((angle, turned))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{matrix_from_angles, rotate, AxisCode};

    /// Points on the plane of a frame, in machine coordinates.
    fn on(f: &Matrix, origin: Vector, x: f64, y: f64) -> Vector {
        let v = rotate(f, [x, y, 0.0]);
        core::array::from_fn(|k| origin[k] + v[k])
    }

    /// The paper's use case: a flange tilted about the machine's X by 30° and Y by 45°
    /// (extrinsic), probed along X and along Y, gives back 30 and 45 for CYCLE600.
    #[test]
    fn the_papers_flange() {
        let r = matrix_from_angles(
            Kind::Extrinsic,
            AxisCode::new(57).unwrap(),
            [30.0, 45.0, 0.0],
        );
        let n = [r[0][2], r[1][2], r[2][2]];
        // Points of the plane z = −(n_x·x + n_y·y)/n_z + 50 at machine X, Y positions.
        let z = |x: f64, y: f64| 50.0 - (n[0] * x + n[1] * y) / n[2];
        let (a1, a2) = ([10.0, 20.0, z(10.0, 20.0)], [110.0, 20.0, z(110.0, 20.0)]);
        let (b1, b2) = ([10.0, 20.0, z(10.0, 20.0)], [10.0, 90.0, z(10.0, 90.0)]);
        let f = flange(a1, a2, b1, b2).unwrap();
        assert!((f.angles[0] - 30.0).abs() < 1e-12, "{:?}", f.angles);
        assert!((f.angles[1] - 45.0).abs() < 1e-12, "{:?}", f.angles);
        assert!(f.angles[2].abs() < 1e-12, "{:?}", f.angles);
        // Independent slopes would be wrong: atan(Δz/Δy) is not the X angle here.
        let naive = ((z(10.0, 90.0) - z(10.0, 20.0)) / 70.0).atan().to_degrees();
        assert!((naive - 30.0).abs() > 1.0);
    }

    #[test]
    fn flange_refusals() {
        let o = [0.0; 3];
        let x = [100.0, 0.0, 0.0];
        assert_eq!(flange(o, o, o, [0.0, 1.0, 0.0]), Err(Error::Coincident));
        assert_eq!(flange(o, x, o, [-50.0, 0.0, 0.0]), Err(Error::Collinear));
        assert_eq!(flange(o, x, o, [f64::NAN, 1.0, 0.0]), Err(Error::NotFinite));
        assert_eq!(
            flange(
                [-f64::MAX, 0.0, 0.0],
                [f64::MAX, 0.0, 0.0],
                o,
                [0.0, 1.0, 0.0]
            ),
            Err(Error::OutOfRange)
        );
        // A1 → A2 against +X, B1 → B2 against +Y: the same plane, the same frame.
        let f = flange(x, o, [0.0, 100.0, 0.0], o).unwrap();
        assert_eq!(f.rotation, crate::IDENTITY);
    }

    #[test]
    fn least_squares_plane() {
        let r = matrix_from_angles(
            Kind::Intrinsic,
            AxisCode::new(57).unwrap(),
            [10.0, -20.0, 35.0],
        );
        let o = [5.0, -7.0, 120.0];
        let mut pts = [[0.0; 3]; 8];
        let grid = [
            (0.0, 0.0),
            (100.0, 0.0),
            (0.0, 80.0),
            (100.0, 80.0),
            (50.0, 40.0),
            (20.0, 70.0),
            (90.0, 10.0),
            (60.0, 60.0),
        ];
        for (p, &(x, y)) in pts.iter_mut().zip(&grid) {
            *p = on(&r, o, x, y);
        }
        let p = plane(&pts).unwrap();
        let d = p
            .frame
            .rotation
            .iter()
            .flatten()
            .zip(r.iter().flatten())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(d < 1e-13, "{d:e}");
        assert!(p.flatness < 1e-12 && p.rms < 1e-12);
        assert!(p
            .frame
            .translation
            .iter()
            .zip(&o)
            .all(|(a, b)| (a - b).abs() < 1e-12));
        // Two corners 0.01 above and two 0.01 below, placed so that by symmetry the fit is
        // the plane itself (Σz = Σzx = Σzy = 0): flatness exactly 0.02, rms 0.01.
        let h = 0.01;
        let sym: Vec<Vector> = [
            (1.0, 1.0, h),
            (-1.0, -1.0, h),
            (1.0, -1.0, -h),
            (-1.0, 1.0, -h),
        ]
        .iter()
        .map(|&(x, y, z)| {
            let p = rotate(&r, [50.0 * x, 50.0 * y, z]);
            core::array::from_fn(|k| o[k] + p[k])
        })
        .collect();
        let q = plane(&sym).unwrap();
        assert!((q.flatness - 2.0 * h).abs() < 1e-12, "{}", q.flatness);
        assert!((q.rms - h).abs() < 1e-12, "{}", q.rms);
        let z = [
            q.frame.rotation[0][2],
            q.frame.rotation[1][2],
            q.frame.rotation[2][2],
        ];
        assert!(z
            .iter()
            .zip(&[r[0][2], r[1][2], r[2][2]])
            .all(|(a, b)| (a - b).abs() < 1e-13));
        // Three points: exactly the PLANE POINTS frame.
        let three = plane(&pts[..3]).unwrap();
        let pp = crate::dialects::heidenhain::points(pts[0], pts[1], pts[2]).unwrap();
        let d = three
            .frame
            .rotation
            .iter()
            .flatten()
            .zip(pp.iter().flatten());
        assert!(d.map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) < 1e-14);
        assert!(three
            .frame
            .translation
            .iter()
            .zip(&pts[0])
            .all(|(a, b)| (a - b).abs() < 1e-12));
    }

    #[test]
    fn plane_refusals() {
        let o = [1.0, 2.0, 3.0];
        assert_eq!(plane(&[o, o]), Err(Error::TooFew));
        assert_eq!(plane(&[o, o, o, o]), Err(Error::Coincident));
        assert_eq!(
            plane(&[o, [2.0, 2.0, 3.0], [3.0, 2.0, 3.0], [-4.0, 2.0, 3.0]]),
            Err(Error::Collinear)
        );
        assert_eq!(
            plane(&[o, o, [f64::INFINITY, 0.0, 0.0]]),
            Err(Error::NotFinite)
        );
        // A regular tetrahedron's corners: every plane fits them alike.
        let t = [
            [1.0, 1.0, 1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, 1.0],
        ];
        assert_eq!(plane(&t), Err(Error::Degenerate));
        // Huge coordinates: scaled, no overflow.
        let big = [
            [1e300, 0.0, 0.0],
            [0.0, 1e300, 0.0],
            [0.0, 0.0, 0.0],
            [1e300, 1e300, 0.0],
        ];
        let p = plane(&big).unwrap();
        assert_eq!(p.frame.rotation[2][2], 1.0);
    }

    #[test]
    fn edges() {
        let tilt = Frame::from_rotation(matrix_from_angles(
            Kind::Extrinsic,
            AxisCode::new(57).unwrap(),
            [30.0, 45.0, 0.0],
        ));
        // An edge at 20° from X' in the tilted plane.
        let e1 = on(&tilt.rotation, [0.0; 3], 10.0, 10.0);
        let e2 = on(
            &tilt.rotation,
            [0.0; 3],
            10.0 + 20f64.to_radians().cos(),
            10.0 + 20f64.to_radians().sin(),
        );
        let (angle, turned) = edge(&tilt, e1, e2).unwrap();
        assert!((angle - 20.0).abs() < 1e-12);
        let x = [
            turned.rotation[0][0],
            turned.rotation[1][0],
            turned.rotation[2][0],
        ];
        let d = crate::unit_vector(core::array::from_fn(|k| e2[k] - e1[k])).unwrap();
        assert!(x.iter().zip(&d).all(|(a, b)| (a - b).abs() < 1e-14));
        let n = [
            tilt.rotation[0][2],
            tilt.rotation[1][2],
            tilt.rotation[2][2],
        ];
        assert_eq!(edge(&tilt, e1, e1), Err(Error::Coincident));
        assert_eq!(edge(&tilt, [0.0; 3], n), Err(Error::Collinear));
    }
}
