//! # cncrot
//!
//! Coordinate rotations for CNC controllers: rotations about the machine axes (extrinsic)
//! and about the workpiece axes (intrinsic), converted into each other for all twelve axis
//! sequences, exactly and robustly, with a C ABI (`include/cncrot.h`).
//!
//! Conventions (docs/conventions.md): active right-handed rotations, angles in degrees,
//! matrices row-major, axis-sequence codes `a1 + 4·a2 + 16·a3` with X = 1, Y = 2, Z = 3.
//!
//! ```
//! use cncrot::{convert, AxisCode, Convention, Kind, Sequence};
//! // Paper, Example 2/3: probe angles about the machine axes X, Y, Z = 30°, 45°, 60°,
//! // as rotations about the workpiece axes Z, X', Y'' for CYCLE800.
//! let d = convert(Kind::Extrinsic, AxisCode::new(57).unwrap(), [30.0, 45.0, 60.0],
//!                 Convention::new(Kind::Intrinsic, Sequence::ZXY));
//! assert!((d.angles[0] - 37.7923).abs() < 1e-4);
//! ```
//!
//! Module map: [`math`](crate) (the only place floating-point functions are called),
//! `sequence` (axis codes), `rotation` (the mathematics), `frame` (translations),
//! `dialects` (controller commands), `kinematics` (rotary-axis positions of real
//! machines), `ffi` (the C boundary, no mathematics).

#![cfg_attr(not(feature = "std"), no_std)]
#![deny(missing_docs)]

mod checksum;
pub mod dialects;
mod error;
mod frame;
pub mod kinematics;
mod math;
mod rotation;
mod sequence;
mod text;
mod vector;

pub mod ffi;

mod panic;
pub mod probe;

pub use checksum::crc32;
pub use error::{Error, STATUSES};
pub use frame::Frame;
pub use rotation::{
    add_rotation, angles_from_matrix, check_rotation, closest_angles, closest_of, convert,
    decompose, determinant, elementary, matrix_from_angles, mul, nearest_rotation,
    orthonormality_error, rotate, rotate_inverse, second_solution, transpose, Decomposition,
    Matrix, Vector, CLOSEST_MAX, ELEMENT_MAX, IDENTITY, ROTATION_TOLERANCE,
};
#[cfg(feature = "nalgebra")]
pub use rotation::{from_nalgebra, to_nalgebra};
pub use sequence::{Axis, AxisCode, Convention, Kind, Sequence};
pub use vector::{rotation_from_x_y, rotation_from_z_x, unit_vector, MIN_SINE};

/// The README's Rust example runs as a doc test (its C, MATLAB and shell blocks are not Rust).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
