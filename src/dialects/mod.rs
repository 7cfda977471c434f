//! Controller dialects: the commands of the controllers, on top of the rotation mathematics.

pub mod carr;
pub mod cycle600;
pub mod fanuc;
pub mod form;
pub mod haas;
pub mod head_def;
pub mod heidenhain;
pub mod program;
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
