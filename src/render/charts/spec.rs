//! What a line chart shows: axes, series, legend placement.

use crate::encode::Rgb;

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Scale {
    #[default]
    Linear,
    /// Base-10 logarithmic; non-positive values are left out.
    Log,
}

/// One axis: its label (with units, Greek letters welcome), an optional
/// fixed range, and the scale.
#[derive(Clone, Debug, Default)]
pub struct Axis {
    pub label: String,
    pub range: Option<(f64, f64)>,
    pub scale: Scale,
    /// Shared with a panel stacked below, which labels it: this panel
    /// draws its ticks without numbers or label.
    pub shared: bool,
    /// Names of the categories at 1, 2, … (a chart of levels, one per
    /// row): the ticks are these names, not numbers.
    pub names: Vec<String>,
    /// A shared axis that keeps its numbers (only its label is the panel
    /// below's): stacked sweep panels, each of whose axes can be read.
    pub numbered: bool,
}

impl Axis {
    /// A linear axis with automatic range.
    pub fn new(label: impl Into<String>) -> Axis {
        Axis {
            label: label.into(),
            ..Axis::default()
        }
    }

    /// Fixes the range.
    pub fn range(mut self, lo: f64, hi: f64) -> Axis {
        self.range = Some((lo, hi));
        self
    }

    /// Makes the axis logarithmic.
    pub fn log(mut self) -> Axis {
        self.scale = Scale::Log;
        self
    }

    /// Categories at 1, 2, …, `names.len()`, each tick labelled with its
    /// name.
    pub fn names(mut self, names: Vec<String>) -> Axis {
        self.range = Some((0.5, names.len() as f64 + 0.5));
        self.names = names;
        self
    }

    /// The tick label of `v` on this axis: its category's name (none
    /// between categories), else the number.
    pub fn tick_text(&self, v: f64) -> String {
        if self.names.is_empty() {
            return super::ticks::tick_label(v, self.scale);
        }
        let k = v.round();
        if (v - k).abs() > 1e-6 || k < 1.0 {
            return String::new();
        }
        self.names.get(k as usize - 1).cloned().unwrap_or_default()
    }

    /// Shared with the panel stacked below, which labels it (an axis
    /// shared by stacked panels is labelled once).
    pub fn shared(mut self) -> Axis {
        self.shared = true;
        self
    }

    /// Shared with the panel stacked below, which labels it, keeping its
    /// own numbers.
    pub fn shared_numbered(mut self) -> Axis {
        self.shared = true;
        self.numbered = true;
        self
    }
}

/// How a series' points are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum LineStyle {
    #[default]
    Solid,
    Dashed,
    /// Markers only.
    None,
}

pub use crate::render::palette::Marker;

/// One data series. Non-finite points (and non-positive ones on log axes)
/// break the line.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text; `None` keeps the series out of the legend.
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub color: Rgb,
    pub line: LineStyle,
    pub marker: Marker,
    /// Line width in pixels.
    pub width: f64,
}

impl Series {
    /// A solid line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>, color: Rgb) -> Series {
        Series {
            label: Some(label.into()).filter(|l: &String| !l.is_empty()),
            points,
            color,
            line: LineStyle::Solid,
            marker: Marker::None,
            width: 2.0,
        }
    }

    /// Markers only, no line.
    pub fn scatter(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        color: Rgb,
        marker: Marker,
    ) -> Series {
        Series {
            line: LineStyle::None,
            marker,
            ..Series::line(label, points, color)
        }
    }

    /// Dashed line.
    pub fn dashed(mut self) -> Series {
        self.line = LineStyle::Dashed;
        self
    }

    /// Adds markers at the points.
    pub fn with_marker(mut self, marker: Marker) -> Series {
        self.marker = marker;
        self
    }

    /// Sets the line width in pixels.
    pub fn with_width(mut self, width: f64) -> Series {
        self.width = width;
        self
    }
}

/// Where the legend goes. `Auto` picks an inside position (corners, then
/// top and bottom middle) that covers no data, and reserves a column right
/// of the plot (`Outside`) when every inside position would.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Legend {
    #[default]
    Auto,
    UpperLeft,
    UpperMiddle,
    UpperRight,
    LowerLeft,
    LowerMiddle,
    LowerRight,
    Outside,
    /// In rows of columns under the plot (chosen by `Auto` when a column
    /// right of the plot would take more than a third of the chart).
    Below,
    Hidden,
}

/// A chart of x–y series.
#[derive(Clone, Debug, Default)]
pub struct ChartSpec {
    pub title: Option<String>,
    pub x: Axis,
    pub y: Axis,
    pub series: Vec<Series>,
    pub legend: Legend,
    /// Equal scales on both axes (parametric curves, the complex plane).
    pub equal_aspect: bool,
    /// Thin grey lines through x = 0 and y = 0 when in range.
    pub zero_lines: bool,
    /// The plot area's left and right edges across the chart, pixels from
    /// its left edge, when they are given (stacked panels sharing one x
    /// extent, docs/formats.md); `None` lays them out from the tick labels
    /// and the legend. A legend right of the plot goes right of `right`.
    pub plot_x: Option<(i32, i32)>,
}

impl ChartSpec {
    /// A chart with the given axes and no series yet.
    pub fn new(x: Axis, y: Axis) -> ChartSpec {
        ChartSpec {
            x,
            y,
            ..ChartSpec::default()
        }
    }

    /// Sets the title.
    pub fn title(mut self, title: impl Into<String>) -> ChartSpec {
        self.title = Some(title.into());
        self
    }

    /// Adds a series.
    pub fn series(mut self, s: Series) -> ChartSpec {
        self.series.push(s);
        self
    }
}
