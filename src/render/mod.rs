//! Rendering: ladder snapshots (tiny-skia), charts (plotters → SVG → resvg),
//! compositions (panels, filmstrips) and the shared style.
//!
//! Render knows a ladder state (a `q` slice and its [`crate::model::Ladder`]),
//! never an integrator. Every function returns a `tiny_skia::Pixmap`; turn it
//! into bytes with [`crate::encode`] and write it with [`crate::output`].

pub mod cells;
pub mod charts;
pub mod compose;
pub mod snapshot;
pub mod style;

pub use charts::{Axis, Chart, ChartSpec, Kymograph, Legend, LineStyle, Marker, Scale, Series};
pub use compose::{FilmstripOptions, Frame, Layout, Panel};
pub use snapshot::{Region, Snapshot, View};
