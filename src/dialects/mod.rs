//! Controller dialects: the commands of the controllers, on top of the rotation mathematics.

pub mod cycle600;
pub mod head_def;
pub mod sinumerik;
