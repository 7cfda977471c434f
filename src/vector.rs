//! Directions and the rotations built from them: what the dialects' vector forms (`PLANE
//! VECTOR`, `PLANE POINTS`, `G68.3`, `G158` mode 3) and tool orientations need.

use crate::math::{abs, sqrt};
use crate::{Error, Matrix, Vector};

pub(crate) fn dot(a: Vector, b: Vector) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: Vector, b: Vector) -> Vector {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v / |v|`, never -0. Scaled by its largest component first, so no finite nonzero vector
/// overflows or underflows on the way. A zero or non-finite vector is refused
/// ([`Error::Degenerate`]).
///
/// ```
/// assert_eq!(cncrot::unit_vector([0.0, 3.0, 4.0]), Ok([0.0, 0.6, 0.8]));
/// assert_eq!(cncrot::unit_vector([1e300, 0.0, 1e300]).map(|v| v[1]), Ok(0.0));
/// assert!(cncrot::unit_vector([0.0; 3]).is_err());
/// ```
pub fn unit_vector(v: Vector) -> Result<Vector, Error> {
    // `max` would drop a NaN: finiteness is checked on its own.
    if !v.iter().all(|x| x.is_finite()) {
        return Err(Error::Degenerate);
    }
    let scale = v.iter().fold(0.0f64, |a, &x| a.max(abs(x)));
    if scale <= 0.0 {
        return Err(Error::Degenerate);
    }
    let w = v.map(|x| x / scale);
    let n = sqrt(dot(w, w));
    Ok(w.map(|x| x / n + 0.0))
}

/// Below this sine between a direction and the one that should be independent of it (a
/// hint parallel to the main axis, collinear points) the second axis is not determined:
/// what is left is rounding, not a direction \[choice\].
pub const MIN_SINE: f64 = 1e-12;

/// `hint` made perpendicular to the unit vector `main`, as a unit vector: Gram–Schmidt,
/// done twice so that the result is perpendicular to a few ulp even when `hint` is nearly
/// parallel to `main` (once leaves an error of eps/sine). [`Error::Degenerate`] when the
/// sine of the angle between them is [`MIN_SINE`] or less.
fn perpendicular(main: Vector, hint: Vector) -> Result<Vector, Error> {
    let h = unit_vector(hint)?;
    let p = dot(h, main);
    let x: Vector = core::array::from_fn(|k| h[k] - p * main[k]);
    let left = sqrt(dot(x, x));
    if left <= MIN_SINE || left.is_nan() {
        return Err(Error::Degenerate);
    }
    let x = x.map(|v| v / left);
    let q = dot(x, main);
    unit_vector(core::array::from_fn(|k| x[k] - q * main[k]))
}

fn columns(x: Vector, y: Vector, z: Vector) -> Matrix {
    core::array::from_fn(|i| [x[i] + 0.0, y[i] + 0.0, z[i] + 0.0])
}

/// The rotation whose Z axis is along `z` and whose X axis is `x_hint` made perpendicular
/// to it (`PLANE VECTOR`: N and B); Y = Z × X. Lengths are irrelevant. Refused
/// ([`Error::Degenerate`]): a zero or non-finite vector, or `x_hint` along `z`.
///
/// ```
/// let f = cncrot::rotation_from_z_x([0.0, 0.0, 2.0], [1.0, 1.0, 5.0]).unwrap();
/// let s = 0.5f64.sqrt();
/// assert!((f[0][0] - s).abs() < 1e-15 && (f[1][0] - s).abs() < 1e-15 && f[2][2] == 1.0);
/// ```
pub fn rotation_from_z_x(z: Vector, x_hint: Vector) -> Result<Matrix, Error> {
    let z = unit_vector(z)?;
    let x = perpendicular(z, x_hint)?;
    Ok(columns(x, cross(z, x), z))
}

/// The rotation whose X axis is along `x` and whose Y axis is `y_hint` made perpendicular
/// to it, on the side of `y_hint` (`PLANE POINTS`: P2 − P1 and P3 − P1); Z = X × Y.
/// Refused as [`rotation_from_z_x`].
///
/// ```
/// let f = cncrot::rotation_from_x_y([1.0, 0.0, 0.0], [5.0, -1.0, 0.0]).unwrap();
/// assert_eq!((f[1][1], f[2][2]), (-1.0, -1.0)); // Y' towards -Y, so Z' = X' × Y' is -Z
/// ```
pub fn rotation_from_x_y(x: Vector, y_hint: Vector) -> Result<Matrix, Error> {
    let x = unit_vector(x)?;
    let y = perpendicular(x, y_hint)?;
    Ok(columns(x, y, cross(x, y)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by fuzzing: axes built from nearly parallel directions were not orthogonal
    /// (one Gram–Schmidt step leaves eps/sine). Every sine above MIN_SINE gives a rotation.
    #[test]
    fn nearly_parallel_directions_still_give_a_rotation() {
        for sine in [1e-3, 1e-8, 1e-11, 2e-12] {
            let z = [0.3, -0.4, 0.866];
            let hint = [0.3 + sine, -0.4, 0.866 - sine];
            for f in [rotation_from_z_x(z, hint), rotation_from_x_y(z, hint)] {
                let f = f.unwrap();
                assert!(crate::orthonormality_error(&f) < 1e-15, "{sine}");
                assert!(crate::determinant(&f) > 0.0);
            }
        }
        assert_eq!(
            rotation_from_z_x([1.0, 1.0, 1.0], [2.0, 2.0, 2.0]),
            Err(Error::Degenerate)
        );
        assert_eq!(
            rotation_from_x_y([1.0, 0.0, 0.0], [-3.0, 0.0, 0.0]),
            Err(Error::Degenerate)
        );
    }
}
