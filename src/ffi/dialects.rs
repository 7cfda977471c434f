//! Exports of the dialects' tilted-plane commands: a form's words to a frame and back.

use super::frame::{read_frame, write_frame};
use super::{cncrot_status, guard, non_null, status_of};
use crate::dialects::form::{self, Form, MAX_VALUES};

/// SINUMERIK `CYCLE800`: selector `_MODE`; words `_X0 _Y0 _Z0 _A _B _C _X1 _Y1 _Z1`.
pub const CNCROT_FORM_CYCLE800: i32 = 1;
/// SINUMERIK `ROT`/`CROT`: selector 0 RPY, 1 Euler; words `X Y Z`.
pub const CNCROT_FORM_SINUMERIK_ROT: i32 = 2;
/// SINUMERIK `ROTS` (frame only): selector 0 `X Y`, 1 `Y Z`, 2 `Z X`; the two angles.
pub const CNCROT_FORM_SINUMERIK_ROTS: i32 = 3;
/// Heidenhain `PLANE SPATIAL`: selector 0; words `SPA SPB SPC`.
pub const CNCROT_FORM_PLANE_SPATIAL: i32 = 4;
/// Heidenhain `PLANE EULER`: selector 0; words `EULPR EULNU EULROT`.
pub const CNCROT_FORM_PLANE_EULER: i32 = 5;
/// Heidenhain `PLANE VECTOR`: selector 0; words `BX BY BZ NX NY NZ`.
pub const CNCROT_FORM_PLANE_VECTOR: i32 = 6;
/// Heidenhain `PLANE POINTS`: selector 0; words `P1X P1Y P1Z P2X P2Y P2Z P3X P3Y P3Z`. The
/// points give the plane's orientation only: the frame has no origin (the control does not
/// move the datum to P1).
pub const CNCROT_FORM_PLANE_POINTS: i32 = 7;
/// Fanuc-style `G68.2`: selector 0; words `X Y Z I J K`.
pub const CNCROT_FORM_G68_2: i32 = 8;
/// Syntec `G158`: selector the `P` word; words `X Y Z A B C U V W`.
pub const CNCROT_FORM_G158: i32 = 9;
/// Beckhoff TwinCAT NC I `ROT`: selector 0; words `X Y Z`.
pub const CNCROT_FORM_TWINCAT_ROT: i32 = 10;
/// Haas `G268`: selector the `Q` word; words `X Y Z I J K`.
pub const CNCROT_FORM_G268: i32 = 11;
/// Fanuc-style `G68.3` (vertical axis +Z): selector 0; words `X Y Z R TX TY TZ`, T the tool
/// direction.
pub const CNCROT_FORM_G68_3: i32 = 12;
/// Heidenhain `PLANE PROJECTED`: selector 0; words `PROPR PROMIN PROROT`.
pub const CNCROT_FORM_PLANE_PROJECTED: i32 = 13;
/// The most words a form has (`count` is exactly the form's number of words).
pub const CNCROT_FORM_MAX_WORDS: usize = 9;
/// How far the frame of the words `cncrot_form_values` and `cncrot_program_write` give may
/// be from the frame asked for: each rotation element, and each origin coordinate relative to
/// the origin's largest (at least 1). Words that would not read back this close (near a
/// projection's singularity) are refused with `CNCROT_STATUS_OUT_OF_RANGE`.
pub const CNCROT_READ_BACK_TOLERANCE: f64 = 1e-12;
// Each C code is the Rust form's discriminant, and the word capacity the Rust one: a change
// on one side fails to compile (the list of forms itself is checked in the tests below).
const _: () = {
    assert!(CNCROT_FORM_MAX_WORDS == MAX_VALUES);
    assert!(CNCROT_FORM_CYCLE800 == Form::Cycle800 as i32);
    assert!(CNCROT_FORM_SINUMERIK_ROT == Form::SinumerikRot as i32);
    assert!(CNCROT_FORM_SINUMERIK_ROTS == Form::SinumerikRots as i32);
    assert!(CNCROT_FORM_PLANE_SPATIAL == Form::PlaneSpatial as i32);
    assert!(CNCROT_FORM_PLANE_EULER == Form::PlaneEuler as i32);
    assert!(CNCROT_FORM_PLANE_VECTOR == Form::PlaneVector as i32);
    assert!(CNCROT_FORM_PLANE_POINTS == Form::PlanePoints as i32);
    assert!(CNCROT_FORM_G68_2 == Form::G68_2 as i32);
    assert!(CNCROT_FORM_G158 == Form::G158 as i32);
    assert!(CNCROT_FORM_TWINCAT_ROT == Form::TwincatRot as i32);
    assert!(CNCROT_FORM_G268 == Form::G268 as i32);
    assert!(CNCROT_FORM_G68_3 == Form::G68_3 as i32);
    assert!(CNCROT_FORM_PLANE_PROJECTED == Form::PlaneProjected as i32);
    assert!(Form::ALL.len() == 13);
};
const _: () = assert!(CNCROT_READ_BACK_TOLERANCE == form::READ_BACK_TOLERANCE);

/// How many words a form has (the `count` that `cncrot_form_frame` and `cncrot_form_values`
/// require), in `*count`. Returns 0, or with `*count` untouched `CNCROT_STATUS_NULL_POINTER`
/// or `CNCROT_STATUS_BAD_ARGUMENT` (an unknown form).
///
/// # Safety
/// `count` points to a writable `size_t` (or NULL: error).
///
/// ```c
/// size_t n;
/// cncrot_form_word_count(CNCROT_FORM_G68_2, &n);   // 6
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_form_word_count(form: i32, count: *mut usize) -> i32 {
    guard(|| {
        non_null(&[count.is_null()])?;
        let form = Form::from_code(form)?;
        count.write_unaligned(form.count());
        Ok(cncrot_status::Ok)
    })
}

/// The frame (4x4, row-major) of a tilted-plane command given as its form, its selector and
/// its words (see the `CNCROT_FORM_*` constants for each form's selector and word order;
/// omitted words are 0). `count` must be the form's number of words.
///
/// Returns 0, or a negative status with `frame` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_ARGUMENT` (unknown form, wrong `count`, a selector the form does not
/// have), `CNCROT_STATUS_BAD_SEQUENCE` (a bad order code in `_MODE`, `P` or `Q`: an axis
/// repeated, or a `Q` that is not a permutation of 1, 2, 3), `CNCROT_STATUS_INCOMPLETE_SEQUENCE`
/// (a `CYCLE800` `_MODE` whose axis code names fewer than the three axes its mode turns
/// about), `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_DEGENERATE` (a zero `PLANE VECTOR` normal or B along N, a zero `G68.3`
/// tool direction or `G158` mode-3 normal), `CNCROT_STATUS_COINCIDENT` /
/// `CNCROT_STATUS_COLLINEAR` (`PLANE POINTS`), `CNCROT_STATUS_NOT_AVAILABLE` (direct modes, which need the
/// machine's kinematics), `CNCROT_STATUS_OUT_OF_RANGE` (an origin whose frame overflows).
///
/// # Safety
/// `words` points to `count` readable doubles, `frame` to 16 writable doubles (or NULL:
/// error).
///
/// ```c
/// double w[6] = {10, 0, 0, 0, 30, 0}, f[16];   // G68.2 X10 I0 J30 K0
/// cncrot_form_frame(CNCROT_FORM_G68_2, 0, w, 6, f);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_form_frame(
    form: i32,
    selector: i32,
    words: *const f64,
    count: usize,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[words.is_null(), frame.is_null()])?;
        let form = Form::from_code(form)?;
        if count != form.count() {
            return Err(cncrot_status::BadArgument);
        }
        let mut w = [0.0; MAX_VALUES];
        let w = w.get_mut(..count).ok_or(cncrot_status::BadArgument)?;
        for (k, x) in w.iter_mut().enumerate() {
            *x = words.add(k).read_unaligned();
            if !x.is_finite() {
                return Err(cncrot_status::NotFinite);
            }
        }
        let f = form::form_frame(form, selector, w)?;
        write_frame(frame, &f)?;
        Ok(cncrot_status::Ok)
    })
}

/// The words of a tilted-plane form that give `frame` (the inverse of
/// `cncrot_form_frame`): what a writer of a measured or converted plane needs. Angles in the
/// dialect's canonical ranges; at the singular middle angle the free angle sits where that
/// dialect's rule puts it and the status is `CNCROT_STATUS_SINGULAR`. A rotation rounded where
/// it was written (within the rotation tolerance but more than 1e-12 from orthonormal: a
/// matrix printed to 4 decimals) gets the words of its nearest rotation.
///
/// Refused, with `words` untouched: `CNCROT_STATUS_NULL_POINTER`;
/// `CNCROT_STATUS_NOT_FINITE`; `CNCROT_STATUS_HAS_ORIGIN` for a frame with an origin and a
/// form without origin words (SINUMERIK `ROT`, `PLANE SPATIAL/EULER/VECTOR/POINTS/PROJECTED`,
/// TwinCAT `ROT`: pass the rotation alone and the datum in the dialect's own command);
/// `CNCROT_STATUS_BAD_ARGUMENT` for an unknown form, a wrong `count`, `ROTS` (not every
/// plane is a projection), an incremental or mode-0 `G158` `P`, a selector the form does
/// not have;
/// `CNCROT_STATUS_BAD_SEQUENCE` for a bad order code in `_MODE`, `P` or `Q`;
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE` for an axis-by-axis `_MODE` or `G158` order of fewer
/// than three rotations (`_MODE` 0..3: it cannot express every frame);
/// `CNCROT_STATUS_NOT_AVAILABLE` for direct modes; `CNCROT_STATUS_OUT_OF_RANGE` for a frame
/// the form cannot express (a projection at or near its singularity: words that would not
/// read back within `CNCROT_READ_BACK_TOLERANCE`) or whose words overflow;
/// `CNCROT_STATUS_NOT_A_ROTATION` for a frame that is not one.
///
/// # Safety
/// `frame` points to 16 readable doubles, `words` to `count` writable doubles (or NULL:
/// error).
///
/// ```c
/// double w[3];   // the PLANE SPATIAL angles of a measured plane f
/// if (cncrot_form_values(CNCROT_FORM_PLANE_SPATIAL, 0, f, w, 3) >= 0) printf("SPA%.4f\n", w[0]);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_form_values(
    form: i32,
    selector: i32,
    frame: *const f64,
    words: *mut f64,
    count: usize,
) -> i32 {
    guard(|| {
        non_null(&[frame.is_null(), words.is_null()])?;
        let form = Form::from_code(form)?;
        if count != form.count() {
            return Err(cncrot_status::BadArgument);
        }
        let mut f = read_frame(frame)?;
        // A rotation rounded where it was written (4 decimals): its words are those of the
        // nearest rotation (its own would not read back to it).
        f.rotation = crate::rotation::exact_or_nearest(&f.rotation);
        let mut w = [0.0; MAX_VALUES];
        let w = w.get_mut(..count).ok_or(cncrot_status::BadArgument)?;
        let singular = form::form_values(form, selector, &f, w)?;
        for (k, &x) in w.iter().enumerate() {
            words.add(k).write_unaligned(x);
        }
        Ok(status_of(singular))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The C constants (literals, which cbindgen can write) name the Rust forms.
    #[test]
    fn constants_name_the_forms() {
        let c = [
            (CNCROT_FORM_CYCLE800, Form::Cycle800),
            (CNCROT_FORM_SINUMERIK_ROT, Form::SinumerikRot),
            (CNCROT_FORM_SINUMERIK_ROTS, Form::SinumerikRots),
            (CNCROT_FORM_PLANE_SPATIAL, Form::PlaneSpatial),
            (CNCROT_FORM_PLANE_EULER, Form::PlaneEuler),
            (CNCROT_FORM_PLANE_VECTOR, Form::PlaneVector),
            (CNCROT_FORM_PLANE_POINTS, Form::PlanePoints),
            (CNCROT_FORM_G68_2, Form::G68_2),
            (CNCROT_FORM_G158, Form::G158),
            (CNCROT_FORM_TWINCAT_ROT, Form::TwincatRot),
            (CNCROT_FORM_G268, Form::G268),
            (CNCROT_FORM_G68_3, Form::G68_3),
            (CNCROT_FORM_PLANE_PROJECTED, Form::PlaneProjected),
        ];
        assert_eq!(c.len(), Form::ALL.len());
        for (code, form) in c {
            assert_eq!(Form::from_code(code), Ok(form));
        }
        assert_eq!(CNCROT_FORM_MAX_WORDS, MAX_VALUES);
        assert_eq!(Form::ALL.iter().map(|f| f.count()).max(), Some(MAX_VALUES));
    }
}
