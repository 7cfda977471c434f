//! Exports of the rotation mathematics.

use super::{
    cncrot_status, convention, guard, kind, non_null, read_finite, read_matrix, status_of,
    with_matrix, write, write_matrix, Outcome,
};
use crate::{AxisCode, Convention, Kind, Sequence};

/// The rotation matrix of three angles in a convention.
///
/// `intrinsic`: 1 about the rotated (workpiece) axes, `R = R_a1·R_a2·R_a3`; 0 about the
/// fixed (machine) axes, `R = R_a3·R_a2·R_a1`. `sequence`: axis-sequence code
/// `a1 + 4·a2 + 16·a3` (X = 1, Y = 2, Z = 3; a pair 00 skips that rotation and its angle).
/// `angles_deg`: θ1, θ2, θ3 in degrees, in rotation order. `matrix`: 9 doubles, row-major.
/// Multiples of 90° give exact 0 and ±1.
///
/// Returns 0, or with `matrix` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_NOT_FINITE`.
///
/// # Safety
/// `angles_deg` points to 3 readable, `matrix` to 9 writable doubles (or NULL: error).
///
/// ```c
/// double a[3] = {30, 45, 60}, m[9];
/// cncrot_matrix_from_angles(0, 57, a, m);   // paper, Example 2: m[0] = 0.3536
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_matrix_from_angles(
    intrinsic: i32,
    sequence: i32,
    angles_deg: *const f64,
    matrix: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[angles_deg.is_null(), matrix.is_null()])?;
        let kind = kind(intrinsic)?;
        let code = AxisCode::new(sequence)?;
        matrix_row(kind, code, angles_deg, matrix)
    })
}

/// One row of `cncrot_matrix_from_angles` (also each row of `cncrot_matrices_from_angles`,
/// so that both give the same bits).
///
/// # Safety
/// `angles_deg` points to 3 readable, `matrix` to 9 writable doubles.
pub(super) unsafe fn matrix_row(
    kind: Kind,
    code: AxisCode,
    angles_deg: *const f64,
    matrix: *mut f64,
) -> Outcome {
    let angles = read_finite::<3>(angles_deg)?;
    let m = crate::rotation::matrix_from_angles_inline(kind, code, angles);
    write_matrix(matrix, &m)?;
    Ok(cncrot_status::Ok)
}

/// The angles of a rotation matrix in a convention (one of the 12 three-rotation codes), in
/// the canonical ranges: θ1, θ3 in (-180, 180], θ2 in [-90, 90] (Tait-Bryan) or [0, 180]
/// (proper Euler). Accurate to 1e-15 in reconstruction everywhere, including near the
/// singular middle angle.
///
/// Returns 0; `CNCROT_STATUS_SINGULAR` (1) when the middle angle is singular (θ2 = ±90
/// Tait-Bryan, 0/180 proper Euler), where θ3 = 0 and θ1 carries the whole free rotation;
/// or a negative status with `angles_deg` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_INCOMPLETE_SEQUENCE`
/// (a sequence of fewer than three rotations), `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NOT_A_ROTATION` (not orthonormal within `CNCROT_ROTATION_TOLERANCE`, or a
/// reflection).
///
/// # Safety
/// `matrix` points to 9 readable, `angles_deg` to 3 writable doubles (or NULL: error).
///
/// ```c
/// double out[3];
/// int32_t s = cncrot_angles_from_matrix(1, 39, m, out);   // 37.7923, 20.7048, 49.1066
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_angles_from_matrix(
    intrinsic: i32,
    sequence: i32,
    matrix: *const f64,
    angles_deg: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[matrix.is_null(), angles_deg.is_null()])?;
        let conv = convention(intrinsic, sequence)?;
        angles_row(conv, matrix, angles_deg)
    })
}

/// One row of `cncrot_angles_from_matrix` and `cncrot_angles_from_matrices`.
///
/// # Safety
/// `matrix` points to 9 readable, `angles_deg` to 3 writable doubles.
pub(super) unsafe fn angles_row(
    conv: Convention,
    matrix: *const f64,
    angles_deg: *mut f64,
) -> Outcome {
    // `check_rotation` refuses a non-finite element as `NOT_FINITE` itself; a second pass
    // over the nine here cost a tenth of the call. It and `decompose` are called apart (what
    // `angles_from_matrix` does): the `Result` of the whole decomposition came back through
    // memory in pieces, read at offsets its stores could not forward to.
    with_matrix(matrix, |m| {
        crate::check_rotation(m)?;
        let d = crate::rotation::decompose_inline(conv, m);
        write(angles_deg, d.angles)?;
        Ok(status_of(d.singular))
    })
}

/// Converts angles from one convention to another: `sequence_in` may skip rotations (00
/// pairs), `sequence_out` must be one of the 12 three-rotation codes. Output as
/// `cncrot_angles_from_matrix`, including the singular status.
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR`, or with `angles_out_deg` untouched
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`,
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE` (a `sequence_out` of fewer than three rotations),
/// `CNCROT_STATUS_NOT_FINITE`.
///
/// # Safety
/// `angles_in_deg` points to 3 readable, `angles_out_deg` to 3 writable doubles (or NULL:
/// error); they may be the same array.
///
/// ```c
/// double in[3] = {30, 45, 60}, out[3];
/// cncrot_convert(0, 57, in, 1, 39, out);   // paper, Example 3: 37.7923, 20.7048, 49.1066
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_convert(
    intrinsic_in: i32,
    sequence_in: i32,
    angles_in_deg: *const f64,
    intrinsic_out: i32,
    sequence_out: i32,
    angles_out_deg: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[angles_in_deg.is_null(), angles_out_deg.is_null()])?;
        let kind_in = kind(intrinsic_in)?;
        let code_in = AxisCode::new(sequence_in)?;
        let to = convention(intrinsic_out, sequence_out)?;
        convert_row(kind_in, code_in, to, angles_in_deg, angles_out_deg)
    })
}

/// One row of `cncrot_convert` and `cncrot_convert_many`. The input is read whole before
/// the output is written, so the two may be the same array.
///
/// # Safety
/// `angles_in_deg` points to 3 readable, `angles_out_deg` to 3 writable doubles.
pub(super) unsafe fn convert_row(
    kind_in: Kind,
    code_in: AxisCode,
    to: Convention,
    angles_in_deg: *const f64,
    angles_out_deg: *mut f64,
) -> Outcome {
    let angles = read_finite::<3>(angles_in_deg)?;
    let d = crate::rotation::convert_inline(kind_in, code_in, angles, to);
    write(angles_out_deg, d.angles)?;
    Ok(status_of(d.singular))
}

/// The other decomposition of the rotation given by `angles_in_deg`:
/// `(θ1+180, 180−θ2, θ3+180)` for Tait-Bryan, `(θ1+180, −θ2, θ3+180)` for proper Euler
/// sequences, all three wrapped into (-180, 180]. The same for intrinsic and extrinsic.
/// Input angles of any size are reduced exactly first.
///
/// Returns 0, or with `angles_out_deg` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_INCOMPLETE_SEQUENCE` (a sequence of fewer
/// than three rotations), `CNCROT_STATUS_NOT_FINITE`.
///
/// # Safety
/// `angles_in_deg` points to 3 readable, `angles_out_deg` to 3 writable doubles (or NULL:
/// error); they may be the same array.
///
/// ```c
/// double a[3] = {10, 20, 30};
/// cncrot_second_solution(57, a, a);   // -170, 160, -150
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_second_solution(
    sequence: i32,
    angles_in_deg: *const f64,
    angles_out_deg: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[angles_in_deg.is_null(), angles_out_deg.is_null()])?;
        let seq = Sequence::from_code(sequence)?;
        let angles = read_finite::<3>(angles_in_deg)?;
        let d = crate::Decomposition {
            angles,
            singular: false,
        };
        write(angles_out_deg, crate::second_solution(seq, d).angles)?;
        Ok(cncrot_status::Ok)
    })
}

/// Of the two decompositions of `matrix`, each angle shifted by whole turns, the one nearest
/// to `reference_deg` (least sum of squared differences; ties go to the canonical one):
/// pass the current axis positions to avoid needless swivel motion. Status as
/// `cncrot_angles_from_matrix`; `CNCROT_STATUS_OUT_OF_RANGE` when a result angle would be
/// 65536 degrees or more (a reference that far away: doubles there no longer denote the
/// rotation to 6e-14 rad).
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR`, or with `angles_deg` untouched
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`,
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_OUT_OF_RANGE`.
///
/// # Safety
/// `matrix` points to 9 and `reference_deg` to 3 readable doubles, `angles_deg` to 3
/// writable doubles (or NULL: error).
///
/// ```c
/// double ref[3] = {-165, -15, 200}, out[3];
/// cncrot_closest_angles(1, 55, m, ref, out);   // for m = ZXZ(10, 20, 30): -170, -20, 210
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_closest_angles(
    intrinsic: i32,
    sequence: i32,
    matrix: *const f64,
    reference_deg: *const f64,
    angles_deg: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            matrix.is_null(),
            reference_deg.is_null(),
            angles_deg.is_null(),
        ])?;
        let conv = convention(intrinsic, sequence)?;
        let m = read_matrix(matrix)?;
        let reference = read_finite::<3>(reference_deg)?;
        let d = crate::closest_angles(conv, &m, reference)?;
        write(angles_deg, d.angles)?;
        Ok(status_of(d.singular))
    })
}

/// Checks that a matrix is a rotation: finite, `max |MᵀM − I| <= CNCROT_ROTATION_TOLERANCE`
/// and determinant positive.
///
/// Returns 0, or `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NOT_A_ROTATION`.
///
/// # Safety
/// `matrix` points to 9 readable doubles (or NULL: error).
///
/// ```c
/// if (cncrot_check_rotation(m) != 0) return -1;  // or cncrot_nearest_rotation, deliberately
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_check_rotation(matrix: *const f64) -> i32 {
    guard(|| {
        non_null(&[matrix.is_null()])?;
        let m = read_matrix(matrix)?;
        crate::check_rotation(&m)?;
        Ok(cncrot_status::Ok)
    })
}

/// The nearest rotation (Frobenius norm) to a nearly orthonormal matrix, such as one
/// assembled from probe measurements. Returns 0, or with `matrix_out` untouched
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_DEGENERATE` (a
/// singular matrix or one nearest to a reflection).
///
/// # Safety
/// `matrix_in` points to 9 readable, `matrix_out` to 9 writable doubles (or NULL: error);
/// they may be the same array.
///
/// ```c
/// double measured[9] = {1, 0.001, 0, -0.001, 1, 0, 0, 0, 1.0002}, r[9];
/// cncrot_nearest_rotation(measured, r);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_nearest_rotation(
    matrix_in: *const f64,
    matrix_out: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[matrix_in.is_null(), matrix_out.is_null()])?;
        let m = read_matrix(matrix_in)?;
        let r = crate::nearest_rotation(&m)?;
        write_matrix(matrix_out, &r)?;
        Ok(cncrot_status::Ok)
    })
}

/// Applies an additional rotation (angles in a convention, like `cncrot_matrix_from_angles`)
/// to an existing rotation matrix: extrinsic (`intrinsic` = 0, about the machine axes)
/// multiplies from the left, `R_add·R_old`; intrinsic from the right, `R_old·R_add`
/// (TwinCAT/SINUMERIK `AROT`, CYCLE600 `_ROT_AD`). `matrix_in` must be a rotation. The
/// result is brought back to orthonormal (to 2 ulp), so chains of any length in place do
/// not drift.
///
/// Returns 0, or with `matrix_out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NOT_A_ROTATION` (`matrix_in`).
///
/// # Safety
/// `angles_deg` points to 3 and `matrix_in` to 9 readable doubles, `matrix_out` to 9
/// writable doubles (or NULL: error); `matrix_in` and `matrix_out` may be the same array.
///
/// ```c
/// double z15[3] = {15, 0, 0};
/// cncrot_add_rotation(1, 3, z15, m, m);   // AROT Z15 on the active rotation m
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_add_rotation(
    intrinsic: i32,
    sequence: i32,
    angles_deg: *const f64,
    matrix_in: *const f64,
    matrix_out: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            angles_deg.is_null(),
            matrix_in.is_null(),
            matrix_out.is_null(),
        ])?;
        let kind = kind(intrinsic)?;
        let code = AxisCode::new(sequence)?;
        let angles = read_finite::<3>(angles_deg)?;
        let old = read_matrix(matrix_in)?;
        crate::check_rotation(&old)?;
        let add = crate::matrix_from_angles(kind, code, angles);
        write_matrix(matrix_out, &crate::add_rotation(kind, &old, &add))?;
        Ok(cncrot_status::Ok)
    })
}

/// `R·v` (TwinCAT `CalcRot`): a vector given in the rotated system, in the original axes.
/// `matrix` must be a rotation.
///
/// Returns 0, or with `out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_OUT_OF_RANGE`
/// (a result that overflows: a vector near the largest double).
///
/// # Safety
/// `matrix` points to 9 and `vector` to 3 readable doubles, `out` to 3 writable doubles
/// (or NULL: error); `vector` and `out` may be the same array.
///
/// ```c
/// double v[3] = {40, 10, 0}, out[3];
/// cncrot_rotate_vector(m, v, out);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_rotate_vector(
    matrix: *const f64,
    vector: *const f64,
    out: *mut f64,
) -> i32 {
    rotate_export(matrix, vector, out, crate::rotate)
}

/// `Rᵀ·v`, the inverse rotation (TwinCAT `CalcInvRot`): after `ROT Z45`, (40, 10, 0)
/// gives (35.36, -21.21, 0). `matrix` must be a rotation.
///
/// Returns 0, or with `out` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_OUT_OF_RANGE`
/// (a result that overflows: a vector near the largest double).
///
/// # Safety
/// As `cncrot_rotate_vector`.
///
/// ```c
/// double v[3] = {40, 10, 0}, out[3];
/// cncrot_rotate_vector_inverse(m, v, out);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_rotate_vector_inverse(
    matrix: *const f64,
    vector: *const f64,
    out: *mut f64,
) -> i32 {
    rotate_export(matrix, vector, out, crate::rotate_inverse)
}

/// The body of both vector exports, which differ only in the operation.
///
/// # Safety
/// As `cncrot_rotate_vector`.
unsafe fn rotate_export(
    matrix: *const f64,
    vector: *const f64,
    out: *mut f64,
    op: impl FnOnce(&crate::Matrix, crate::Vector) -> crate::Vector,
) -> i32 {
    guard(|| {
        non_null(&[matrix.is_null(), vector.is_null(), out.is_null()])?;
        let m = read_matrix(matrix)?;
        let v = read_finite::<3>(vector)?;
        crate::check_rotation(&m)?;
        write(out, op(&m, v))?;
        Ok(cncrot_status::Ok)
    })
}
