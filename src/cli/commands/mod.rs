//! The commands, one file each: each turns its checked arguments into
//! library calls and says what it did.

pub mod bench;
pub mod docs;
pub mod render;
pub mod simulate;
pub mod sweep;
pub mod theory;
