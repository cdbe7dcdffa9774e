//! The static figures of the catalogue (SPEC section 4): 2b, 2c, 2d, S3, S4,
//! S5, winding, edge-mode and barrier.

use crate::catalog::TheoryFigure;
use crate::error::{Error, Result};
use tiny_skia::Pixmap;

/// Renders one static figure.
pub fn render(figure: TheoryFigure) -> Result<Pixmap> {
    Err(Error::failed(format!("figure {figure:?} is not drawn yet")))
}
