//! Batch exports: many rows in one call (post-processors and MATLAB convert millions of
//! orientations). Each row is computed by the same code as the single call, so it gives the
//! same bits; a failing row leaves its output row untouched and the others are computed.

use super::rotation::{angles_row, convert_row, matrix_row};
use super::{cncrot_status, convention, guard, kind, non_null, Outcome};
use crate::AxisCode;

/// `n` rows of `width` doubles must be an object C can have (at most `PTRDIFF_MAX` bytes),
/// else `CNCROT_STATUS_BAD_ARGUMENT` before anything is read.
fn rows_fit(n: usize, width: usize) -> Result<(), cncrot_status> {
    match n.checked_mul(width.wrapping_mul(8)) {
        Some(bytes) if bytes <= isize::MAX as usize => Ok(()),
        _ => Err(cncrot_status::BadArgument),
    }
}

/// Runs `row` for rows `0..n`, writes each status to `statuses` (unless NULL) and returns
/// the batch's status: the first error's, else the first remark's, else success.
///
/// # Safety
/// `statuses` is NULL or points to `n` writable `int32_t`.
unsafe fn each_row(
    n: usize,
    statuses: *mut i32,
    mut row: impl FnMut(usize) -> Outcome,
) -> cncrot_status {
    let mut first_error = None;
    let mut first_remark = None;
    for i in 0..n {
        let s = match row(i) {
            Ok(s) | Err(s) => s,
        };
        if !statuses.is_null() {
            statuses.wrapping_add(i).write_unaligned(s as i32);
        }
        let code = s as i32;
        if code < 0 && first_error.is_none() {
            first_error = Some(s);
        } else if code > 0 && first_remark.is_none() {
            first_remark = Some(s);
        }
    }
    first_error.or(first_remark).unwrap_or(cncrot_status::Ok)
}

/// `cncrot_matrix_from_angles` for `n` rows: `angles_deg` holds `n` rows of 3 angles,
/// `matrices` receives `n` row-major 3x3 matrices (9 doubles each), contiguous.
///
/// `statuses` (may be NULL) receives each row's status. A row that fails (a non-finite
/// angle) leaves its matrix untouched; the other rows are still computed. Returns 0 when
/// every row succeeded, else the status of the first failing row (a positive status when
/// only remarks occurred). A bad flag or code, a NULL `angles_deg` or `matrices`, or an `n`
/// whose arrays could not exist (`CNCROT_STATUS_BAD_ARGUMENT`) is refused before any row:
/// then nothing is written, `statuses` included. Every row equals the single call's result
/// bit for bit. `n = 0` succeeds and writes nothing.
///
/// Statuses (of the call and of the rows): `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`, `CNCROT_STATUS_BAD_ARGUMENT`
/// before any row; per row `CNCROT_STATUS_NOT_FINITE`.
///
/// # Safety
/// `angles_deg` points to `3n` readable and `matrices` to `9n` writable doubles, not
/// overlapping; `statuses` is NULL or points to `n` writable `int32_t`.
///
/// ```c
/// double a[6] = {30, 45, 60,  0, 90, 0}, m[18];
/// int32_t st[2];
/// cncrot_matrices_from_angles(0, 57, a, 2, m, st);   // m[0] = 0.3536 (paper, Example 2)
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_matrices_from_angles(
    intrinsic: i32,
    sequence: i32,
    angles_deg: *const f64,
    n: usize,
    matrices: *mut f64,
    statuses: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[angles_deg.is_null(), matrices.is_null()])?;
        let kind = kind(intrinsic)?;
        let code = AxisCode::new(sequence)?;
        rows_fit(n, 9)?;
        Ok(each_row(n, statuses, |i| {
            matrix_row(
                kind,
                code,
                angles_deg.wrapping_add(i.wrapping_mul(3)),
                matrices.wrapping_add(i.wrapping_mul(9)),
            )
        }))
    })
}

/// `cncrot_angles_from_matrix` for `n` rows: `matrices` holds `n` row-major 3x3 matrices
/// (9 doubles each), `angles_deg` receives `n` rows of 3 angles, contiguous. Statuses,
/// return value and refusals as `cncrot_matrices_from_angles`: a row that is not a rotation
/// gets `CNCROT_STATUS_NOT_A_ROTATION` and keeps its output row, a singular row
/// `CNCROT_STATUS_SINGULAR`.
///
/// Statuses (of the call and of the rows): `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`,
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE`, `CNCROT_STATUS_BAD_ARGUMENT` before any row; per
/// row `CNCROT_STATUS_SINGULAR`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NOT_A_ROTATION`.
///
/// # Safety
/// `matrices` points to `9n` readable and `angles_deg` to `3n` writable doubles, not
/// overlapping; `statuses` is NULL or points to `n` writable `int32_t`.
///
/// ```c
/// double out[6];
/// int32_t s = cncrot_angles_from_matrices(1, 39, m, 2, out, NULL);   // 1: row 2 is singular
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_angles_from_matrices(
    intrinsic: i32,
    sequence: i32,
    matrices: *const f64,
    n: usize,
    angles_deg: *mut f64,
    statuses: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[matrices.is_null(), angles_deg.is_null()])?;
        let conv = convention(intrinsic, sequence)?;
        rows_fit(n, 9)?;
        Ok(each_row(n, statuses, |i| {
            angles_row(
                conv,
                matrices.wrapping_add(i.wrapping_mul(9)),
                angles_deg.wrapping_add(i.wrapping_mul(3)),
            )
        }))
    })
}

/// `cncrot_convert` for `n` rows of 3 angles, contiguous. Statuses, return value and
/// refusals as `cncrot_matrices_from_angles`. The output may be the input array itself
/// (each row is read whole before it is written), but must not overlap it otherwise.
///
/// Statuses (of the call and of the rows): `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_BAD_SEQUENCE`,
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE`, `CNCROT_STATUS_BAD_ARGUMENT` before any row; per
/// row `CNCROT_STATUS_SINGULAR`, `CNCROT_STATUS_NOT_FINITE`.
///
/// # Safety
/// `angles_in_deg` points to `3n` readable and `angles_out_deg` to `3n` writable doubles,
/// the same array or not overlapping; `statuses` is NULL or points to `n` writable
/// `int32_t`.
///
/// ```c
/// double a[6] = {30, 45, 60,  10, 20, 30};
/// cncrot_convert_many(0, 57, a, 2, 1, 39, a, NULL);   // in place; row 1: 37.7923, 20.7048, 49.1066
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn cncrot_convert_many(
    intrinsic_in: i32,
    sequence_in: i32,
    angles_in_deg: *const f64,
    n: usize,
    intrinsic_out: i32,
    sequence_out: i32,
    angles_out_deg: *mut f64,
    statuses: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[angles_in_deg.is_null(), angles_out_deg.is_null()])?;
        let kind_in = kind(intrinsic_in)?;
        let code_in = AxisCode::new(sequence_in)?;
        let to = convention(intrinsic_out, sequence_out)?;
        rows_fit(n, 3)?;
        Ok(each_row(n, statuses, |i| {
            convert_row(
                kind_in,
                code_in,
                to,
                angles_in_deg.wrapping_add(i.wrapping_mul(3)),
                angles_out_deg.wrapping_add(i.wrapping_mul(3)),
            )
        }))
    })
}
