//! Scene → canvas: renders each catalogue entry into the bytes of its files.
//! `theory` draws the static figures (geometry, formulas, linear theory);
//! `dynamic` the simulated figures and the movies.

pub mod dynamic;
pub mod theory;

use crate::catalog::{Content, Entry};
use crate::encode::png_bytes;
use crate::error::Result;
pub use dynamic::MovieOptions;

/// The files of one entry, as (file name, bytes), in `Entry::files` order.
pub fn render(entry: &Entry, movie: &MovieOptions) -> Result<Vec<(String, Vec<u8>)>> {
    let names = entry.files();
    let bytes = match entry.content {
        Content::Theory(fig) => vec![png_bytes(&theory::render(fig)?)?],
        Content::Strips(strips) => {
            let image = dynamic::strips_figure(entry.title, strips, dynamic::STRIP_FRAME)?;
            vec![png_bytes(&image)?]
        }
        Content::Arrivals(alphas) => {
            vec![png_bytes(&dynamic::arrivals_figure(entry.title, alphas)?)?]
        }
        Content::Movie { sim, follow_kink } => {
            let (gif, kymo) = dynamic::movie(entry.title, &sim, follow_kink, movie)?;
            vec![gif, kymo]
        }
    };
    Ok(names.into_iter().zip(bytes).collect())
}
