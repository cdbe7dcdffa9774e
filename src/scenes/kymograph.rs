//! The kymograph view: sin θₙ over blocks and time.

use super::data::RunData;
use super::run::{self};
use crate::error::{Error, Result};
use crate::render::charts::{self, Kymograph};
use crate::render::{MovieLayout, Picture, Theme};
use crate::scene::{Scene, describe};
use crate::sim::Trajectory;
use tiny_skia::Pixmap;

/// A kymograph figure: sin θ_n of the scene's run over `frames` rows,
/// drawn with `theme`.
pub fn kymograph_figure(theme: &Theme, scene: &Scene, frames: usize) -> Result<(Picture, RunData)> {
    // `t_end = "auto"` resolved here too, for callers of this function
    // that did not go through `scenes::render_to` (a no-op when resolved).
    let scene = &scene.with_auto_window()?;
    let times = frame_times(scene.run.t_end, frames);
    let run = run::simulate(scene, &times)?;
    let title = describe::title(scene);
    // The run once; the chart is drawn again only to search a size.
    let (picture, ()) = crate::render::fitted(theme, |t| {
        let (w, h) = t.style.frame((820, 560));
        let image = kymograph_chart(t, &title, &run.trajectory, scene.model.n, w, h)?;
        Ok((Picture::from(image).fit_page().titled(title.clone()), ()))
    })?;
    Ok((picture, RunData::with_kymograph(scene, run)))
}

/// The kymograph of sin θ_n of `traj`: blocks across, time down, as a
/// `width × height` image. Above 640 × 480 the chart is laid out at the
/// size of the movie layout's design frame and drawn scaled up, so its
/// text and lines grow with the image as the movie's do.
pub fn kymograph_image(
    theme: &Theme,
    title: &str,
    traj: &Trajectory,
    n: usize,
    width: u32,
    height: u32,
) -> Result<Pixmap> {
    let scale = MovieLayout::new(theme, width, height, n).scale.max(1.0);
    if scale <= 1.0 {
        return Ok(kymograph_chart(theme, title, traj, n, width, height)?.pixmap);
    }
    let design = |v: u32| ((v as f32 / scale).round() as u32).max(60);
    let chart = kymograph_chart(theme, title, traj, n, design(width), design(height))?;
    let tree = chart
        .tree()
        .ok_or_else(|| Error::failed("the kymograph's SVG could not be parsed"))?;
    charts::rasterize_tree(tree, width, height)
}

/// The kymograph of [`kymograph_image`] as a picture (for every figure
/// format) with the scale at which its PNG is `width × height`.
pub fn kymograph_picture(
    theme: &Theme,
    title: &str,
    traj: &Trajectory,
    n: usize,
    width: u32,
    height: u32,
) -> Result<MovieKymograph> {
    // At a print style the kymograph is a figure of the page, as a
    // kymograph view is: laid out at the page's size, so that its text
    // prints at the style's size.
    if theme.is_print() {
        let (w, h) = theme.style.frame((820, 560));
        let chart = kymograph_chart(theme, title, traj, n, w, h)?;
        return Ok(MovieKymograph {
            png_scale: 1.0,
            picture: Picture::from(chart).fit_page().titled(title),
        });
    }
    let scale = MovieLayout::new(theme, width, height, n).scale.max(1.0);
    let design = |v: u32| ((v as f32 / scale).round() as u32).max(60);
    let (w, h) = if scale <= 1.0 {
        (width, height)
    } else {
        (design(width), design(height))
    };
    let chart = kymograph_chart(theme, title, traj, n, w, h)?;
    let picture: Picture = chart.into();
    Ok(MovieKymograph {
        png_scale: width as f32 / w as f32,
        picture: picture.titled(title),
    })
}

/// The kymograph chart (SVG and raster) of sin θ_n of `traj`.
fn kymograph_chart(
    theme: &Theme,
    title: &str,
    traj: &Trajectory,
    n: usize,
    width: u32,
    height: u32,
) -> Result<charts::Chart> {
    let states: Vec<&[f64]> = traj.states.iter().map(|q| q.as_slice()).collect();
    let values = charts::polarisation_rows(&states);
    // An empty title leaves no stray ": " before the quantity.
    let kymo_title = if title.ends_with("sin θₙ") {
        title.to_string()
    } else if title.trim().is_empty() {
        "sin θₙ".to_string()
    } else {
        format!("{title}: sin θₙ")
    };
    let mut k = Kymograph::new(&traj.times, &values, n);
    k.title = Some(&kymo_title);
    let marks = super::toy::kymograph_marks(traj.impacts.as_deref());
    k.marks = &marks;
    charts::kymograph(theme, &k, width, height)
}

/// The kymograph beside a movie: a picture like any figure's, and the
/// scale at which its PNG has the movie's pixels (above 640 × 480 the
/// chart is laid out at the movie layout's design size and drawn scaled
/// up, so its text grows with the movie's).
pub struct MovieKymograph {
    pub picture: Picture,
    /// PNG pixels per picture pixel at `--scale 1`.
    pub png_scale: f32,
}

/// Frame times of a movie: `frames` times evenly over [0, t_end].
pub fn frame_times(t_end: f64, frames: usize) -> Vec<f64> {
    crate::scene::even_times(t_end, frames)
}
