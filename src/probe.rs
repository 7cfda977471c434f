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
    /// `(P2 − P1) × (P3 − P1)` (so three points give `PLANE POINTS`'s rotation).
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
/// The normal is the direction in which the points spread least: the right singular vector
/// of the smallest singular value of the points about their centroid (scaled to their
/// extent, so that nothing overflows). The points are folded one by one into the 3x3
/// triangular factor R of a QR decomposition (Givens rotations; nothing is stored but R),
/// whose singular values and vectors come from one-sided Jacobi rotations, at most 10
/// sweeps of three (5 at most in practice). Nothing squares the extents, as the
/// eigenvalues of the scatter matrix would (which lost a second extent below about 1e-8 of
/// the first and gave thin sets a wrong plane): every extent is kept to about 1e-16 of the
/// first, so a thin set gets its own plane, tilted by about 1e-16 × length / width radians
/// at most (the rounding of its coordinates tilts it as much). Time linear in the number of
/// points. Three points give exactly `PLANE POINTS`'s rotation (its own construction: the
/// plane through three points is exact). Refused: [`Error::TooFew`] (fewer than 3),
/// [`Error::NotFinite`], [`Error::Coincident`] (all points equal, or the first two closer
/// than [`X_SPACING`] times the points' spread: X' undefined), [`Error::Collinear`]
/// (all on one line: the second extent, the second singular value, at most [`MIN_SINE`]
/// times the first), [`Error::Degenerate`] (four or more points whose two smallest extents
/// differ by at most [`MIN_SINE`] times the largest, e.g. spread equally in every direction:
/// no plane is best), [`Error::OutOfRange`].
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
    let e = extents(points)?;
    // The first two points apart (else "coincide", not "collinear").
    x_defined(points)?;
    determined(e.sigma, points.len())?;
    let rotation = if points.len() == 3 {
        // PLANE POINTS refuses a sine at P1 of at most MIN_SINE; for three nearly collinear
        // points the sine at any corner is at least 2/√3 times middle/largest, so
        // `determined` has already refused whatever it would.
        crate::rotation_from_x_y(diff(p1, points[1])?, diff(p1, points[2])?)
            .map_err(|_| Error::Collinear)?
    } else {
        let mut n = e.normal;
        // The side of (P2 − P1) × (P3 − P1), as PLANE POINTS; where those three are
        // collinear, the +Z side, then +Y, then +X [choice]. Of the unit vectors: the
        // product of differences beyond 1e154 overflows, and ∞ − ∞ would leave no side.
        let a = crate::unit_vector(diff(p1, points[1])?);
        let b = crate::unit_vector(diff(p1, points[2])?);
        let side = match (a, b) {
            (Ok(a), Ok(b)) => cross(a, b),
            // P2 or P3 is P1.
            _ => [0.0; 3],
        };
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
        // X' along P1 → P2 in the plane; where that is along the normal, the machine's X,
        // then Y.
        let hints = [diff(p1, points[1])?, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        hints
            .iter()
            .find_map(|&h| rotation_from_z_x(n, h).ok())
            .ok_or(Error::Degenerate)?
    };
    let c = e.centroid;
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

/// The share of the points' spread below which the first two points' distance defines no
/// X' \[choice: a point probed twice, or 2 µm apart on a part of 100 mm,
/// gave an X' of the probe's noise, turned by any angle\].
pub const X_SPACING: f64 = 1e-3;

/// Refuses ([`Error::Coincident`]) points whose first two lie closer than [`X_SPACING`]
/// times the largest distance of a point from the first: X' runs from the first to the
/// second.
fn x_defined(points: &[Vector]) -> Result<(), Error> {
    // Scaled by the largest coordinate, so that no difference overflows.
    let scale = points
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(crate::math::abs(*x)));
    let from =
        |p: &Vector| -> Vector { core::array::from_fn(|i| p[i] / scale - points[0][i] / scale) };
    let along = from(&points[1]);
    let far = points
        .iter()
        .map(|p| {
            let q = from(p);
            dot(q, q)
        })
        .fold(0.0f64, f64::max);
    // Written so that NaN refuses.
    if dot(along, along) > X_SPACING * X_SPACING * far {
        Ok(())
    } else {
        Err(Error::Coincident)
    }
}

/// [`plane`] with Z' on the side of `toward` (a direction, any length): the side the tool
/// comes from. `[0, 0, 1]` is the machine's +Z, the default of `cncrot_probe_plane`: the
/// same corners probed clockwise or anticlockwise give the same plane, the right way up. A
/// plane whose Z' points away from `toward` is turned half a turn about its X' (X' stays
/// along P1 → P2, Y' and Z' change sign); the second value says whether it was. Zero
/// `toward`, or a Z' square to it, keeps the order of the points (`PLANE POINTS`'s rule:
/// Z' on the side of `(P2 − P1) × (P3 − P1)`). Refused: as [`plane`], and
/// [`Error::NotFinite`] for `toward`.
///
/// ```
/// use cncrot::probe::{plane, plane_toward};
/// // Four corners of a plane tilted 5.71° about Y, probed clockwise (seen from above):
/// // the order alone puts Z' below the plane, toward the table.
/// let pts = [[0.0, 0.0, 0.0], [0.0, 50.0, 0.0], [100.0, 50.0, -10.0], [100.0, 0.0, -10.0]];
/// assert!(plane(&pts).unwrap().frame.rotation[2][2] < 0.0);
/// let (p, turned) = plane_toward(&pts, [0.0, 0.0, 1.0]).unwrap();
/// assert!(turned && p.frame.rotation[2][2] > 0.99);
/// ```
pub fn plane_toward(points: &[Vector], toward: Vector) -> Result<(Plane, bool), Error> {
    if !toward.iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    let mut p = plane(points)?;
    // Scaled to its largest component: the dot product cannot overflow.
    let m = toward
        .iter()
        .fold(0.0, |m: f64, x| m.max(crate::math::abs(*x)));
    let t = if m > 0.0 {
        toward.map(|x| x / m)
    } else {
        toward
    };
    let r = p.frame.rotation;
    let turned = dot([r[0][2], r[1][2], r[2][2]], t) < 0.0;
    if turned {
        // 0 − x, not −x: no −0 in a result.
        for row in p.frame.rotation.iter_mut() {
            row[1] = 0.0 - row[1];
            row[2] = 0.0 - row[2];
        }
    }
    Ok((p, turned))
}

/// Refuses the extents `sigma` (largest first) of `points` points when they determine no
/// plane: a second extent at most [`MIN_SINE`] times the first (collinear), or, past three
/// points, the two smallest differing by at most [`MIN_SINE`] times the first (degenerate:
/// the normal's error is about the rounding of the largest extent over that gap; three
/// points always have a smallest extent of zero).
fn determined([largest, middle, smallest]: [f64; 3], points: usize) -> Result<(), Error> {
    if middle <= MIN_SINE * largest {
        Err(Error::Collinear)
    } else if points > 3 && middle - smallest <= MIN_SINE * largest {
        Err(Error::Degenerate)
    } else {
        Ok(())
    }
}

/// Sweeps of Jacobi rotations at most: twice what any point set tried needs (at most 5; the
/// test `jacobi_converges_in_few_sweeps`), so that the time stays bounded whatever the
/// points.
const SWEEPS: usize = 10;

/// The points about their centroid: the centroid, the extents (the singular values of the
/// centred points scaled to at most 1 per coordinate, largest first) and the unit direction
/// of the smallest.
struct Extents {
    centroid: Vector,
    sigma: [f64; 3],
    normal: Vector,
}

/// The extents of `points` (at least one, all finite); refused: [`Error::Coincident`] (all
/// equal), [`Error::OutOfRange`] (a coordinate's distance from the centroid overflows).
fn extents(points: &[Vector]) -> Result<Extents, Error> {
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
    let (sigma, v, _) = jacobi(&triangular(points, c, scale));
    // Largest first.
    let mut s = [(sigma[0], v[0]), (sigma[1], v[1]), (sigma[2], v[2])];
    for (i, j) in [(0, 1), (1, 2), (0, 1)] {
        if s[i].0 < s[j].0 {
            s.swap(i, j);
        }
    }
    let [(s1, _), (s2, _), (s3, normal)] = s;
    Ok(Extents {
        centroid: c,
        sigma: [s1, s2, s3],
        normal,
    })
}

/// `sqrt(a² + b²)`, `a` and `b` not both zero, without overflow or underflow on the way.
fn hypot(a: f64, b: f64) -> f64 {
    let (a, b) = (crate::math::abs(a), crate::math::abs(b));
    let (big, small) = if a < b { (b, a) } else { (a, b) };
    let q = small / big;
    big * sqrt(1.0 + q * q)
}

/// The rows `(p − c) / scale` folded one by one into the upper triangular R of their QR
/// decomposition by Givens rotations, so that RᵀR is their scatter matrix without forming
/// it: its entries would square the extents and lose a small one in the rounding of a large
/// one.
fn triangular(points: &[Vector], c: Vector, scale: f64) -> Matrix {
    let mut r = [[0.0; 3]; 3];
    for p in points {
        let mut row: Vector = core::array::from_fn(|i| (p[i] - c[i]) / scale);
        for k in 0..3 {
            if row[k] == 0.0 {
                continue;
            }
            let rho = hypot(r[k][k], row[k]);
            let (cos, sin) = (r[k][k] / rho, row[k] / rho);
            r[k][k] = rho;
            for j in k + 1..3 {
                let (x, y) = (r[k][j], row[j]);
                r[k][j] = cos * x + sin * y;
                row[j] = cos * y - sin * x;
            }
        }
    }
    r
}

/// The singular values of `r` (unsorted), the right singular vectors (the same order) and
/// the sweeps that turned something: one-sided Jacobi, which turns pairs of columns of
/// A = R·V until all are orthogonal; then A's columns have the singular values as lengths.
/// It works on the columns themselves, never on their products, so small singular values
/// keep their accuracy.
fn jacobi(r: &Matrix) -> ([f64; 3], [Vector; 3], usize) {
    let mut a: [Vector; 3] = core::array::from_fn(|j| [r[0][j], r[1][j], r[2][j]]);
    let mut v = crate::IDENTITY;
    // A column this short is rounding of the whole matrix: turning it against another would
    // only stir that rounding (and never end: each turn leaves a new residue).
    let floor2 = f64::EPSILON * f64::EPSILON * r.iter().flatten().map(|x| x * x).sum::<f64>();
    let mut sweeps = 0;
    while sweeps < SWEEPS {
        let [a0, a1, a2] = &mut a;
        let [v0, v1, v2] = &mut v;
        let t01 = turn(a0, a1, v0, v1, floor2);
        let t02 = turn(a0, a2, v0, v2, floor2);
        let t12 = turn(a1, a2, v1, v2, floor2);
        if !(t01 || t02 || t12) {
            break;
        }
        sweeps += 1;
    }
    (a.map(|x| sqrt(dot(x, x))), v, sweeps)
}

/// One Jacobi rotation that makes the columns `a` and `b` orthogonal, applied to the
/// columns `va`, `vb` of V too; false (nothing turned) when they are orthogonal to rounding
/// or either is shorter than √`floor2`.
fn turn(a: &mut Vector, b: &mut Vector, va: &mut Vector, vb: &mut Vector, floor2: f64) -> bool {
    let (alpha, beta, gamma) = (dot(*a, *a), dot(*b, *b), dot(*a, *b));
    // 4 ε, not ε: at ε the rounding of a turn can undo the last one indefinitely.
    if crate::math::abs(gamma) <= 4.0 * f64::EPSILON * sqrt(alpha) * sqrt(beta)
        || alpha.min(beta) <= floor2
    {
        return false;
    }
    // t = tan θ of the smaller turn that zeroes a·b: cot 2θ = ζ, t² + 2ζt − 1 = 0.
    let zeta = (beta - alpha) / (2.0 * gamma);
    let t = 1.0 / (crate::math::abs(zeta) + hypot(1.0, zeta));
    let t = if zeta < 0.0 { -t } else { t };
    let cos = 1.0 / sqrt(1.0 + t * t);
    let sin = cos * t;
    for (x, y) in [(a, b), (va, vb)] {
        let (p, q) = (*x, *y);
        *x = core::array::from_fn(|k| cos * p[k] - sin * q[k]);
        *y = core::array::from_fn(|k| sin * p[k] + cos * q[k]);
    }
    true
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

    /// The Z column of a rotation.
    fn z_of(m: &Matrix) -> Vector {
        [m[0][2], m[1][2], m[2][2]]
    }

    fn max_diff(a: &Matrix, b: &Matrix) -> f64 {
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    }

    /// The angle between two unit vectors pointing the same way (radians, for small angles);
    /// opposite ones give more than 1.
    fn tilt(a: Vector, b: Vector) -> f64 {
        if dot(a, b) <= 0.0 {
            return 2.0;
        }
        let c = cross(a, b);
        sqrt(dot(c, c))
    }

    /// A tilted plane whose normal is exact: N = (2, 3, 6)/7, in the plane U = (3, −2, 0) and
    /// V = 7N × U = (12, 18, −13) (|U| = √13, |V| = 7√13, U × V = 13·7N). The point
    /// O + a·U + b·V for small dyadic a and b is an exact double, so a point set built from
    /// them lies exactly in a plane of normal N.
    fn tilted(a: f64, b: f64) -> Vector {
        let (o, u, v) = ([5.0, -7.0, 120.0], [3.0, -2.0, 0.0], [12.0, 18.0, -13.0]);
        core::array::from_fn(|k| o[k] + a * u[k] + b * v[k])
    }

    const TILTED_NORMAL: Vector = [2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0];

    /// Issue 20, class 5: the closed-form eigenvalues of the scatter matrix lost the two
    /// small ones, so thin sets got a wrong plane with success. A backward-stable fit moves
    /// each point by about ε times the set's extent, which tilts a set of length L and width
    /// W by about ε·L/W: that is the tolerance.
    #[test]
    fn thin_point_sets_give_their_own_plane() {
        // The issue's three points: PLANE POINTS's frame, normal +Z (the apex is off the
        // line towards +Y, so (P2 − P1) × (P3 − P1) is along +Z).
        let three = [[0.0, 0.0, 0.0], [100.0, 0.0, 0.0], [50.0, 1e-6, 0.0]];
        let p = plane(&three).unwrap();
        let pp = crate::dialects::heidenhain::points(three[0], three[1], three[2]).unwrap();
        assert!(
            max_diff(&p.frame.rotation, &pp) <= 1e-15,
            "{:?}",
            p.frame.rotation
        );
        assert!(tilt(z_of(&p.frame.rotation), [0.0, 0.0, 1.0]) <= 1e-15);

        // An apex 2⁻¹¹·7√13 = 0.0123 mm off a line 28√13 = 101 mm long (L/W = 8192), on the
        // tilted plane: three points, then four (the fourth on the line).
        let eps = f64::EPSILON;
        let b = 2f64.powi(-11);
        let apex = [
            tilted(-14.0, 0.0),
            tilted(14.0, 0.0),
            tilted(0.0, b),
            tilted(3.0, 0.0),
        ];
        for n in [3, 4] {
            let p = plane(&apex[..n]).unwrap();
            let t = tilt(z_of(&p.frame.rotation), TILTED_NORMAL);
            assert!(t <= eps * 8192.0, "{n} points: {t:e}");
        }
        let p = plane(&apex[..3]).unwrap();
        let pp = crate::dialects::heidenhain::points(apex[0], apex[1], apex[2]).unwrap();
        assert!(max_diff(&p.frame.rotation, &pp) <= 1e-15);

        // Four exactly coplanar points on a strip 101 mm × 2⁻¹⁸·7√13 = 9.6e-5 mm.
        let w = 2f64.powi(-18);
        let strip = [
            tilted(-14.0, 0.0),
            tilted(14.0, 0.0),
            tilted(14.0, w),
            tilted(-14.0, w),
        ];
        let p = plane(&strip).unwrap();
        let t = tilt(z_of(&p.frame.rotation), TILTED_NORMAL);
        assert!(t <= eps * 4.0 * 2f64.powi(18), "{t:e}");
        assert!(p.flatness <= 1e-12, "{}", p.flatness);

        // Ever thinner: the true plane, or refused as collinear once the width is near
        // MIN_SINE times the length; never another plane.
        for k in 1..=44 {
            let w = 2f64.powi(-k);
            let set = [
                tilted(-14.0, 0.0),
                tilted(14.0, 0.0),
                tilted(5.0, w),
                tilted(-9.0, -0.5 * w),
                tilted(1.0, 0.25 * w),
            ];
            let length_over_width = 28.0 / (7.0 * w);
            match plane(&set) {
                Ok(p) => {
                    let t = tilt(z_of(&p.frame.rotation), TILTED_NORMAL);
                    assert!(t <= eps * length_over_width, "2^-{k}: {t:e}");
                }
                Err(e) => {
                    assert_eq!(e, Error::Collinear, "2^-{k}");
                    assert!(length_over_width >= 0.1 / MIN_SINE, "2^-{k} refused");
                }
            }
        }
    }

    /// The Jacobi sweeps stay far below their bound, SWEEPS, on point sets of every shape:
    /// extents over 20 orders of magnitude, nearly equal ones, flat and thin sets, turned.
    #[test]
    fn jacobi_converges_in_few_sweeps() {
        let mut rng = crate::math::Xorshift(0x9E37_79B9_7F4A_7C15);
        let mut most = 0;
        let mut worst: f64 = 0.0;
        let mut histogram = [0usize; SWEEPS + 1];
        for t in 0..100_000 {
            let n = 3 + t % 10;
            let e0 = 10f64.powf(20.0 * rng.unit() - 10.0);
            let mut small = || 10f64.powf(-16.0 * rng.unit());
            let extent = match t % 4 {
                0 => [e0, e0 * small(), e0 * small() * small()],
                1 => [
                    e0,
                    e0 * (1.0 + 1e-12 * small()),
                    e0 * (1.0 + 1e-6 * small()),
                ],
                2 => [e0, e0, e0 * small()],
                _ => [e0, e0 * small(), e0 * small()],
            };
            let turn = matrix_from_angles(
                Kind::Intrinsic,
                AxisCode::new(57).unwrap(),
                [360.0 * rng.unit(), 360.0 * rng.unit(), 360.0 * rng.unit()],
            );
            let pts: Vec<Vector> = (0..n)
                .map(|_| rotate(&turn, extent.map(|e| e * (rng.unit() - 0.5))))
                .collect();
            let e = extents(&pts);
            let Ok(Extents { centroid, .. }) = e else {
                continue;
            };
            let scale = pts
                .iter()
                .flatten()
                .zip([0, 1, 2].iter().cycle())
                .map(|(x, &i)| (x - centroid[i]).abs())
                .fold(0.0, f64::max);
            let (_, v, sweeps) = jacobi(&triangular(&pts, centroid, scale));
            worst = worst.max(crate::orthonormality_error(&v));
            histogram[sweeps] += 1;
            most = most.max(sweeps);
        }
        assert!(most <= SWEEPS / 2, "{histogram:?}");
        // Each turn rounds V by about ε, and at most 15 (5 sweeps) were made.
        assert!(worst <= 16.0 * f64::EPSILON, "{worst:e}");
        // Most sets need 2 to 4 sweeps: the count is the iteration's, not a constant.
        assert!(histogram[3] > 10_000, "{histogram:?}");
    }

    /// X' runs from the first point to the second: closer than [`X_SPACING`] of the
    /// points' spread (a point probed twice, 2 µm apart on a part of 141 mm) they define
    /// none, and are refused as coinciding; at 0.2 mm the plane is measured.
    #[test]
    fn plane_needs_its_first_two_points_apart() {
        let rest = [
            [100.0, 0.0, -10.0],
            [0.0, 100.0, 0.0],
            [100.0, 100.0, -10.0],
        ];
        let with = |p2: Vector| {
            let mut v = vec![[0.0; 3], p2];
            v.extend(rest);
            plane(&v)
        };
        assert_eq!(with([0.0, 0.0, 0.002]).err(), Some(Error::Coincident));
        assert_eq!(with([0.001, 0.001, 0.0]).err(), Some(Error::Coincident));
        assert_eq!(with([0.0; 3]).err(), Some(Error::Coincident));
        let p = with([0.2, 0.0, -0.02]).unwrap();
        // X' along (1, 0, -0.1) made perpendicular to the fit's normal: in the XZ plane.
        assert!(
            p.frame.rotation[1][0].abs() < 1e-9,
            "{:?}",
            p.frame.rotation
        );
        assert_eq!(
            plane(&[[0.0; 3], [0.0, 0.0, 1e-4], [100.0, 0.0, 0.0]]).err(),
            Some(Error::Coincident)
        );
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

    // The thresholds, tested where they are: each refusal at the first value that must be
    // refused and its acceptance one step beyond, so that a comparison turned the other way,
    // made strict or dropped fails (cargo mutants found them tested only far away).
    // sqrt(x·x) == x for doubles (no underflow), which makes the ties exact; each test
    // checks its tie before relying on it.

    /// The sine of flange's two directions is at most MIN_SINE: refused; the next double
    /// above: a plane.
    #[test]
    fn flange_at_min_sine() {
        let o = [0.0; 3];
        let x = [1.0, 0.0, 0.0];
        let at = [1.0, MIN_SINE, 0.0];
        let above = [1.0, f64::from_bits(MIN_SINE.to_bits() + 1), 0.0];
        assert_eq!(sine(x, at), Ok(MIN_SINE));
        assert!(sine(x, above).unwrap() > MIN_SINE);
        assert_eq!(flange(o, x, o, at), Err(Error::Collinear));
        assert_eq!(flange(o, x, o, above).unwrap().rotation, crate::IDENTITY);
    }

    /// flange's two choices at their boundary: a vertical flange keeps the cross product's
    /// side (n = X × Z = −Y, so the frame is Rx(90°), not Rx(−90°)), and A1 → A2 with no X
    /// component is not turned (X' = +Y: Rz(90°), not Rz(−90°)).
    #[test]
    fn flange_sides_at_zero() {
        let o = [0.0; 3];
        let (x, y, z) = ([100.0, 0.0, 0.0], [0.0, 100.0, 0.0], [0.0, 0.0, 100.0]);
        let vertical = flange(o, x, o, z).unwrap();
        assert_eq!(
            vertical.rotation,
            [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
        );
        assert!(
            (vertical.angles[0] - 90.0).abs() < 1e-12,
            "{:?}",
            vertical.angles
        );
        let along_y = flange(o, y, o, x).unwrap();
        assert_eq!(
            along_y.rotation,
            [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
        );
    }

    /// An edge whose component in the plane is MIN_SINE of its length (along X' or along
    /// Y'): refused; the next double above: a turn of 0° or 90°.
    #[test]
    fn edge_at_min_sine() {
        let f = Frame::IDENTITY;
        let above = f64::from_bits(MIN_SINE.to_bits() + 1);
        let o = [0.0; 3];
        assert_eq!(edge(&f, o, [MIN_SINE, 0.0, 1.0]), Err(Error::Collinear));
        assert_eq!(edge(&f, o, [0.0, MIN_SINE, 1.0]), Err(Error::Collinear));
        assert_eq!(edge(&f, o, [above, 0.0, 1.0]).unwrap().0, 0.0);
        assert_eq!(edge(&f, o, [0.0, above, 1.0]).unwrap().0, 90.0);
    }

    /// The criteria on the extents, at their ties: a second extent MIN_SINE times the first
    /// is collinear, the next double above is not; two smallest extents MIN_SINE times the
    /// first apart are degenerate past three points, the next double further apart is not.
    #[test]
    fn extents_at_min_sine() {
        let up = |x: f64| f64::from_bits(x.to_bits() + 1);
        let down = |x: f64| f64::from_bits(x.to_bits() - 1);
        let m = MIN_SINE;
        for n in [3, 4] {
            assert_eq!(determined([1.0, m, 0.0], n), Err(Error::Collinear));
            assert_eq!(determined([2.0, 2.0 * m, 0.0], n), Err(Error::Collinear));
            assert_eq!(determined([1.0, up(m), 0.0], n), Ok(()));
        }
        assert_eq!(determined([1.0, 2.0 * m, m], 4), Err(Error::Degenerate));
        assert_eq!(determined([1.0, 2.0 * m, down(m)], 4), Ok(()));
        assert_eq!(determined([1.0, 2.0 * m, m], 3), Ok(()));
        assert_eq!(determined([1.0, 1.0, 1.0], 4), Err(Error::Degenerate));
        assert_eq!(determined([1.0, 0.5, 0.5], 4), Err(Error::Degenerate));
        assert_eq!(determined([1.0, 0.5, 0.25], 4), Ok(()));
    }

    /// The same through plane: (0, ±b, 0), (±1, 0, 0), whose extents are exactly √2 and
    /// √2·b (the running mean of ±pairs in this order is exactly 0), at the tie b = MIN_SINE
    /// and the next double above; and six points with extents √2·(1, 2e-12, c) on either
    /// side of the degenerate threshold, c = 1e-12.
    #[test]
    fn plane_at_min_sine() {
        // X' from the first point to the second: those two far apart.
        let pairs = |b: f64| {
            [
                [-1.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, b, 0.0],
                [0.0, -b, 0.0],
            ]
        };
        let at = pairs(MIN_SINE);
        let e = extents(&at).unwrap();
        assert_eq!(e.centroid, [0.0; 3]);
        assert_eq!(e.sigma[1], MIN_SINE * e.sigma[0]);
        assert_eq!(plane(&at), Err(Error::Collinear));
        let above = pairs(f64::from_bits(MIN_SINE.to_bits() + 1));
        let e = extents(&above).unwrap();
        assert!(e.sigma[1] > MIN_SINE * e.sigma[0]);
        assert_eq!(
            z_of(&plane(&above).unwrap().frame.rotation),
            [0.0, 0.0, 1.0]
        );
        let six = |c: f64| {
            [
                [1.0, 0.0, 0.0],
                [-1.0, 0.0, 0.0],
                [0.0, 2.0 * MIN_SINE, 0.0],
                [0.0, -2.0 * MIN_SINE, 0.0],
                [0.0, 0.0, c],
                [0.0, 0.0, -c],
            ]
        };
        assert_eq!(plane(&six(1.5 * MIN_SINE)), Err(Error::Degenerate));
        let p = plane(&six(0.5 * MIN_SINE)).unwrap();
        assert_eq!(z_of(&p.frame.rotation).map(f64::abs), [0.0, 0.0, 1.0]);
    }

    /// What cargo mutants found untested in plane besides its thresholds: the origin is the
    /// first point's foot on the plane (not the point, nor its mirror image), never −0, and
    /// a flatness beyond the largest double is refused, not returned; and the side of
    /// points so far apart that the cross product of their differences overflows.
    #[test]
    fn plane_origin_and_overflow() {
        // The doc example: the plane z = 5, P1 0.01 above it.
        let p = plane(&[
            [0.0, 0.0, 5.01],
            [100.0, 100.0, 5.01],
            [0.0, 100.0, 4.99],
            [100.0, 0.0, 4.99],
        ])
        .unwrap();
        let t = p.frame.translation;
        assert!(
            t.iter()
                .zip(&[0.0, 0.0, 5.0])
                .all(|(a, b)| (a - b).abs() < 1e-12),
            "{t:?}"
        );
        // P1 = (−0, 0, 0) on the plane z = 0: its foot is itself, written +0.
        let p = plane(&[
            [-0.0, 0.0, 0.0],
            [100.0, 0.0, 0.0],
            [0.0, 100.0, 0.0],
            [100.0, 100.0, 0.0],
        ])
        .unwrap();
        assert_eq!(p.frame.translation.map(f64::to_bits), [0; 3]);
        // ±(a, a, a) at ±√3·a = ±1.3e308 from the plane x + y + z = 0, along which twice six
        // points spread more: the flatness 2.6e308 overflows.
        let a = 0.75e308;
        let mut pts = vec![[a, a, a], [-a, -a, -a]];
        for _ in 0..2 {
            for u in [[a, -a, 0.0], [a, 0.0, -a], [0.0, a, -a]] {
                pts.push(u);
                pts.push(u.map(|x| -x));
            }
        }
        assert_eq!(plane(&pts), Err(Error::OutOfRange));
        // The same set scaled by 2⁻⁹⁰⁰: a plane, normal (1, 1, 1)/√3.
        let small: Vec<Vector> = pts.iter().map(|p| p.map(|x| x * 2f64.powi(-900))).collect();
        let z = z_of(&plane(&small).unwrap().frame.rotation).map(f64::abs);
        let third = (1.0f64 / 3.0).sqrt();
        assert!(z.iter().all(|x| (x - third).abs() < 1e-15), "{z:?}");
        // (P2 − P1) × (P3 − P1) = (0, 0, −1e600): from the differences themselves, 1e600 −
        // 1e600 would be ∞ − ∞ and no side; it is −Z.
        let huge = [
            [0.0, 0.0, 0.0],
            [1e300, 1e300, 0.0],
            [2e300, 1e300, 0.0],
            [0.0, 1e300, 0.0],
        ];
        assert_eq!(
            z_of(&plane(&huge).unwrap().frame.rotation),
            [0.0, 0.0, -1.0]
        );
    }

    /// The side of plane's normal: that of (P2 − P1) × (P3 − P1); where P1, P2, P3 are
    /// collinear, +Z, then +Y, then +X. Each case gives another answer under the next rule.
    #[test]
    fn plane_side_rules() {
        let r2 = 0.5f64.sqrt();
        let normal = |pts: &[Vector]| z_of(&plane(pts).unwrap().frame.rotation);
        let near = |a: Vector, b: Vector| a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15);
        // (P2 − P1) × (P3 − P1) along −Z: Z' = −Z although it has a Z component.
        let down = [
            [0.0, 0.0, 0.0],
            [100.0, 0.0, 0.0],
            [0.0, -50.0, 0.0],
            [100.0, -50.0, 0.0],
        ];
        let p = plane(&down).unwrap();
        assert!(
            max_diff(
                &p.frame.rotation,
                &[[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]
            ) < 1e-15
        );
        // P1, P2, P3 on the X axis, the plane y = z: the +Z side, (0, −1, 1)/√2 (the +Y
        // side would be the opposite).
        let yz = [
            [3.0, 0.0, 0.0],
            [-3.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.0, 4.0, 4.0],
            [0.0, -4.0, -4.0],
        ];
        assert!(near(normal(&yz), [0.0, -r2, r2]), "{:?}", normal(&yz));
        // P1, P2, P3 on the line x = y, z = 0, the vertical plane x = y: the normal's Z
        // component is exactly 0 (the Z coordinates are decoupled from X and Y), so the +Y
        // side, (−1, 1, 0)/√2 (the +X side would be the opposite).
        let xy = [
            [3.0, 3.0, 0.0],
            [-3.0, -3.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 4.0],
            [0.0, 0.0, -4.0],
        ];
        let n = normal(&xy);
        assert_eq!(n[2], 0.0);
        assert!(near(n, [-r2, r2, 0.0]), "{n:?}");
        // The plane x = 0 through P1, P2, P3 on the Y axis: the +X side.
        let x0 = [
            [0.0, 3.0, 0.0],
            [0.0, -3.0, 0.0],
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 4.0],
            [0.0, 0.0, -4.0],
        ];
        assert_eq!(normal(&x0), [1.0, 0.0, 0.0]);
    }
}
