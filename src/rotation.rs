//! Rotation matrices: composition from angles, decomposition into angles for all 24
//! conventions, conversion, validation, additive rotations and rotating vectors.
//!
//! Matrices are row-major `[[f64; 3]; 3]` (`m[i-1][j-1]` is the paper's `A_ij`), the layout
//! of the C boundary's `double[9]`. Angles are in degrees.

use crate::math::{self, sin_cos_deg, sqrt, wrap_deg, Lanes, F4};
use crate::{Axis, AxisCode, Convention, Error, Kind, Sequence};

/// A 3x3 matrix, row-major: `m[i][j]` is row `i`, column `j` (0-based).
pub type Matrix = [[f64; 3]; 3];

/// A 3-vector.
pub type Vector = [f64; 3];

/// The identity matrix.
pub const IDENTITY: Matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// How far from orthonormal a matrix may be and still be accepted as a rotation:
/// the largest element of `MᵀM − I`. Matrices printed to four decimals, like the paper's,
/// stay below 2e-4; anything more distorted (raw probe data) must go through
/// [`nearest_rotation`] deliberately.
pub const ROTATION_TOLERANCE: f64 = 1e-3;

/// Below this norm of the first-angle pair (`|cos θ2|` for Tait-Bryan, `|sin θ2|` for proper
/// Euler) a decomposition is treated as singular. Measured: with it the reconstruction error
/// stays below 1e-15 on both sides of the threshold (see `tests/accuracy.rs`).
const SINGULAR_NORM: f64 = 2.0 * f64::EPSILON;

/// Angles of a rotation in one convention.
///
/// ```
/// use cncrot::{angles_from_matrix, matrix_from_angles, Convention, Kind, Sequence};
/// let conv = Convention::new(Kind::Intrinsic, Sequence::ZYX);
/// let m = matrix_from_angles(Kind::Intrinsic, Sequence::ZYX.into(), [40.0, 90.0, 10.0]);
/// let d = angles_from_matrix(conv, &m).unwrap();
/// // Singular: only θ1 - θ3 is determined, and θ3 = 0 by rule (SINUMERIK reads back 30, 90, 0).
/// assert!(d.singular);
/// assert!((d.angles[0] - 30.0).abs() < 1e-12 && d.angles[1] == 90.0 && d.angles[2] == 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposition {
    /// θ1, θ2, θ3 in degrees, in rotation order (the angle of the first rotation first).
    pub angles: [f64; 3],
    /// The middle angle is at its singular value (θ2 = ±90° Tait-Bryan, 0°/180° proper
    /// Euler): only θ1 ± θ3 is determined and θ3 was set to 0.
    pub singular: bool,
}

/// The rotation about one axis by an angle in degrees (active, right-handed).
///
/// ```
/// use cncrot::{elementary, Axis};
/// assert_eq!(elementary(Axis::Z, 90.0), [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
/// ```
pub fn elementary(axis: Axis, deg: f64) -> Matrix {
    let (s, c) = sin_cos_deg(deg);
    let n = -s + 0.0;
    match axis {
        Axis::X => [[1.0, 0.0, 0.0], [0.0, c, n], [0.0, s, c]],
        Axis::Y => [[c, 0.0, s], [0.0, 1.0, 0.0], [n, 0.0, c]],
        Axis::Z => [[c, n, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]],
    }
}

/// Matrix product `a · b`.
#[inline]
pub fn mul(a: &Matrix, b: &Matrix) -> Matrix {
    let mut r = [[0.0; 3]; 3];
    for (ri, ai) in r.iter_mut().zip(a) {
        for (j, rij) in ri.iter_mut().enumerate() {
            *rij = ai[0] * b[0][j] + ai[1] * b[1][j] + ai[2] * b[2][j] + 0.0;
        }
    }
    r
}

/// The transpose, which for a rotation is its inverse.
#[inline]
pub fn transpose(m: &Matrix) -> Matrix {
    [
        [m[0][0], m[1][0], m[2][0]],
        [m[0][1], m[1][1], m[2][1]],
        [m[0][2], m[1][2], m[2][2]],
    ]
}

/// The rotation matrix of three angles (degrees) in a convention.
///
/// Intrinsic: `R = R_a1(θ1)·R_a2(θ2)·R_a3(θ3)`; extrinsic: `R = R_a3(θ3)·R_a2(θ2)·R_a1(θ1)`.
/// Slots whose code pair is `00` are skipped (their angle is ignored). Multiples of 90°
/// give exact 0 and ±1. Non-finite angles give non-finite elements (the C boundary refuses
/// them before calling).
///
/// ```
/// use cncrot::{matrix_from_angles, Kind, Sequence};
/// // Paper, Example 2: extrinsic X, Y, Z = 30°, 45°, 60°.
/// let m = matrix_from_angles(Kind::Extrinsic, Sequence::XYZ.into(), [30.0, 45.0, 60.0]);
/// assert!((m[0][0] - 0.3536).abs() < 1e-4 && (m[2][0] + 0.7071).abs() < 1e-4);
/// ```
pub fn matrix_from_angles(kind: Kind, code: AxisCode, angles_deg: [f64; 3]) -> Matrix {
    matrix_from_angles_inline(kind, code, angles_deg)
}

/// [`matrix_from_angles`], inlined into the C boundary's row functions, where the matrix
/// then stays in registers.
#[inline(always)]
pub(crate) fn matrix_from_angles_inline(
    kind: Kind,
    code: AxisCode,
    angles_deg: [f64; 3],
) -> Matrix {
    let Ok(seq) = Sequence::from_axis_code(code) else {
        return matrix_from_slots(kind, code, angles_deg);
    };
    // Extrinsic is the intrinsic reversed sequence with the angles reversed (paper eq. 13).
    let (seq, [a, b, c]) = match kind {
        Kind::Intrinsic => (seq, angles_deg),
        Kind::Extrinsic => (
            seq.reversed(),
            [angles_deg[2], angles_deg[1], angles_deg[0]],
        ),
    };
    let m = match seq {
        Sequence::XYZ => tait_bryan_matrix::<0, 1, 2>(a, b, c),
        Sequence::XZY => tait_bryan_matrix::<0, 2, 1>(a, b, c),
        Sequence::YXZ => tait_bryan_matrix::<1, 0, 2>(a, b, c),
        Sequence::YZX => tait_bryan_matrix::<1, 2, 0>(a, b, c),
        Sequence::ZXY => tait_bryan_matrix::<2, 0, 1>(a, b, c),
        Sequence::ZYX => tait_bryan_matrix::<2, 1, 0>(a, b, c),
        Sequence::XYX => proper_euler_matrix::<0, 1, 2>(a, b, c),
        Sequence::XZX => proper_euler_matrix::<0, 2, 1>(a, b, c),
        Sequence::YXY => proper_euler_matrix::<1, 0, 2>(a, b, c),
        Sequence::YZY => proper_euler_matrix::<1, 2, 0>(a, b, c),
        Sequence::ZXZ => proper_euler_matrix::<2, 0, 1>(a, b, c),
        Sequence::ZYZ => proper_euler_matrix::<2, 1, 0>(a, b, c),
    };
    // `+ 0.0`: no element is ever -0.
    m.map(|row| row.map(|v| v + 0.0))
}

/// The sines of the three angles, times the parity `e` of (I, J, K), and their cosines.
///
/// An odd permutation of the axes is a reflection, which turns every rotation the other way:
/// `R_I(a)·R_J(b)·R_K(c)` with (I, J, K) odd is the matrix of the even case with all three
/// sines negated, its elements relabelled. So one closed form per family serves all six
/// sequences, with `e·sin`.
#[inline(always)]
fn parity_sin_cos<const I: usize, const J: usize>(angles: [f64; 3]) -> [(f64, f64); 3] {
    let odd = (I + 1) % 3 != J;
    // The three in the lanes of one vector computation.
    let (s, c) = math::sin_cos_deg4([angles[0], angles[1], angles[2], 0.0]);
    let e = if odd { -1.0 } else { 1.0 };
    [(e * s[0], c[0]), (e * s[1], c[1]), (e * s[2], c[2])]
}

/// Intrinsic `R_I(a)·R_J(b)·R_K(c)`, I, J, K all different, in closed form: 12
/// multiplications instead of the 36 of three turns (the inverse of `tait_bryan`).
#[inline(always)]
fn tait_bryan_matrix<const I: usize, const J: usize, const K: usize>(
    a: f64,
    b: f64,
    c: f64,
) -> Matrix {
    let [(sa, ca), (sb, cb), (sc, cc)] = parity_sin_cos::<I, J>([a, b, c]);
    let (sa_sb, ca_sb) = (sa * sb, ca * sb);
    let mut r = [[0.0; 3]; 3];
    r[I][I] = cb * cc;
    r[I][J] = -(cb * sc);
    r[I][K] = sb;
    r[J][I] = ca * sc + sa_sb * cc;
    r[J][J] = ca * cc - sa_sb * sc;
    r[J][K] = -(sa * cb);
    r[K][I] = sa * sc - ca_sb * cc;
    r[K][J] = sa * cc + ca_sb * sc;
    r[K][K] = ca * cb;
    r
}

/// Intrinsic `R_I(a)·R_J(b)·R_I(c)`, K the remaining axis, in closed form.
#[inline(always)]
fn proper_euler_matrix<const I: usize, const J: usize, const K: usize>(
    a: f64,
    b: f64,
    c: f64,
) -> Matrix {
    let [(sa, ca), (sb, cb), (sc, cc)] = parity_sin_cos::<I, J>([a, b, c]);
    let (sa_cb, ca_cb) = (sa * cb, ca * cb);
    let mut r = [[0.0; 3]; 3];
    r[I][I] = cb;
    r[I][J] = sb * sc;
    r[I][K] = sb * cc;
    r[J][I] = sa * sb;
    r[J][J] = ca * cc - sa_cb * sc;
    r[J][K] = -(ca * sc + sa_cb * cc);
    r[K][I] = -(ca * sb);
    r[K][J] = sa * cc + ca_cb * sc;
    r[K][K] = ca_cb * cc - sa * sc;
    r
}

/// [`matrix_from_angles`] for any code, skipped slots included: the rotations applied one
/// after the other.
fn matrix_from_slots(kind: Kind, code: AxisCode, angles_deg: [f64; 3]) -> Matrix {
    let mut r = IDENTITY;
    for (axis, angle) in code.axes().into_iter().zip(angles_deg) {
        if let Some(axis) = axis {
            let (s, c) = sin_cos_deg(angle);
            match kind {
                Kind::Intrinsic => turn_columns(&mut r, axis, s, c),
                Kind::Extrinsic => turn_rows(&mut r, axis, s, c),
            }
        }
    }
    r
}

/// The two axes turned by a rotation about `axis`, in right-handed order.
#[inline(always)]
fn plane(axis: Axis) -> (usize, usize) {
    match axis {
        Axis::X => (1, 2),
        Axis::Y => (2, 0),
        Axis::Z => (0, 1),
    }
}

/// `r ← r·R_axis`: only the columns of the turned plane change (12 flops, not a 3x3
/// product).
#[inline(always)]
fn turn_columns(r: &mut Matrix, axis: Axis, s: f64, c: f64) {
    let (u, v) = plane(axis);
    for row in r.iter_mut() {
        let (a, b) = (row[u], row[v]);
        row[u] = a * c + b * s + 0.0;
        row[v] = b * c - a * s + 0.0;
    }
}

/// `r ← R_axis·r`: only the rows of the turned plane change.
#[inline(always)]
fn turn_rows(r: &mut Matrix, axis: Axis, s: f64, c: f64) {
    let (u, v) = plane(axis);
    let (ru, rv) = (r[u], r[v]);
    r[u] = core::array::from_fn(|k| c * ru[k] - s * rv[k] + 0.0);
    r[v] = core::array::from_fn(|k| s * ru[k] + c * rv[k] + 0.0);
}

/// Checks that `m` is a rotation: finite, `max |MᵀM − I| ≤ ROTATION_TOLERANCE`, `det > 0`.
///
/// Every comparison is written as "accept only if", so that NaN refuses: a non-finite
/// element, or huge ones whose products overflow (`∞ − ∞ = NaN`, or `∞`), make some element
/// of `MᵀM − I` NaN or infinite, and the matrix is refused. Any element beyond
/// [`ELEMENT_MAX`] puts a diagonal element of `MᵀM` above 4, so it is refused too. Only a
/// refused matrix is looked at again, for the reason ([`Error::NotFinite`] or
/// [`Error::NotARotation`]).
///
/// ```
/// use cncrot::{check_rotation, Error, IDENTITY};
/// assert_eq!(check_rotation(&IDENTITY), Ok(()));
/// let mirror = [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(check_rotation(&mirror), Err(Error::NotARotation));
/// // Orthogonal, but scaled by 1.4e155: MᵀM overflows; still refused.
/// let huge = [[1e155, -1e155, 0.0], [1e155, 1e155, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(check_rotation(&huge), Err(Error::NotARotation));
/// ```
#[inline]
pub fn check_rotation(m: &Matrix) -> Result<(), Error> {
    // MᵀM − I and the determinant in the lanes of vector registers, from the rows as they
    // lie in memory: row r, the same row rotated (y, z, x) and (z, x, y). The same
    // products, summed in the same order, as `orthonormality_error` and `determinant`,
    // hence the same decision; a third of the instructions.
    let row = |r: usize| F4::new([m[r][0], m[r][1], m[r][2], 0.0]);
    let yzx = |r: usize| F4::new([m[r][1], m[r][2], m[r][0], 0.0]);
    let zxy = |r: usize| F4::new([m[r][2], m[r][0], m[r][1], 0.0]);
    let (r0, r1, r2) = (row(0), row(1), row(2));
    let (s0, s1, s2) = (yzx(0), yzx(1), yzx(2));
    // (g00, g11, g22, 0) and (g01, g12, g20, 0).
    let diagonal = r0.mul(r0).add(r1.mul(r1)).add(r2.mul(r2));
    let off = r0.mul(s0).add(r1.mul(s1)).add(r2.mul(s2));
    let tolerance = F4::splat(ROTATION_TOLERANCE);
    let orthonormal = diagonal
        .sub(F4::new([1.0, 1.0, 1.0, 0.0]))
        .abs()
        .le(tolerance)
        .and(off.abs().le(tolerance))
        .all();
    // Row 1 × row 2, then its dot product with row 0: the determinant.
    let cross = s1.mul(zxy(2)).sub(zxy(1).mul(s2)).to_array();
    let det = m[0][0] * cross[0] + m[0][1] * cross[1] + m[0][2] * cross[2];
    if orthonormal & (det > 0.0) {
        Ok(())
    } else if m.iter().flatten().all(|x| x.is_finite()) {
        Err(Error::NotARotation)
    } else {
        Err(Error::NotFinite)
    }
}

/// A bound on the elements of every matrix [`check_rotation`] accepts: within the tolerance
/// every element is below `sqrt(1 + ROTATION_TOLERANCE)` ≈ 1.0005, so 2 leaves room.
pub const ELEMENT_MAX: f64 = 2.0;

/// `max |MᵀM − I|` over all elements; NaN when any element product is NaN (huge elements
/// whose products overflow with opposite signs), so that callers comparing it with `<=`
/// refuse such a matrix.
pub fn orthonormality_error(m: &Matrix) -> f64 {
    let mut worst: f64 = 0.0;
    // MᵀM is symmetric, and its (i, j) and (j, i) elements are computed from the same
    // products in the same order, so they are equal bit for bit: the upper triangle decides.
    for i in 0..3 {
        for j in i..3 {
            let dot = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
            let target = if i == j { 1.0 } else { 0.0 };
            let e = math::abs(dot - target);
            // A NaN must not be lost in the maximum (`max` would drop it).
            if e.is_nan() {
                return f64::NAN;
            }
            worst = worst.max(e);
        }
    }
    worst
}

/// Brings a matrix that is already close to a rotation (as [`check_rotation`] accepts)
/// back to orthonormal, so that chains of products (additive rotations, composed frames)
/// do not drift: each product adds a few ulp to `|MᵀM − I|`, which a million-step chain
/// turns into 1e-12.
///
/// One Newton–Schulz step `X ← X + X·(I − XᵀX)/2` converges quadratically to the nearest
/// rotation (the orthogonal polar factor): from a deviation `δ` it leaves about `1.5·δ²`. A
/// matrix within 2 ulp of orthonormal is returned unchanged (so exact matrices, and the
/// products of exact rotations, stay bit for bit what they were); otherwise steps are taken
/// until it is, at most four, which is enough from anything `check_rotation` accepts (and
/// from the product of two such matrices: 3e-3 → 1e-5 → 3e-10 → rounding).
pub(crate) fn reorthonormalize(m: &Matrix) -> Matrix {
    let mut x = *m;
    for _ in 0..4 {
        let mut residual = [[0.0; 3]; 3];
        let mut worst: f64 = 0.0;
        let mut finite = true;
        for (i, row) in residual.iter_mut().enumerate() {
            for (j, r) in row.iter_mut().enumerate() {
                let dot = x[0][i] * x[0][j] + x[1][i] * x[1][j] + x[2][i] * x[2][j];
                let target = if i == j { 1.0 } else { 0.0 };
                *r = target - dot;
                worst = worst.max(math::abs(*r));
                finite &= r.is_finite();
            }
        }
        // The callers have refused non-finite input, so `finite` holds; were it not to, the
        // matrix is returned as it is rather than made worse.
        if worst <= 2.0 * f64::EPSILON || !finite {
            break;
        }
        let correction = mul(&x, &residual);
        for (xr, cr) in x.iter_mut().zip(&correction) {
            for (v, c) in xr.iter_mut().zip(cr) {
                *v += 0.5 * c;
            }
        }
    }
    x.map(|row| row.map(|v| v + 0.0))
}

/// How far from orthonormal (`max |MᵀM − I|`) a rotation is taken as it is; beyond (and
/// within [`ROTATION_TOLERANCE`]), it is one rounded where it was written (a matrix printed
/// to 4 or 6 decimals, a float one), which the solvers and writers take for its nearest
/// rotation. Far below their verifications (1e-9, 1e-12 on the read-back of words), far
/// above the rounding of the library's own rotations (a few 1e-16).
const ROUNDED: f64 = 1e-12;

/// Whether `max |MᵀM − I| ≤ 1e-12` (NaN: no): a rotation the library takes bit for bit.
pub(crate) fn is_exact(m: &Matrix) -> bool {
    orthonormality_error(m) <= ROUNDED
}

/// `m` itself when [`is_exact`], else its nearest rotation ([`reorthonormalize`]): what a
/// writer writes for a rotation the caller rounded.
pub(crate) fn exact_or_nearest(m: &Matrix) -> Matrix {
    if is_exact(m) {
        *m
    } else {
        reorthonormalize(m)
    }
}

/// The determinant.
pub fn determinant(m: &Matrix) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// The nearest rotation (in the Frobenius norm) to a nearly orthonormal matrix, such as one
/// built from probe measurements: the orthogonal polar factor, by Newton's iteration
/// `X ← (γX + X⁻ᵀ/γ)/2`, which converges quadratically. The scaling γ (Higham's Frobenius
/// scaling, dropped once the iterate is close) bounds the number of steps for badly
/// conditioned input too: a real-time caller gets the same time for every input class.
///
/// Refuses ([`Error::Degenerate`]) a matrix that is singular or has a negative determinant
/// (its nearest orthogonal matrix is a reflection), and non-finite input
/// ([`Error::NotFinite`]).
///
/// ```
/// use cncrot::{nearest_rotation, orthonormality_error};
/// let measured = [[1.0, 0.001, 0.0], [-0.001, 1.0, 0.0], [0.0, 0.0, 1.0002]];
/// let r = nearest_rotation(&measured).unwrap();
/// assert!(orthonormality_error(&r) < 1e-15);
/// ```
pub fn nearest_rotation(m: &Matrix) -> Result<Matrix, Error> {
    if !m.iter().flatten().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    // Scale to unit determinant first: Newton's iteration then starts close to its fixed
    // point whatever the input's scale, and a huge or tiny matrix cannot overflow.
    let scale = m.iter().flatten().fold(0.0f64, |a, &x| a.max(math::abs(x)));
    if scale == 0.0 {
        return Err(Error::Degenerate);
    }
    let mut x = m.map(|row| row.map(|v| v / scale));
    let frobenius = |a: &Matrix| math::sqrt(a.iter().flatten().map(|v| v * v).sum());
    for _ in 0..32 {
        let det = determinant(&x);
        if det.is_nan() || det <= 1e-12 {
            return Err(Error::Degenerate);
        }
        let inv_t = cofactor(&x).map(|row| row.map(|v| v / det));
        // Unscaled Newton needs about log2(condition) steps before it converges
        // quadratically (25 for a condition of 1e6). Far from orthogonal (the determinant of
        // a near-rotation is near 1), the scaling brings that down to a few; near it, plain
        // Newton is already quadratic and exact, and the scaling would only cost.
        let gamma = if (0.5..=2.0).contains(&det) {
            1.0
        } else {
            math::sqrt(frobenius(&inv_t) / frobenius(&x))
        };
        let mut change: f64 = 0.0;
        let mut next = x;
        for i in 0..3 {
            for j in 0..3 {
                next[i][j] = 0.5 * (gamma * x[i][j] + inv_t[i][j] / gamma);
                change = change.max(math::abs(next[i][j] - x[i][j]));
            }
        }
        x = next;
        if change <= 4.0 * f64::EPSILON {
            return Ok(x.map(|row| row.map(|v| v + 0.0)));
        }
    }
    Err(Error::Degenerate)
}

/// The cofactor matrix: `det(M) · M⁻ᵀ`.
fn cofactor(m: &Matrix) -> Matrix {
    let c =
        |r0: usize, r1: usize, c0: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    [
        [c(1, 2, 1, 2), -c(1, 2, 0, 2), c(1, 2, 0, 1)],
        [-c(0, 2, 1, 2), c(0, 2, 0, 2), -c(0, 2, 0, 1)],
        [c(0, 1, 1, 2), -c(0, 1, 0, 2), c(0, 1, 0, 1)],
    ]
}

/// The angles of a rotation matrix in a convention, in the canonical ranges: θ1, θ3 in
/// (-180°, 180°], θ2 in [-90°, 90°] (Tait-Bryan) or [0°, 180°] (proper Euler).
///
/// The matrix is checked with [`check_rotation`] first. At the singular middle angle
/// θ3 = 0, θ1 carries the whole free rotation and [`Decomposition::singular`] is set; the
/// result is still an exact decomposition.
///
/// ```
/// use cncrot::{angles_from_matrix, matrix_from_angles, Convention, Kind, Sequence};
/// // Paper, Example 2: extrinsic XYZ (30, 45, 60) as intrinsic Z, X', Y''.
/// let m = matrix_from_angles(Kind::Extrinsic, Sequence::XYZ.into(), [30.0, 45.0, 60.0]);
/// let d = angles_from_matrix(Convention::new(Kind::Intrinsic, Sequence::ZXY), &m).unwrap();
/// assert!((d.angles[0] - 37.7923).abs() < 1e-4);
/// assert!((d.angles[1] - 20.7048).abs() < 1e-4);
/// assert!((d.angles[2] - 49.1066).abs() < 1e-4);
/// ```
pub fn angles_from_matrix(conv: Convention, m: &Matrix) -> Result<Decomposition, Error> {
    check_rotation(m)?;
    Ok(decompose(conv, m))
}

/// [`angles_from_matrix`] without the rotation check, for callers that built `m`
/// themselves. Never panics; a matrix that is not a rotation gives meaningless angles.
#[inline]
pub fn decompose(conv: Convention, m: &Matrix) -> Decomposition {
    decompose_inline(conv, m)
}

/// [`decompose`], inlined into the C boundary's row function: returned from a call, its
/// angles came back through memory stored in pieces and were read whole, which the
/// processor cannot forward from store to load (a stall on every call).
#[inline(always)]
pub(crate) fn decompose_inline(conv: Convention, m: &Matrix) -> Decomposition {
    // An extrinsic sequence is the intrinsic reversed sequence with the angles reversed, so
    // one algorithm serves all 24 conventions. The singular rule zeroes the convention's own
    // third angle, which is the reversed sequence's first.
    let (seq, zero_first) = match conv.kind {
        Kind::Intrinsic => (conv.sequence, false),
        Kind::Extrinsic => (conv.sequence.reversed(), true),
    };
    let prep = match seq {
        Sequence::XYZ => tait_bryan::<0, 1, 2>(m, zero_first),
        Sequence::XZY => tait_bryan::<0, 2, 1>(m, zero_first),
        Sequence::YXZ => tait_bryan::<1, 0, 2>(m, zero_first),
        Sequence::YZX => tait_bryan::<1, 2, 0>(m, zero_first),
        Sequence::ZXY => tait_bryan::<2, 0, 1>(m, zero_first),
        Sequence::ZYX => tait_bryan::<2, 1, 0>(m, zero_first),
        Sequence::XYX => proper_euler::<0, 1, 2>(m, zero_first),
        Sequence::XZX => proper_euler::<0, 2, 1>(m, zero_first),
        Sequence::YXY => proper_euler::<1, 0, 2>(m, zero_first),
        Sequence::YZY => proper_euler::<1, 2, 0>(m, zero_first),
        Sequence::ZXZ => proper_euler::<2, 0, 1>(m, zero_first),
        Sequence::ZYZ => proper_euler::<2, 1, 0>(m, zero_first),
    };
    // One `atan2` of four lanes after the match, not three in each of its 12 arms: the
    // compact code runs at one speed wherever it lands (two identical copies of the
    // inlined version differed by a quarter).
    let r = math::atan2_deg4(prep.y, prep.x);
    let (mut a, singular) = match prep.singular_middle {
        None => ([r[0], r[1], r[2]], false),
        Some(b) if zero_first => ([0.0, b, r[0]], true),
        Some(b) => ([r[0], b, 0.0], true),
    };
    if conv.kind == Kind::Extrinsic {
        a.swap(0, 2);
    }
    Decomposition {
        angles: a,
        singular,
    }
}

/// Intrinsic `R = R_I(a)·R_J(b)·R_K(c)`, `I, J, K` all different.
///
/// With `e` the parity of (I, J, K): `R_IK = e·sin b`, `(R_II, R_IJ) = cos b·(cos c, -e sin c)`,
/// `(R_JK, R_KK) = cos b·(-e sin a, cos a)`. The middle angle comes from `atan2` against the
/// norm of its row (never `asin`), the first from column K, and the third from the matrix
/// de-rotated by the first, `R_I(a)ᵀ·R = R_J(b)·R_K(c)`, whose row J is `(e sin c, cos c)`:
/// the third angle then absorbs any error of the first, so the reconstruction stays exact
/// near the singularity where the first angle is ill-conditioned.
#[inline(always)]
fn tait_bryan<const I: usize, const J: usize, const K: usize>(
    m: &Matrix,
    zero_first: bool,
) -> Prepared {
    let e = if (I + 1) % 3 == J { 1.0 } else { -1.0 };
    let sa = -e * m[J][K];
    let ca = m[K][K];
    if sa * sa + ca * ca > SINGULAR_NORM * SINGULAR_NORM {
        let cb = sqrt(m[I][I] * m[I][I] + m[I][J] * m[I][J]);
        // (sa, ca) are cos b times the sine and cosine of a; atan2 needs no normalisation.
        let sc = e * ca * m[J][I] + sa * m[K][I];
        let cc = ca * m[J][J] + e * sa * m[K][J];
        Prepared::regular([sa, e * m[I][K], sc], [ca, cb, cc])
    } else {
        let b = if e * m[I][K] >= 0.0 { 90.0 } else { -90.0 };
        if zero_first {
            // R = R_J(b)·R_K(c): row J is (e sin c, cos c) at (I, J).
            Prepared::singular(e * m[J][I], m[J][J], b)
        } else {
            // R = R_I(a)·R_J(b): column J is (cos a, e sin a) at (J, K).
            Prepared::singular(e * m[K][J], m[J][J], b)
        }
    }
}

/// What a decomposition hands to `atan2`: the (y, x) of its three angles (lane 3 unused),
/// or at a singular middle angle the one free angle's (y, x) in lane 0 and the middle
/// angle itself.
struct Prepared {
    y: [f64; 4],
    x: [f64; 4],
    singular_middle: Option<f64>,
}

impl Prepared {
    #[inline(always)]
    fn regular(y: [f64; 3], x: [f64; 3]) -> Prepared {
        Prepared {
            y: [y[0], y[1], y[2], 0.0],
            x: [x[0], x[1], x[2], 1.0],
            singular_middle: None,
        }
    }

    #[inline(always)]
    fn singular(y: f64, x: f64, middle: f64) -> Prepared {
        Prepared {
            y: [y, 0.0, 0.0, 0.0],
            x: [x, 1.0, 1.0, 1.0],
            singular_middle: Some(middle),
        }
    }
}

/// Intrinsic `R = R_I(a)·R_J(b)·R_I(c)`, K the remaining axis, `e` the parity of (I, J, K).
///
/// `R_II = cos b`, `(R_IJ, R_IK) = sin b·(sin c, e cos c)`, `(R_JI, R_KI) = sin b·(sin a,
/// -e cos a)`; de-rotated, `R_I(a)ᵀ·R = R_J(b)·R_I(c)` has row J `(cos c, -e sin c)` at (J, K).
#[inline(always)]
fn proper_euler<const I: usize, const J: usize, const K: usize>(
    m: &Matrix,
    zero_first: bool,
) -> Prepared {
    let e = if (I + 1) % 3 == J { 1.0 } else { -1.0 };
    let sa = m[J][I];
    let ca = -e * m[K][I];
    if sa * sa + ca * ca > SINGULAR_NORM * SINGULAR_NORM {
        let sb = sqrt(m[I][J] * m[I][J] + m[I][K] * m[I][K]);
        let cc = ca * m[J][J] + e * sa * m[K][J];
        let sc = -e * ca * m[J][K] - sa * m[K][K];
        Prepared::regular([sa, sb, sc], [ca, m[I][I], cc])
    } else {
        let b = if m[I][I] >= 0.0 { 0.0 } else { 180.0 };
        if zero_first {
            // R = R_J(b)·R_I(c): row J is (cos c, -e sin c) at (J, K).
            Prepared::singular(-e * m[J][K], m[J][J], b)
        } else {
            // R = R_I(a)·R_J(b): column J is (cos a, e sin a) at (J, K).
            Prepared::singular(e * m[K][J], m[J][J], b)
        }
    }
}

/// The other decomposition of the same rotation: `(θ1+180°, 180°−θ2, θ3+180°)` for
/// Tait-Bryan, `(θ1+180°, −θ2, θ3+180°)` for proper Euler, all three wrapped into
/// (-180°, 180°]. Its middle angle lies outside the canonical range (|θ2| ≥ 90° resp.
/// θ2 ≤ 0°, where θ2 = 180° gives 180°, not -180°). At a singular decomposition it is
/// another member of the same family. Angles of any size are accepted: each is reduced
/// exactly into (-180°, 180°] first, as [`matrix_from_angles`] reduces it.
///
/// ```
/// use cncrot::{second_solution, Decomposition, Sequence};
/// let d = Decomposition { angles: [10.0, 20.0, 30.0], singular: false };
/// assert_eq!(second_solution(Sequence::XYZ, d).angles, [-170.0, 160.0, -150.0]);
/// assert_eq!(second_solution(Sequence::ZXZ, d).angles, [-170.0, -20.0, -150.0]);
/// ```
pub fn second_solution(sequence: Sequence, d: Decomposition) -> Decomposition {
    // Reduced first: `θ + 180` of a huge θ (from 2^55° on) would round to another rotation.
    let [a, b, c] = d.angles.map(wrap_deg);
    let b2 = if sequence.is_proper_euler() {
        wrap_deg(-b)
    } else {
        wrap_deg(180.0 - b)
    };
    Decomposition {
        angles: [wrap_deg(a + 180.0), b2, wrap_deg(c + 180.0)],
        singular: d.singular,
    }
}

/// Of the two decompositions of `m`, each angle shifted by whole turns, the one nearest to
/// `reference` (least sum of squared differences; on a tie the canonical one). Use it to
/// avoid needless swivel motion: the reference is the current position.
///
/// A result angle of magnitude [`CLOSEST_MAX`] or more is refused with
/// [`Error::OutOfRange`]: there doubles are spaced 1.5e-11° or more apart, so the angle
/// could no longer denote the rotation to the library's accuracy (a reference of 1e15°
/// would be off by 0.06°).
///
/// ```
/// use cncrot::{closest_angles, matrix_from_angles, Convention, Error, Kind, Sequence};
/// let conv = Convention::new(Kind::Intrinsic, Sequence::ZXZ);
/// let m = matrix_from_angles(Kind::Intrinsic, Sequence::ZXZ.into(), [10.0, 20.0, 30.0]);
/// // Near the second solution (-170, -20, -150), and 360° further on θ3.
/// let d = closest_angles(conv, &m, [-165.0, -15.0, 200.0]).unwrap();
/// let expect = [-170.0, -20.0, 210.0];
/// assert!(d.angles.iter().zip(expect).all(|(a, b)| (a - b).abs() < 1e-9), "{:?}", d.angles);
/// assert_eq!(closest_angles(conv, &m, [1e15, 0.0, 0.0]), Err(Error::OutOfRange));
/// ```
pub fn closest_angles(
    conv: Convention,
    m: &Matrix,
    reference: [f64; 3],
) -> Result<Decomposition, Error> {
    let first = angles_from_matrix(conv, m)?;
    closest_of(conv.sequence, first, reference)
}

/// The magnitude from which [`closest_angles`] refuses a result: 2^16 = 65 536° (182
/// turns). Below it doubles are spaced at most 7.3e-12° apart, so the returned angle is
/// the exact `θ + k·360°` to within 3.7e-12° (6.4e-14 rad).
pub const CLOSEST_MAX: f64 = 65_536.0;

/// [`closest_angles`] for a decomposition already at hand (its angles may be of any size;
/// they are reduced exactly first).
pub fn closest_of(
    sequence: Sequence,
    first: Decomposition,
    reference: [f64; 3],
) -> Result<Decomposition, Error> {
    let first = Decomposition {
        angles: first.angles.map(wrap_deg),
        ..first
    };
    let unwind = |d: Decomposition| {
        let mut out = d;
        let mut dist = 0.0;
        let mut fits = true;
        for ((o, &a), &r) in out.angles.iter_mut().zip(&d.angles).zip(&reference) {
            *o = a + math::turns_toward(a, r) + 0.0;
            dist += (*o - r) * (*o - r);
            // Written so that NaN or ∞ (a reference near f64::MAX) refuses.
            fits &= math::abs(*o) < CLOSEST_MAX;
        }
        (out, dist, fits)
    };
    let (a, da, a_fits) = unwind(first);
    let (b, db, b_fits) = unwind(second_solution(sequence, first));
    let (best, fits) = if db < da { (b, b_fits) } else { (a, a_fits) };
    if fits {
        Ok(best)
    } else {
        Err(Error::OutOfRange)
    }
}

/// Converts angles from one convention to another (`from_code` may have `00` pairs).
///
/// ```
/// use cncrot::{convert, AxisCode, Convention, Kind, Sequence};
/// // Paper, Example 3: extrinsic X, Y, Z (30, 45, 60) as extrinsic Z, X, Y.
/// let d = convert(Kind::Extrinsic, AxisCode::new(57).unwrap(), [30.0, 45.0, 60.0],
///                 Convention::new(Kind::Extrinsic, Sequence::ZXY));
/// assert!((d.angles[0] - 39.6392).abs() < 1e-4 && (d.angles[1] + 16.2799).abs() < 1e-4);
/// ```
pub fn convert(
    from_kind: Kind,
    from_code: AxisCode,
    angles_deg: [f64; 3],
    to: Convention,
) -> Decomposition {
    convert_inline(from_kind, from_code, angles_deg, to)
}

/// [`convert`], inlined into the C boundary's row functions.
#[inline(always)]
pub(crate) fn convert_inline(
    from_kind: Kind,
    from_code: AxisCode,
    angles_deg: [f64; 3],
    to: Convention,
) -> Decomposition {
    decompose_inline(
        to,
        &matrix_from_angles_inline(from_kind, from_code, angles_deg),
    )
}

/// An additional rotation applied to an existing one: extrinsic (about the machine axes)
/// multiplies from the left, `R_add·R_old`; intrinsic (about the rotated axes) from the
/// right, `R_old·R_add`. The product is brought back to orthonormal (to 2 ulp), so a chain
/// of any length does not drift away from a rotation.
///
/// ```
/// use cncrot::{add_rotation, elementary, Axis, Kind};
/// let r = add_rotation(Kind::Intrinsic, &elementary(Axis::Z, 30.0), &elementary(Axis::Z, 15.0));
/// let expect = elementary(Axis::Z, 45.0);
/// assert!(r.iter().flatten().zip(expect.iter().flatten()).all(|(a, b)| (a - b).abs() < 1e-15));
/// ```
pub fn add_rotation(kind: Kind, old: &Matrix, add: &Matrix) -> Matrix {
    let product = match kind {
        Kind::Extrinsic => mul(add, old),
        Kind::Intrinsic => mul(old, add),
    };
    reorthonormalize(&product)
}

/// `R·v`: a vector given in the rotated system, in the original one (TwinCAT `CalcRot`).
///
/// ```
/// use cncrot::{elementary, rotate, Axis};
/// assert_eq!(rotate(&elementary(Axis::Z, 90.0), [1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]);
/// ```
pub fn rotate(m: &Matrix, v: Vector) -> Vector {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2] + 0.0)
}

/// `Rᵀ·v`, the inverse rotation (TwinCAT `CalcInvRot`).
///
/// ```
/// use cncrot::{elementary, rotate_inverse, Axis};
/// // TwinCAT: after ROT Z45, CalcInvRot of (40, 10, 0) is (35.36, -21.21, 0).
/// let v = rotate_inverse(&elementary(Axis::Z, 45.0), [40.0, 10.0, 0.0]);
/// assert!((v[0] - 35.3553).abs() < 1e-4 && (v[1] + 21.2132).abs() < 1e-4);
/// ```
pub fn rotate_inverse(m: &Matrix, v: Vector) -> Vector {
    rotate(&transpose(m), v)
}

/// The matrix as an `nalgebra` matrix, for Rust callers that work in nalgebra (feature
/// `nalgebra`).
///
/// ```
/// let m = cncrot::to_nalgebra(&cncrot::IDENTITY);
/// assert_eq!(m, nalgebra::Matrix3::identity());
/// ```
#[cfg(feature = "nalgebra")]
pub fn to_nalgebra(m: &Matrix) -> nalgebra::Matrix3<f64> {
    nalgebra::Matrix3::from_fn(|i, j| m[i][j])
}

/// An `nalgebra` matrix as a row-major matrix (feature `nalgebra`).
///
/// ```
/// let m = nalgebra::Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
/// assert_eq!(cncrot::from_nalgebra(&m), cncrot::elementary(cncrot::Axis::Z, 90.0));
/// ```
#[cfg(feature = "nalgebra")]
pub fn from_nalgebra(m: &nalgebra::Matrix3<f64>) -> Matrix {
    core::array::from_fn(|i| core::array::from_fn(|j| m[(i, j)]))
}

/// The rotation by `deg` about the unit vector `u` (Rodrigues): exact for multiples of 90°
/// about the coordinate axes.
pub(crate) fn about_axis(u: Vector, deg: f64) -> Matrix {
    let (s, c) = sin_cos_deg(deg);
    about_axis_sc(u, s, c)
}

/// [`about_axis`] for an angle given by its sine `s` and cosine `c`.
#[inline(always)]
pub(crate) fn about_axis_sc(u: Vector, s: f64, c: f64) -> Matrix {
    let t = 1.0 - c;
    let [x, y, z] = u;
    [
        [
            c + t * x * x + 0.0,
            t * x * y - s * z + 0.0,
            t * x * z + s * y + 0.0,
        ],
        [
            t * x * y + s * z + 0.0,
            c + t * y * y + 0.0,
            t * y * z - s * x + 0.0,
        ],
        [
            t * x * z - s * y + 0.0,
            t * y * z + s * x + 0.0,
            c + t * z * z + 0.0,
        ],
    ]
}

/// `Rot(u, φ)·v` for the unit vector `u` from `s = sin φ` and `c = cos φ` (Rodrigues'
/// formula on the vector: a third of the work of [`about_axis_sc`] and a product).
#[inline(always)]
pub(crate) fn turn_vector(u: Vector, s: f64, c: f64, v: Vector) -> Vector {
    let uv = crate::vector::dot(u, v);
    let w = crate::vector::cross(u, v);
    core::array::from_fn(|i| v[i] * c + w[i] * s + u[i] * (uv * (1.0 - c)) + 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Xorshift;

    /// The product of the elementary rotations, the definition the closed forms replace.
    fn by_definition(conv: Convention, a: [f64; 3]) -> Matrix {
        let [x, y, z] = conv.sequence.axes();
        let [r1, r2, r3] = [
            elementary(x, a[0]),
            elementary(y, a[1]),
            elementary(z, a[2]),
        ];
        match conv.kind {
            Kind::Intrinsic => mul(&mul(&r1, &r2), &r3),
            Kind::Extrinsic => mul(&mul(&r3, &r2), &r1),
        }
    }

    #[test]
    fn closed_forms_are_the_products_of_their_rotations() {
        let mut rng = Xorshift(0x1234_5678_9ABC_DEF1);
        let mut angle = || rng.unit() * 720.0 - 360.0;
        for conv in Convention::all() {
            let code = AxisCode::from(conv.sequence);
            for _ in 0..2000 {
                let a = [angle(), angle(), angle()];
                let m = matrix_from_angles(conv.kind, code, a);
                let d = by_definition(conv, a);
                let s = matrix_from_slots(conv.kind, code, a);
                for ((x, y), z) in m
                    .iter()
                    .flatten()
                    .zip(d.iter().flatten())
                    .zip(s.iter().flatten())
                {
                    assert!(
                        (x - y).abs() <= 6e-16 && (x - z).abs() <= 6e-16,
                        "{conv:?} {a:?}"
                    );
                }
            }
            // A non-finite angle in any slot shows in the matrix (the C boundary refuses
            // such angles; the Rust API must not turn them into a rotation).
            for slot in 0..3 {
                for bad in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
                    let mut a = [10.0, 20.0, 30.0];
                    a[slot] = bad;
                    let m = matrix_from_angles(conv.kind, code, a);
                    assert!(m.iter().flatten().any(|x| !x.is_finite()), "{conv:?} {a:?}");
                }
            }
            // Right angles: exact, and never -0.
            for i in 0..125 {
                let a = [i % 5, i / 5 % 5, i / 25].map(|k| 90.0 * k as f64 - 180.0);
                let m = matrix_from_angles(conv.kind, code, a);
                let d = by_definition(conv, a);
                for (x, y) in m.iter().flatten().zip(d.iter().flatten()) {
                    // Equal to the product of the rotations, and a zero is +0.
                    assert!(*x == *y, "{conv:?} {a:?}");
                    assert!(*x != 0.0 || x.is_sign_positive(), "{conv:?} {a:?}");
                    assert!(*x == 0.0 || x.abs() == 1.0);
                }
            }
        }
    }

    #[test]
    fn check_decides_as_its_definition() {
        // The vector check against the definition written plainly: max |MᵀM − I| within
        // the tolerance and det > 0, on rotations disturbed around the tolerance's edge,
        // reflections, huge and non-finite elements.
        let mut rng = Xorshift(0x0DDB_1A5E_5BAD_5EED);
        let mut unit = || rng.unit();
        let specials = [
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
            1e155,
            -1e200,
            2.5,
            1e-300,
        ];
        let (mut accepted, mut refused) = (0, 0);
        for n in 0..200_000 {
            let a = [unit() * 360.0, unit() * 360.0, unit() * 360.0];
            let mut m = matrix_from_angles(Kind::Intrinsic, Sequence::ZYX.into(), a);
            // Disturbances of 0 .. 1.2e-3 / 3, one element or all.
            let size = unit() * 1.2e-3;
            if n % 2 == 0 {
                m[n % 3][(n / 3) % 3] += size;
            } else {
                for v in m.iter_mut().flatten() {
                    *v += (unit() - 0.5) * size;
                }
            }
            if n % 7 == 0 {
                m[1] = m[1].map(|v| -v);
            }
            if n % 11 == 0 {
                m[(n / 11) % 3][(n / 33) % 3] = specials[(n / 99) % specials.len()];
            }
            let definition =
                orthonormality_error(&m) <= ROTATION_TOLERANCE && determinant(&m) > 0.0;
            let got = check_rotation(&m);
            assert_eq!(got.is_ok(), definition, "{m:?}");
            if got.is_ok() {
                accepted += 1;
            } else {
                refused += 1;
                let finite = m.iter().flatten().all(|x| x.is_finite());
                let reason = if finite {
                    Error::NotARotation
                } else {
                    Error::NotFinite
                };
                assert_eq!(got, Err(reason));
            }
        }
        // Both sides of the edge were exercised.
        assert!(
            accepted > 20_000 && refused > 20_000,
            "{accepted} {refused}"
        );
    }
    /// The bound of [`closest_of`] right at 65 536°, on both sides of it and for both
    /// signs: 16° + 182 turns is 65 536° exactly (refused), 16° − 2⁻³⁷ + 182 turns is the
    /// largest double below it (returned as it is).
    #[test]
    fn closest_refuses_from_65536_degrees_on() {
        const ULP: f64 = 1.0 / 137_438_953_472.0; // 2⁻³⁷, the spacing just below 2¹⁶
        let d = |a: f64| Decomposition {
            angles: [20.0, 30.0, a],
            singular: false,
        };
        for sign in [1.0, -1.0] {
            let reference = [20.0, 30.0, sign * CLOSEST_MAX];
            assert_eq!(
                closest_of(Sequence::ZXZ, d(sign * 16.0), reference),
                Err(Error::OutOfRange)
            );
            let below = closest_of(Sequence::ZXZ, d(sign * (16.0 - ULP)), reference).unwrap();
            assert_eq!(below.angles, [20.0, 30.0, sign * (CLOSEST_MAX - ULP)]);
        }
    }
}
