//! Scene → canvas: renders each catalogue entry into image bytes.
//! `theory` draws the static figures (geometry, formulas, linear theory);
//! `dynamic` the simulated figures and the movies.

pub mod theory;
