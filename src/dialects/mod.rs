//! Controller dialects: the commands of the controllers, on top of the rotation mathematics.

pub mod cycle600;
pub mod fanuc;
pub mod form;
pub mod haas;
pub mod head_def;
pub mod heidenhain;
pub mod sinumerik;
pub mod syntec;
pub mod twincat;
