//! Controller dialects: the commands of the controllers, on top of the rotation mathematics.
//!
//! One file or folder per controller family (`sinumerik/` with its CYCLE600, `HEAD_DEF` and
//! `$TC_CARR`, `heidenhain`, `fanuc`, `syntec`, `twincat`, `haas`), each fulfilling the
//! contract in `family.rs`; the one list of families in `registry.rs`; what is the same for
//! every family in [`program`] (program lines) and [`form`] (commands as numbers, for the C
//! boundary). The families build on the mathematics and `crate::text`; nothing builds on
//! the families but the registry and the modules above it.

mod family;
pub mod fanuc;
pub mod form;
pub mod haas;
pub mod heidenhain;
pub mod program;
mod registry;
pub mod sinumerik;
pub mod syntec;
pub mod toolpath;
pub mod twincat;

// SINUMERIK's cycles and data, at the paths they have always had.
pub use sinumerik::{carr, cycle600, head_def};

/// Whether two matrices agree element by element within `tol` (the dialects' tests).
#[cfg(test)]
pub(crate) fn close(a: &crate::Matrix, b: &crate::Matrix, tol: f64) -> bool {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .all(|(x, y)| (x - y).abs() <= tol)
}
