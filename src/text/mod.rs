//! Program text: the one place where characters become numbers and numbers characters.
//!
//! - [`scan`]: the cursor every reader walks a line with (program lines of every dialect,
//!   `$TC_CARR` assignments, `HEAD_DEF` tokens), what a number is in each dialect
//!   ([`scan::Syntax`]), address words, errors with their column;
//! - [`number`]: decimal numbers read and written, correctly rounded both ways, without
//!   allocation, `core::fmt` or a path that can panic;
//! - `big`: the fixed-size integers that make the rare hard cases exact.
//!
//! Nothing here knows a controller: the dialects hand their rules in.

mod big;
pub mod number;
pub mod scan;
