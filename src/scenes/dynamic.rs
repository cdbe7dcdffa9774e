//! The simulated scenes: filmstrips (figures 1c, 3, 4a), arrival times
//! (figure S6) and the movies with their kymographs. Each simulation runs
//! only to its last frame and is sampled only at the times drawn.

pub use super::data::{FrameData, RunData};
pub use super::kymograph::{MovieKymograph, frame_times};
pub use super::movie::{movie, movie_at, movie_block_pixels, movie_column_numbers, movie_frame};
pub use super::options::{MAX_FRAMES, MAX_SIDE, MIN_SIDE};
use super::run::{self, SceneRun};
use super::walls::wall_marks;
pub use super::walls::{Wall, walls};
use crate::error::Result;
use crate::model::Ladder;
use crate::render::compose::{
    self, ChainMark, FilmstripOptions, Frame, Layout, Panel, StripGeometry,
};
use crate::render::palette::Role;
use crate::render::{Picture, Theme, style};
use crate::scene::{MIN_BLOCK_PIXELS, OutputSpec, Scene, describe};

/// "kink α = 60°" or "antikink α = −60°".
pub(crate) fn wave_name(alpha_deg: f64) -> String {
    let kind = crate::sim::waves::WaveKind::launched(alpha_deg).name();
    format!("{kind} α = {}°", describe::num(alpha_deg))
}

/// Snapshot size in a filmstrip for an N-block ladder: 330 pixels tall up
/// to N = 10, taller for longer chains (up to 900), so that blocks stay
/// visible.
pub fn strip_frame(n: usize) -> (u32, u32) {
    let h = (330.0 * (n.max(10) as f64 / 10.0).sqrt()).min(900.0) as u32;
    (96, h)
}

/// Width of a filmstrip frame with [`wall_marks`]: room for "antikink"
/// beside the chain.
const MARKED_FRAME_WIDTH: u32 = 170;

/// A simulated filmstrip: the run, its ladder and how to draw it.
struct Strip {
    run: SceneRun,
    ladder: Ladder,
    opts: FilmstripOptions,
}

impl Strip {
    /// The strip of a single-run scene at `times`: snapshots of `frame`
    /// pixels (default [`strip_frame`]) sharing one scale, a long ladder
    /// folded into columns so that no block is shorter than
    /// [`MIN_BLOCK_PIXELS`], and with several flips the walls marked;
    /// with one flip and `fronts`, each wave's front ([`front_marks`]).
    fn new(
        label: &str,
        scene: &Scene,
        times: &[f64],
        frame: Option<(u32, u32)>,
        fit: Option<(u32, u32)>,
        fronts: bool,
    ) -> Result<Strip> {
        let run = run::simulate(scene, times)?;
        let ladder = super::toy::drawn_ladder(scene)?;
        let traj = &run.trajectory;
        let title =
            (!label.is_empty()).then(|| format!("{label}  {}", wave_name(scene.model.alpha)));
        // Several flips put a kink and an antikink on the chain at once: mark
        // them (and where they meet) in wider frames that leave room for words.
        let marked = scene.drive.flips.len() > 1;
        let marks: Vec<Vec<ChainMark>> = if marked {
            traj.states.iter().map(|q| wall_marks(q)).collect()
        } else if fronts {
            traj.times
                .iter()
                .map(|t| front_marks(&traj.waves, *t))
                .collect()
        } else {
            Vec::new()
        };
        let mut size = frame.unwrap_or_else(|| strip_frame(scene.model.n));
        if marked {
            size.0 = size.0.max(MARKED_FRAME_WIDTH);
        }
        let opts = FilmstripOptions {
            frame_size: Some(size),
            title,
            label: None,
            view: None,
            marks,
            min_block_pixels: Some(MIN_BLOCK_PIXELS as f32),
            fit,
        };
        Ok(Strip { run, ladder, opts })
    }

    /// The snapshots, from the samples the strip's data took from its run
    /// (`RunData::taking_samples`: drawn and written from one copy).
    fn frames<'a>(data: &'a RunData) -> Vec<Frame<'a>> {
        data.frames
            .rows()
            .map(|(time, q)| Frame { time, q })
            .collect()
    }

    /// The strip drawn with `theme`, fitted to the box `fit` (pixels).
    fn picture(&self, theme: &Theme, data: &RunData, fit: Option<(u32, u32)>) -> Result<Picture> {
        let frames = Self::frames(data);
        if fit == self.opts.fit {
            return compose::filmstrip_picture(theme, &self.ladder, &frames, &self.opts);
        }
        let opts = FilmstripOptions {
            fit,
            ..self.opts.clone()
        };
        compose::filmstrip_picture(theme, &self.ladder, &frames, &opts)
    }
}

/// The marks of a snapshot at time `t` from the wave tracker's record:
/// for every wave on the chain at `t` (launched, and neither at the end
/// nor annihilated yet), a triangle in its kind's colour (kink on the
/// left, antikink on the right) at its front, the block it reached last
/// by `t` (its origin before it reached any), exactly at that block. No
/// words: the strip's title names its wave, and a snapshot of a strip of
/// seven is too narrow for them.
pub(crate) fn front_marks(waves: &crate::sim::waves::Waves, t: f64) -> Vec<ChainMark> {
    use crate::sim::waves::{Fate, WaveKind};
    waves
        .waves
        .iter()
        .filter_map(|w| {
            // The last block the wave crossed by `t`, and when.
            let last = w
                .arrival_times
                .iter()
                .enumerate()
                .filter_map(|(i, a)| a.filter(|a| *a <= t).map(|a| (i + 1, a)))
                .max_by(|a, b| a.1.total_cmp(&b.1));
            let gone = match w.fate {
                // At the end: off the chain from its arrival at the last block.
                Fate::End => w
                    .arrival_times
                    .get(w.front.wrapping_sub(1))
                    .copied()
                    .flatten(),
                Fate::Annihilated { at, .. } => Some(at),
                Fate::Stopped | Fate::Undecided => None,
            };
            if w.launched_at > t || gone.is_some_and(|g| g <= t) {
                return None;
            }
            let kink = w.kind == WaveKind::Kink;
            Some(ChainMark {
                at: last.map_or(w.origin, |(b, _)| b) as f64,
                label: String::new(),
                role: if kink { Role::Kink } else { Role::Antikink },
                side: if kink {
                    style::HAlign::Left
                } else {
                    style::HAlign::Right
                },
            })
        })
        .collect()
}

/// Strips a row at a print style: two on a page wide enough for two
/// strips of snapshots side by side (`paper-wide`), where the ladders are
/// then drawn larger than one strip a row would, else one.
fn print_columns(theme: &Theme, count: usize) -> usize {
    let wide = theme.style.fit_box().is_some_and(|(w, _)| w >= WIDE_PAGE);
    if wide && count >= 2 { 2 } else { 1 }
}

/// Design width from which a print page takes two strips a row.
const WIDE_PAGE: f32 = 800.0;

/// The box each of `count` strips must fit at a print style, in
/// [`print_columns`] strips a row under the figure's title on the style's
/// page ([`crate::render::Style::fit_box`]); none at screen.
fn strip_fit(theme: &Theme, count: usize) -> Option<(u32, u32)> {
    let (w, h) = theme.style.fit_box()?;
    let (m, gap) = (theme.margin, theme.gap);
    // The figure's title band, where the style draws titles.
    let title = if theme.titles {
        theme.title_band()
    } else {
        0.0
    };
    let cols = print_columns(theme, count) as f32;
    let rows = count.max(1).div_ceil(cols as usize) as f32;
    let wide = (w - 2.0 * m - (cols - 1.0) * gap) / cols;
    let each = (h - 2.0 * m - title - (rows - 1.0) * gap) / rows;
    Some((wide.floor() as u32, each.max(1.0).floor() as u32))
}

/// The strips of a filmstrip scene, one per panel, with their data.
fn strips(
    theme: &Theme,
    scene: &Scene,
    frame: Option<(u32, u32)>,
) -> Result<Vec<(Strip, RunData)>> {
    // `t_end = "auto"` resolved here too, for callers of this function
    // that did not go through `scenes::render_to` (a no-op when resolved).
    let scene = &scene.with_auto_window()?;
    let labels = panel_labels(scene);
    let runs = scene.runs();
    let fit = strip_fit(theme, runs.len());
    // Strips side by side compare waves (Fig. 3: kink and antikink at
    // ±60° and ±50°): each snapshot marks where its wave is.
    let fronts = runs.len() > 1;
    runs.iter()
        .zip(&labels)
        .map(|((s, times), label)| {
            let mut strip = Strip::new(label, s, times, frame, fit, fronts)?;
            let data = RunData::taking_samples(label, s, &mut strip.run);
            Ok((strip, data))
        })
        .collect()
}

/// Widest row of two strips side by side, pixels: wider strips (those of
/// folded ladders) go one a row.
const MAX_STRIP_ROW: u32 = 2000;

/// The figure's layout of `panels`: two strips a row when there are more
/// than two and they fit (more when one or two a row would be too tall),
/// with the scene's title.
fn strips_layout(theme: &Theme, scene: &Scene, panels: &[Panel]) -> Layout {
    let widest = panels
        .iter()
        .map(|p| p.image.pixel_size().0)
        .max()
        .unwrap_or(0);
    // At a print style the strips were fitted [`print_columns`] a row.
    let two = if theme.is_print() {
        print_columns(theme, panels.len()) == 2
    } else {
        panels.len() > 2 && 2 * widest <= MAX_STRIP_ROW
    };
    // Journal styles draw no figure title (the caption is the document's).
    let layout = |columns| {
        let l = Layout::columns(theme, columns);
        if theme.titles {
            l.title(describe::title(scene))
        } else {
            l
        }
    };
    // Tall strips (of folded ladders) go side by side rather than make a
    // figure taller than a picture may be.
    let first = if two { 2 } else { 1 };
    (first..=panels.len().max(first))
        .map(layout)
        .find(|l| compose::panel_origins(panels, l).is_ok())
        .unwrap_or_else(|| layout(first))
}

/// A filmstrip figure (figures 1c, 3 and 4a): one strip per panel, two
/// strips a row, with the scene's title; snapshots of `frame` pixels
/// (default [`strip_frame`]), drawn with `theme`. A page too small for
/// the style's text is refused as [`crate::render::fitted`] says, naming
/// the smallest width or height that holds the figure: the strips are
/// composed again for each size tried (their snapshots re-fitted), and
/// the runs are not repeated.
pub fn filmstrip_figure(
    theme: &Theme,
    scene: &Scene,
    frame: Option<(u32, u32)>,
) -> Result<(Picture, Vec<RunData>)> {
    let strips = strips(theme, scene, frame)?;
    let (picture, ()) =
        crate::render::fitted(theme, |t| Ok((compose_strips(t, scene, &strips)?, ())))?;
    let data = strips.into_iter().map(|(_, d)| d).collect();
    Ok((picture, data))
}

/// The strips drawn and composed into one figure on the style's page,
/// each fitted to its share of that page ([`strip_fit`]), titled.
fn compose_strips(theme: &Theme, scene: &Scene, strips: &[(Strip, RunData)]) -> Result<Picture> {
    let fit = strip_fit(theme, strips.len());
    let panels = strips
        .iter()
        .map(|(s, d)| Ok(Panel::new(s.picture(theme, d, fit)?)))
        .collect::<Result<Vec<_>>>()?;
    let layout = strips_layout(theme, scene, &panels);
    Ok(compose::compose_picture(&panels, &layout)?
        .fit_page()
        .titled(describe::title(scene)))
}

/// For a test of the filmstrips: where [`filmstrip_figure`] draws every
/// block, one [`StripGeometry`] per strip in the figure's pixels.
pub fn filmstrip_geometry(
    theme: &Theme,
    scene: &Scene,
    frame: Option<(u32, u32)>,
) -> Result<Vec<StripGeometry>> {
    let strips = strips(theme, scene, frame)?;
    let panels = strips
        .iter()
        .map(|(s, d)| Ok(Panel::new(s.picture(theme, d, s.opts.fit)?)))
        .collect::<Result<Vec<_>>>()?;
    let layout = strips_layout(theme, scene, &panels);
    let (size, origins) = compose::panel_origins(&panels, &layout)?;
    strips
        .iter()
        .zip(origins)
        .map(|((s, d), at)| {
            let g = compose::filmstrip_geometry(theme, &s.ladder, &Strip::frames(d), &s.opts)?;
            Ok(g.placed(at, size))
        })
        .collect()
}

pub(crate) fn panel_labels(scene: &Scene) -> Vec<String> {
    match &scene.output {
        OutputSpec::Filmstrip { panels, .. } | OutputSpec::Arrivals { curves: panels } => {
            let mut l: Vec<String> = panels.iter().map(|p| p.label.clone()).collect();
            if l.is_empty() {
                l.push(String::new());
            }
            l
        }
        _ => vec![String::new()],
    }
}

#[cfg(test)]
mod front_mark_tests {
    use super::*;
    use crate::render::Palette;
    use crate::render::{Item, Style, StyleName};
    use crate::scene::Kind;
    use tiny_skia::Transform;

    /// The centre of every filled triangle of `colors` in `items`, in the
    /// picture's pixels.
    fn triangles(
        items: &[Item],
        ts: Transform,
        colors: &[crate::encode::Rgb],
        out: &mut Vec<(f32, f32)>,
    ) {
        for item in items {
            match item {
                Item::Fill { path, color } if colors.contains(color) => {
                    let mut p: Vec<tiny_skia::Point> = path.points().to_vec();
                    p.dedup();
                    if p.len() == 3 {
                        ts.map_points(&mut p);
                        let b = tiny_skia::Rect::from_points(&p).unwrap();
                        out.push((0.5 * (b.left() + b.right()), 0.5 * (b.top() + b.bottom())));
                    }
                }
                Item::Group { transform, items } => {
                    triangles(items, ts.pre_concat(*transform), colors, out)
                }
                _ => {}
            }
        }
    }

    /// Where the tracker has a wave at `t`: launched by then, and not yet
    /// at the end nor annihilated (the record's own words).
    fn tracked_at(waves: &crate::sim::waves::Waves, t: f64) -> Vec<usize> {
        use crate::sim::waves::Fate;
        waves
            .waves
            .iter()
            .filter(|w| w.launched_at <= t)
            .filter(|w| match w.fate {
                Fate::End => w.arrival_times[w.front - 1].is_some_and(|a| a > t),
                Fate::Annihilated { at, .. } => at > t,
                _ => true,
            })
            .map(|w| {
                // The block crossed last by t.
                (1..=w.arrival_times.len())
                    .filter(|b| w.arrival_times[b - 1].is_some_and(|a| a <= t))
                    .max_by(|a, b| {
                        w.arrival_times[a - 1]
                            .unwrap()
                            .total_cmp(&w.arrival_times[b - 1].unwrap())
                    })
                    .unwrap_or(w.origin)
            })
            .collect()
    }

    /// Every text drawn in `items`: (text, colour).
    fn texts(items: &[Item], out: &mut Vec<(String, crate::encode::Rgb)>) {
        for item in items {
            match item {
                Item::Text { text, color, .. } => out.push((text.clone(), *color)),
                Item::Group { items, .. } => texts(items, out),
                _ => {}
            }
        }
    }

    /// Figure 4a marks its kinks and antikinks in the colours figure 3
    /// marks them in (the palette's roles: vermillion and blue; 4a drew
    /// them orange and purple), and the words beside its marks read at
    /// 4.5:1 on white (4a's orange "kink" read at 2.25:1).
    #[test]
    fn figure_4a_marks_kinks_as_figure_3_does_in_words_that_read() {
        use crate::render::palette::contrast_on_white;
        let theme = Theme::of(&Style::default());
        let scene = crate::catalog::find(Kind::Figure, "4a")
            .unwrap()
            .scene
            .clone();
        let strips = strips(&theme, &scene, None).unwrap();
        let picture = compose_strips(&theme, &scene, &strips).unwrap();
        let (kink, antikink) = (Palette.color(Role::Kink), Palette.color(Role::Antikink));
        for (color, what) in [(kink, "kink"), (antikink, "antikink")] {
            let mut found = Vec::new();
            triangles(picture.items(), Transform::identity(), &[color], &mut found);
            assert!(!found.is_empty(), "no {what} mark in {color:?}");
        }
        let mut words = Vec::new();
        texts(picture.items(), &mut words);
        for want in ["kink", "antikink", "collision"] {
            let (_, c) = words
                .iter()
                .find(|(t, _)| t == want)
                .unwrap_or_else(|| panic!("no \"{want}\" in 4a"));
            assert!(contrast_on_white(*c) >= 4.5, "{want} in {c:?}");
        }
        let kink_word = words.iter().find(|(t, _)| t == "kink").unwrap().1;
        assert_eq!(kink_word, Palette.text(Role::Kink), "the kink's own hue");
    }

    /// Figure 3 at paper: each row marks, with a triangle in its wave's
    /// colour, every snapshot where the tracker has a wave and no other,
    /// each at the height of the front block's centre, exactly.
    #[test]
    fn figure_3_marks_each_front_at_its_block() {
        let theme = Theme::of(&Style::named(StyleName::Paper));
        let scene = crate::catalog::find(Kind::Figure, "3")
            .unwrap()
            .scene
            .clone();
        let strips = strips(&theme, &scene, None).unwrap();
        let geometry = filmstrip_geometry(&theme, &scene, None).unwrap();
        let picture = compose_strips(&theme, &scene, &strips).unwrap();
        let mut found = Vec::new();
        triangles(
            picture.items(),
            Transform::identity(),
            &[Palette.color(Role::Kink), Palette.color(Role::Antikink)],
            &mut found,
        );
        let mut expected_total = 0;
        for ((strip, data), g) in strips.iter().zip(&geometry) {
            let traj = &strip.run.trajectory;
            let frames = Strip::frames(data);
            assert_eq!(frames.len(), g.snapshots.len());
            let mut marked = 0;
            for (k, f) in frames.iter().enumerate() {
                let fronts = tracked_at(&traj.waves, f.time);
                let r = g.snapshots[k];
                let here: Vec<&(f32, f32)> = found
                    .iter()
                    .filter(|(x, y)| {
                        *y >= r.y && *y <= r.y + r.h && *x >= r.x - 1.0 && *x <= r.x + r.w + 1.0
                    })
                    .collect();
                assert_eq!(
                    here.len(),
                    fronts.len(),
                    "{}: snapshot {k} (t = {}) has {} marks, the tracker {fronts:?}",
                    data.label,
                    f.time,
                    here.len()
                );
                for b in &fronts {
                    let [a, e] = g.blocks[k][b - 1];
                    let y = 0.5 * (a.1 + e.1);
                    assert!(
                        here.iter().any(|m| (m.1 - y).abs() < 1e-3),
                        "{}: snapshot {k}: no mark at block {b} (y = {y}): {here:?}",
                        data.label
                    );
                }
                marked += usize::from(!fronts.is_empty());
                expected_total += fronts.len();
            }
            // The first snapshot (t = 0) has no wave yet; every row has some.
            assert!(tracked_at(&traj.waves, frames[0].time).is_empty());
            assert!(marked >= 4, "{}: {marked} snapshots marked", data.label);
        }
        assert_eq!(found.len(), expected_total, "{found:?}");
    }
}
