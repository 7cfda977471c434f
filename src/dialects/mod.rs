//! Controller dialects: the commands of the controllers, on top of the rotation mathematics.
//!
//! One file per controller family (`sinumerik`, `heidenhain`, `fanuc`, `syntec`, `twincat`,
//! `haas`; SINUMERIK's CYCLE600, `HEAD_DEF` and `$TC_CARR` beside it), each fulfilling the
//! contract in `family.rs`; the one list of families in `registry.rs`; what is the same for
//! every family in [`program`] (program lines) and [`form`] (commands as numbers, for the C
//! boundary). The families build on the mathematics and `crate::text`; nothing builds on
//! the families but the registry and the modules above it.

pub mod carr;
pub mod cycle600;
mod family;
pub mod fanuc;
pub mod form;
pub mod haas;
pub mod head_def;
pub mod heidenhain;
pub mod program;
mod registry;
pub mod sinumerik;
pub mod syntec;
pub mod twincat;

/// Whether two matrices agree element by element within `tol` (the dialects' tests).
#[cfg(test)]
pub(crate) fn close(a: &crate::Matrix, b: &crate::Matrix, tol: f64) -> bool {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .all(|(x, y)| (x - y).abs() <= tol)
}
