//! Rings drawn as tubes in an orthographic view (paper Fig. 4b, SI Movie
//! 12): every ring's centre circle cut into [`SEGMENTS`] segments, the
//! segments of all rings sorted by depth one by one (far first), each
//! drawn as its outline (a wider stroke in the ink colour, butt ends) and
//! then its shaded fill (round ends), so interlocked rings cross in front
//! and behind as they do in space. Render knows only poses (centre,
//! rotation, radii, colour), never the simulation.

use super::canvas::{Canvas, Cap, Pen};
use super::palette::Role;
use super::theme::Theme;
use crate::encode::Rgb;

/// Segments per ring.
pub const SEGMENTS: usize = 48;

/// One ring to draw: centre (m), rotation (body → world, rows first; the
/// centre circle in the body xy plane), centre-line and tube radii (m),
/// colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tube {
    pub centre: [f64; 3],
    pub rot: [[f64; 3]; 3],
    pub radius: f64,
    pub tube: f64,
    pub color: Rgb,
}

/// An orthographic camera: looking along `dir` (from the viewer into the
/// scene), `up` the world direction drawn upwards; world point → pixel by
/// `scale` pixels per metre about `centre` (world) at `at` (pixels).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ortho {
    pub right: [f64; 3],
    pub up: [f64; 3],
    pub dir: [f64; 3],
    pub centre: [f64; 3],
    pub at: (f32, f32),
    pub scale: f64,
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = dot(a, a).sqrt();
    [a[0] / n, a[1] / n, a[2] / n]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl Ortho {
    /// The view from azimuth `azimuth` (degrees; the viewer stands at that
    /// horizontal direction from the chain) and `elevation` degrees above
    /// the horizontal, z up.
    pub fn looking(azimuth: f64, elevation: f64) -> Ortho {
        let (a, e) = (azimuth.to_radians(), elevation.to_radians());
        let dir = [-a.cos() * e.cos(), -a.sin() * e.cos(), -e.sin()];
        let right = unit(cross(dir, [0.0, 0.0, 1.0]));
        let up = cross(right, dir);
        Ortho {
            right,
            up,
            dir,
            centre: [0.0; 3],
            at: (0.0, 0.0),
            scale: 1.0,
        }
    }

    /// Pixel of a world point.
    pub fn pixel(&self, p: [f64; 3]) -> (f32, f32) {
        let d = [
            p[0] - self.centre[0],
            p[1] - self.centre[1],
            p[2] - self.centre[2],
        ];
        (
            self.at.0 + (self.scale * dot(d, self.right)) as f32,
            self.at.1 - (self.scale * dot(d, self.up)) as f32,
        )
    }

    /// Depth of a world point (larger is farther).
    pub fn depth(&self, p: [f64; 3]) -> f64 {
        dot(p, self.dir)
    }

    /// This view fitted to `tubes` in a `w × h` box at `origin` (pixels):
    /// centred on their bounds, as large as fits.
    pub fn fitted(mut self, tubes: &[Tube], origin: (f32, f32), w: f32, h: f32) -> Ortho {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for t in tubes {
            let reach = t.radius + t.tube;
            let (u, v) = (dot(t.centre, self.right), dot(t.centre, self.up));
            lo = [lo[0].min(u - reach), lo[1].min(v - reach)];
            hi = [hi[0].max(u + reach), hi[1].max(v + reach)];
        }
        if !lo[0].is_finite() {
            return self;
        }
        let scale = (w as f64 / (hi[0] - lo[0])).min(h as f64 / (hi[1] - lo[1]));
        let (mu, mv) = (0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
        self.centre = [
            mu * self.right[0] + mv * self.up[0],
            mu * self.right[1] + mv * self.up[1],
            mu * self.right[2] + mv * self.up[2],
        ];
        self.at = (origin.0 + 0.5 * w, origin.1 + 0.5 * h);
        self.scale = scale;
        self
    }
}

/// A colour between `a` (f = 0) and `b` (f = 1).
pub fn mix(a: Rgb, b: Rgb, f: f64) -> Rgb {
    let f = f.clamp(0.0, 1.0);
    std::array::from_fn(|k| (a[k] as f64 + (b[k] as f64 - a[k] as f64) * f).round() as u8)
}

/// Draws `tubes` through `view` on `canvas`, segments sorted by depth.
/// The outline takes the theme's ink (series 0); the fill is the tube's
/// colour, lighter where the tube runs across the light (from the upper
/// left, in front) and darker where it runs along it.
pub fn draw_tubes(canvas: &mut impl Canvas, theme: &Theme, view: &Ortho, tubes: &[Tube]) {
    let ink = theme.color(Role::Ink);
    let white = theme.color(Role::Paper);
    let light = unit([-0.5, 0.4, 0.75]);
    let light = [
        dot(light, view.right),
        dot(light, view.up),
        -dot(light, view.dir),
    ];
    let mut segments: Vec<(f64, usize, [f64; 3], [f64; 3])> = Vec::new();
    for (k, t) in tubes.iter().enumerate() {
        let point = |j: usize| {
            let a = std::f64::consts::TAU * j as f64 / SEGMENTS as f64;
            let b = [t.radius * a.cos(), t.radius * a.sin(), 0.0];
            std::array::from_fn(|i| t.centre[i] + dot(t.rot[i], b))
        };
        for j in 0..SEGMENTS {
            let (p, q) = (point(j), point(j + 1));
            let mid = [
                0.5 * (p[0] + q[0]),
                0.5 * (p[1] + q[1]),
                0.5 * (p[2] + q[2]),
            ];
            segments.push((view.depth(mid), k, p, q));
        }
    }
    segments.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    for (_, k, p, q) in segments {
        let t = &tubes[k];
        let width = (2.0 * t.tube * view.scale) as f32;
        let outline = (0.18 * width).clamp(0.6, 1.6 * theme.thin.max(0.6));
        let (a, b) = (view.pixel(p), view.pixel(q));
        canvas.line(
            a,
            b,
            &Pen {
                width: width + 2.0 * outline,
                color: ink,
                cap: Cap::Butt,
                dash: None,
            },
        );
        // Brightness of a cylinder along the segment: √(1 − (t·l)²).
        let along = unit([q[0] - p[0], q[1] - p[1], q[2] - p[2]]);
        let along = [
            dot(along, view.right),
            dot(along, view.up),
            -dot(along, view.dir),
        ];
        let lit = (1.0 - dot(along, light).powi(2)).max(0.0).sqrt();
        let fill = if lit > 0.8 {
            mix(t.color, white, 2.0 * (lit - 0.8))
        } else {
            mix(t.color, ink, 0.5 * (0.8 - lit))
        };
        canvas.line(a, b, &Pen::new(width, fill).round());
    }
}
