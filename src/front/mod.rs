//! What both front ends do, the command line (`cli`) and the Python
//! package (`python/`): render scenes into a folder, the render options
//! and their defaults, and a sweep planned, checked, run and gathered.
//! Each front end only turns its own words (flags, keywords) into these
//! calls, so that the two cannot drift apart.

pub mod executor;
pub mod options;
pub mod render;
pub mod sweep;
pub mod timings;
