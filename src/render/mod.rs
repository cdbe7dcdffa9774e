//! Rendering: ladder snapshots, charts (plotters → SVG → resvg),
//! compositions (panels, filmstrips), the movie frame layout, the one
//! palette of roles ([`Palette`]) and the fonts and typesetting they share.
//!
//! Render knows a ladder state (a `q` slice and its [`crate::model::Ladder`]),
//! never an integrator. Drawing code is written once against [`Canvas`]:
//! figures record a [`Picture`] (a display list) that becomes a PNG at any
//! scale, an SVG or a PDF; movie frames draw straight onto a pixmap
//! ([`Raster`]). Turn pixels or trees into bytes with [`crate::encode`] and
//! write them with [`crate::output`].

pub mod blocks;
pub mod canvas;
pub mod cells;
pub mod charts;
pub mod color;
pub mod compose;
pub mod fit;
pub mod fold;
pub mod fonts;
pub mod italic;
pub mod markup;
pub mod movie_layout;
pub mod page_style;
pub mod palette;
pub mod picture;
mod picture_files;
pub mod raster_text;
pub mod snapshot;
pub mod style;
mod svg;
pub mod text_boxes;
pub mod theme;
pub mod tubes;
pub mod typeset;

pub use canvas::{Canvas, Cap, Pen, Raster};
pub use charts::{Axis, Chart, ChartSpec, Kymograph, Legend, LineStyle, Marker, Scale, Series};
pub use compose::{FilmstripOptions, Frame, Layout, Panel};
pub use fit::{fitted, line_chart_figure};
pub use movie_layout::MovieLayout;
pub use page_style::{FontChoice, Length, Style, StyleName, StyleSpec, TextMode};
pub use palette::{OutcomeRole, Palette, Role};
pub use picture::{Item, PageSide, Picture};
pub use snapshot::{Region, Snapshot, View};
pub use text_boxes::TextBox;
pub use theme::Theme;
