//! Homogeneous frames: a rotation with translations before and after it.
//!
//! CYCLE600 (`_POS_*` before, `_POS_*_R` after), CYCLE800 (`X0..Z0`, `X1..Z1`) and G158
//! (`X Y Z`, `U V W`) all define `T = Trans(p_before)·Rot·Trans(p_after)`: a point `q` of the
//! new system lies at `p_before + R·(p_after + q)` in the old one.

use crate::rotation::{
    check_rotation, mul, reorthonormalize, rotate, transpose, Matrix, Vector, IDENTITY,
};
use crate::Error;

/// A rigid transformation `p ↦ R·p + t`, as the 4x4 matrix `[R t; 0 0 0 1]`.
///
/// ```
/// use cncrot::{elementary, Axis, Frame};
/// // TwinCAT: transRotZ(45) twice maps (30, 0, 0) to (0, 30, 0).
/// let r = Frame::from_rotation(elementary(Axis::Z, 45.0));
/// let p = r.compose(&r).transform_point([30.0, 0.0, 0.0]);
/// assert!(p[0].abs() < 1e-12 && (p[1] - 30.0).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The rotation `R`.
    pub rotation: Matrix,
    /// The translation `t` (the new origin in old coordinates).
    pub translation: Vector,
}

impl Default for Frame {
    fn default() -> Frame {
        Frame::IDENTITY
    }
}

impl Frame {
    /// No rotation, no translation.
    pub const IDENTITY: Frame = Frame {
        rotation: IDENTITY,
        translation: [0.0; 3],
    };

    /// A pure rotation.
    pub const fn from_rotation(rotation: Matrix) -> Frame {
        Frame {
            rotation,
            translation: [0.0; 3],
        }
    }

    /// `Trans(before)·Rot·Trans(after)`.
    ///
    /// ```
    /// use cncrot::{elementary, Axis, Frame};
    /// let f = Frame::with_translations([10.0, 0.0, 0.0], elementary(Axis::Z, 90.0), [5.0, 0.0, 0.0]);
    /// assert_eq!(f.translation, [10.0, 5.0, 0.0]); // 10 along X, then 5 along the new X = old Y
    /// ```
    pub fn with_translations(before: Vector, rotation: Matrix, after: Vector) -> Frame {
        let ra = rotate(&rotation, after);
        Frame {
            rotation,
            translation: core::array::from_fn(|k| before[k] + ra[k] + 0.0),
        }
    }

    /// Rotation about a point `a` (paper eq. 35): `Trans(a)·Rot·Trans(-a)`.
    ///
    /// ```
    /// use cncrot::{elementary, Axis, Frame};
    /// let f = Frame::about_point(elementary(Axis::Z, 90.0), [1.0, 0.0, 0.0]);
    /// assert_eq!(f.transform_point([1.0, 0.0, 0.0]), [1.0, 0.0, 0.0]); // the centre stays
    /// assert_eq!(f.transform_point([2.0, 0.0, 0.0]), [1.0, 1.0, 0.0]);
    /// ```
    pub fn about_point(rotation: Matrix, a: Vector) -> Frame {
        Frame::with_translations(a, rotation, a.map(|x| -x))
    }

    /// `self · other`: `other` expressed in the system of `self` (`R1·R2`, `t1 + R1·t2`).
    /// The rotation is brought back to orthonormal (to 2 ulp), so that chains of any
    /// length do not drift.
    ///
    /// ```
    /// use cncrot::{elementary, Axis, Frame};
    /// let a = Frame::with_translations([1.0, 0.0, 0.0], elementary(Axis::Z, 90.0), [0.0; 3]);
    /// let b = Frame::with_translations([1.0, 0.0, 0.0], elementary(Axis::Z, 90.0), [0.0; 3]);
    /// let ab = a.compose(&b);
    /// assert_eq!(ab.translation, [1.0, 1.0, 0.0]);
    /// assert_eq!(ab.transform_point([0.0; 3]), a.transform_point(b.transform_point([0.0; 3])));
    /// ```
    pub fn compose(&self, other: &Frame) -> Frame {
        let r1t2 = rotate(&self.rotation, other.translation);
        Frame {
            rotation: reorthonormalize(&mul(&self.rotation, &other.rotation)),
            translation: core::array::from_fn(|k| self.translation[k] + r1t2[k] + 0.0),
        }
    }

    /// The inverse frame: `[Rᵀ, −Rᵀ·t]`, with `R` first brought to orthonormal (to 2 ulp; a
    /// rotation accepted within the tolerance is otherwise not exactly inverted by its
    /// transpose). Never -0.
    ///
    /// ```
    /// use cncrot::{elementary, Axis, Frame};
    /// let f = Frame::with_translations([1.0, 2.0, 3.0], elementary(Axis::X, 90.0), [0.0; 3]);
    /// assert_eq!(f.compose(&f.inverse()).translation, [0.0; 3]);
    /// ```
    pub fn inverse(&self) -> Frame {
        let rt = transpose(&reorthonormalize(&self.rotation));
        let t = rotate(&rt, self.translation);
        Frame {
            rotation: rt,
            translation: t.map(|x| -x + 0.0),
        }
    }

    /// `R·p + t`: a point of the new system in the old one.
    pub fn transform_point(&self, p: Vector) -> Vector {
        let rp = rotate(&self.rotation, p);
        core::array::from_fn(|k| rp[k] + self.translation[k] + 0.0)
    }

    /// The 4x4 homogeneous matrix, row-major.
    pub fn to_homogeneous(&self) -> [[f64; 4]; 4] {
        let r = &self.rotation;
        let t = &self.translation;
        [
            [r[0][0], r[0][1], r[0][2], t[0]],
            [r[1][0], r[1][1], r[1][2], t[1]],
            [r[2][0], r[2][1], r[2][2], t[2]],
            [0.0, 0.0, 0.0, 1.0],
        ]
    }

    /// A frame from a 4x4 homogeneous matrix, checked: finite, last row exactly `0 0 0 1`,
    /// rotation part a rotation ([`check_rotation`]).
    pub fn from_homogeneous(h: &[[f64; 4]; 4]) -> Result<Frame, Error> {
        if !h.iter().flatten().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        if h[3] != [0.0, 0.0, 0.0, 1.0] {
            return Err(Error::NotARotation);
        }
        let rotation: Matrix = core::array::from_fn(|i| [h[i][0], h[i][1], h[i][2]]);
        check_rotation(&rotation)?;
        Ok(Frame {
            rotation,
            translation: [h[0][3], h[1][3], h[2][3]],
        })
    }
}
