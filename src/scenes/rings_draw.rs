//! Pictures of the ring chain (paper Fig. 4b, SI Movie 12): a frame of
//! the movie, the strip of snapshots of the figure, and the kymograph of
//! each ring's normal coloured by its azimuth. Colours come from the
//! theme: the wave's strand (even rings) in series 2 (blue), the partner
//! strand in series 3 (bluish green), taped rings in series 4 (orange, the
//! paper's yellow tapes); the azimuth wheel runs through series 1 to 6.

use crate::encode::Rgb;
use crate::render::palette::Role;
use crate::render::style::{HAlign, VAlign};
use crate::render::tubes::{self, Ortho, Tube};
use crate::render::{Canvas, Picture, Theme};
use crate::rings::run::Sample;
use crate::rings::{RingChain, RingRun};

/// The camera: from azimuth 20° (the paper's photograph is taken from
/// the side), 15° above the horizontal.
pub const VIEW_AZIMUTH: f64 = 20.0;
pub const VIEW_ELEVATION: f64 = 15.0;

/// Ring k's colour.
pub fn ring_color(theme: &Theme, chain: &RingChain, k: usize) -> Rgb {
    if chain.tapes.iter().any(|t| t.contains(&k)) {
        theme.color(Role::Series(4))
    } else {
        theme.color(Role::Series(2 + RingChain::strand(k)))
    }
}

/// The tubes of a sample.
pub fn tubes_of(theme: &Theme, chain: &RingChain, s: &Sample) -> Vec<Tube> {
    (0..s.rings.len())
        .map(|k| Tube {
            centre: s.rings[k].x,
            rot: s.quat(k).matrix(),
            radius: chain.major_radius,
            tube: chain.tube_radius,
            color: ring_color(theme, chain, k),
        })
        .collect()
}

/// One view that holds every sample of the run in a `w × h` box.
pub fn fixed_view(
    theme: &Theme,
    chain: &RingChain,
    samples: &[Sample],
    origin: (f32, f32),
    w: f32,
    h: f32,
) -> Ortho {
    let all: Vec<Tube> = samples
        .iter()
        .flat_map(|s| tubes_of(theme, chain, s))
        .collect();
    Ortho::looking(VIEW_AZIMUTH, VIEW_ELEVATION).fitted(&all, origin, w, h)
}

/// "t = 0.45 s".
pub fn time_label(t: f64) -> String {
    format!("t = {} s", short(t))
}

/// A time in seconds to the hundredth, without trailing zeros: "0.4".
fn short(t: f64) -> String {
    let s = format!("{t:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A movie frame: the chain through `view`, the title above, the time
/// below.
pub fn draw_frame(
    canvas: &mut impl Canvas,
    theme: &Theme,
    chain: &RingChain,
    s: &Sample,
    view: &Ortho,
    title: &str,
    size: (f32, f32),
) {
    let ink = theme.color(Role::Ink);
    tubes::draw_tubes(canvas, theme, view, &tubes_of(theme, chain, s));
    if theme.titles && !title.is_empty() {
        // As every movie's title: smaller where it would not fit the frame.
        let full = crate::render::style::text_width(theme.font(), title, theme.title);
        let room = 0.96 * size.0;
        let title_size = if full > room {
            theme.title * room / full
        } else {
            theme.title
        };
        canvas.text(
            title,
            (0.5 * size.0, 6.0),
            title_size,
            ink,
            (HAlign::Center, VAlign::Top),
        );
    }
    canvas.text(
        &time_label(s.t),
        (0.5 * size.0, size.1 - 6.0),
        theme.label,
        ink,
        (HAlign::Center, VAlign::Baseline),
    );
}

/// Width of a figure: the style's page, or 960 design pixels at screen.
fn figure_width(theme: &Theme) -> f32 {
    theme
        .style
        .width_pt
        .map_or(960.0, |w| w * theme.style.px_per_pt())
}

/// The strip of snapshots of Fig. 4b: one panel per sample, side by side,
/// one view for all, each labelled with its time.
pub fn strip_picture(theme: &Theme, chain: &RingChain, run: &RingRun, title: &str) -> Picture {
    let width = figure_width(theme);
    let ink = theme.color(Role::Ink);
    let count = run.samples.len().max(1) as f32;
    let margin = theme.label;
    let panel = (width - 2.0 * margin) / count;
    let top = if theme.titles {
        theme.title_band()
    } else {
        0.0
    };
    let label = 1.6 * theme.label;
    // The strips no taller than the page leaves (a slide is wide and
    // short): the rings are drawn smaller rather than the figure refused.
    let page = theme
        .style
        .fit_box()
        .map_or(f32::INFINITY, |(w, h)| h.floor() * width / w - top - label);
    let tall = (panel * 4.5)
        .clamp(4.0 * theme.label, 520.0)
        .min(page.max(4.0 * theme.label));
    let height = top + tall + label;
    let mut p = Picture::new(theme, width, height.ceil()).titled(title);
    if theme.titles && !title.is_empty() {
        p.text(
            title,
            (0.5 * width, 4.0),
            theme.title,
            ink,
            (HAlign::Center, VAlign::Top),
        );
    }
    for (k, s) in run.samples.iter().enumerate() {
        let x0 = margin + panel * k as f32;
        let view = fixed_view(
            theme,
            chain,
            &run.samples,
            (x0 + 2.0, top),
            panel - 4.0,
            tall,
        );
        tubes::draw_tubes(&mut p, theme, &view, &tubes_of(theme, chain, s));
        p.text(
            &format!("{} s", short(s.t)),
            (x0 + 0.5 * panel, top + tall + 0.3 * theme.label),
            theme.tick,
            ink,
            (HAlign::Center, VAlign::Top),
        );
    }
    p.fit_page()
}

/// The azimuth wheel: series 1 to 6 around the circle, blended linearly.
pub fn azimuth_color(theme: &Theme, degrees: f64) -> Rgb {
    let anchors: Vec<Rgb> = [1, 4, 3, 5, 2, 6]
        .iter()
        .map(|&i| theme.color(Role::Series(i)))
        .collect();
    let x = degrees.rem_euclid(360.0) / 60.0;
    let k = x.floor() as usize % 6;
    tubes::mix(anchors[k], anchors[(k + 1) % 6], x - x.floor())
}

/// Rows of the kymograph drawn (samples are thinned to this many).
pub const KYMOGRAPH_ROWS: usize = 200;

/// The kymograph: time down, rings across (the even strand, a gap, the
/// odd strand), each cell the azimuth of the ring's normal, paler as the
/// ring lies flat (its normal vertical); flips marked with ink dots.
pub fn kymograph_picture(theme: &Theme, chain: &RingChain, run: &RingRun, title: &str) -> Picture {
    let ink = theme.color(Role::Ink);
    let width = figure_width(theme).min(640.0);
    let top = if theme.titles {
        theme.title_band()
    } else {
        0.0
    } + 1.5 * theme.label;
    let key = key_width(theme);
    let (left, bottom, right) = (3.5 * theme.tick, 3.2 * theme.label, 2.0 * theme.tick + key);
    let cols: Vec<Option<usize>> = (0..chain.n)
        .filter(|k| k % 2 == 0)
        .map(Some)
        .chain([None])
        .chain((0..chain.n).filter(|k| k % 2 == 1).map(Some))
        .collect();
    let plot_w = width - left - right;
    let plot_h = (plot_w * 0.9).min(460.0);
    let cell_w = plot_w / cols.len() as f32;
    let rows = run.samples.len().clamp(1, KYMOGRAPH_ROWS);
    let cell_h = plot_h / rows as f32;
    let mut p = Picture::new(theme, width, (top + plot_h + bottom).ceil()).titled(title);
    if theme.titles && !title.is_empty() {
        p.text(
            title,
            (0.5 * width, 4.0),
            theme.title,
            ink,
            (HAlign::Center, VAlign::Top),
        );
    }
    for r in 0..rows {
        let s = &run.samples[r * run.samples.len() / rows];
        for (c, ring) in cols.iter().enumerate() {
            let Some(k) = *ring else { continue };
            let n = crate::rings::run::normals(&[body_of(s, k)])[0];
            let az = n[1].atan2(n[0]).to_degrees();
            let flat = n[2].abs();
            let color = tubes::mix(azimuth_color(theme, az), theme.color(Role::Paper), flat);
            p.rect(
                left + cell_w * c as f32,
                top + cell_h * r as f32,
                cell_w + 0.3,
                cell_h + 0.3,
                color,
            );
        }
    }
    let t_end = run.samples.last().map_or(1.0, |s| s.t).max(1e-9);
    for f in &run.flips {
        let c = cols.iter().position(|&x| x == Some(f.ring)).unwrap_or(0);
        let y = top + plot_h * (f.t / t_end) as f32;
        p.disc(
            (left + cell_w * (c as f32 + 0.5), y),
            (0.22 * cell_w).clamp(1.0, 3.0),
            ink,
        );
    }
    axes(&mut p, theme, (left, top, plot_w, plot_h), &cols, t_end);
    azimuth_key(
        &mut p,
        theme,
        (width - right + 2.0 * theme.tick, top),
        plot_h,
    );
    p.fit_page()
}

/// Width of the azimuth key: the bar, a gap and its widest number.
fn key_width(theme: &Theme) -> f32 {
    let number = crate::render::style::text_width(theme.font(), "−180°", theme.tick);
    0.8 * theme.label + 0.4 * theme.tick + number
}

/// The colour key of the kymograph: the azimuth wheel as a bar, −180° at
/// the top to 180° at the bottom (the cells' colour where the ring stands
/// upright; paler as it lies flat), numbered every 90°.
fn azimuth_key(p: &mut Picture, theme: &Theme, (x, top): (f32, f32), h: f32) {
    let ink = theme.color(Role::Ink);
    let bar = 0.8 * theme.label;
    let steps = 180;
    for k in 0..steps {
        let az = -180.0 + 360.0 * (k as f64 + 0.5) / steps as f64;
        let y = top + h * k as f32 / steps as f32;
        let color = azimuth_color(theme, az);
        p.rect(x, y, bar, h / steps as f32 + 0.3, color);
    }
    let pen = crate::render::canvas::Pen::new(1.0, ink);
    p.polyline(
        &[
            (x, top),
            (x + bar, top),
            (x + bar, top + h),
            (x, top + h),
            (x, top),
        ],
        &pen,
    );
    for k in 0..=4 {
        let y = top + h * k as f32 / 4.0;
        let degrees = -180 + 90 * k;
        let number = format!("{}°", degrees).replace('-', "−");
        p.line((x + bar, y), (x + bar + 0.2 * theme.tick, y), &pen);
        p.text(
            &number,
            (x + bar + 0.4 * theme.tick, y),
            theme.tick,
            ink,
            (HAlign::Left, VAlign::Middle),
        );
    }
    p.text(
        "φ",
        (x + 0.5 * bar, top - 0.5 * theme.tick - 3.0),
        theme.label,
        ink,
        (HAlign::Center, VAlign::Baseline),
    );
}

fn body_of(s: &Sample, k: usize) -> crate::rings::body::Body {
    crate::rings::body::Body {
        x: s.rings[k].x,
        v: [0.0; 3],
        q: s.quat(k),
        l: [0.0; 3],
    }
}

/// Ring numbers below, times on the left, the axis words.
fn axes(
    p: &mut Picture,
    theme: &Theme,
    (left, top, w, h): (f32, f32, f32, f32),
    cols: &[Option<usize>],
    t_end: f64,
) {
    let ink = theme.color(Role::Ink);
    let cell = w / cols.len() as f32;
    for (c, ring) in cols.iter().enumerate() {
        if let Some(k) = ring
            && k % 10 < 2
        {
            p.text(
                &k.to_string(),
                (left + cell * (c as f32 + 0.5), top + h + 2.0),
                theme.tick,
                ink,
                (HAlign::Center, VAlign::Top),
            );
        }
    }
    for k in 0..=4 {
        let t = t_end * k as f64 / 4.0;
        let y = top + h * k as f32 / 4.0;
        p.text(
            &format!("{t:.1}"),
            (left - 4.0, y),
            theme.tick,
            ink,
            (HAlign::Right, VAlign::Middle),
        );
    }
    p.text(
        "t (s)",
        // Above the first time's number (centred on the plot's top edge).
        (left - 3.0 * theme.tick, top - 0.5 * theme.tick - 3.0),
        theme.label,
        ink,
        (HAlign::Left, VAlign::Baseline),
    );
    let words = "ring: even strand | odd strand; colour: azimuth φ of the normal";
    p.text(
        words,
        (left + 0.5 * w, top + h + 1.3 * theme.label),
        theme.label,
        ink,
        (HAlign::Center, VAlign::Top),
    );
}
