//! Golden images of the renderer (`LADDER_BLESS=1 cargo test --release
//! --test integration golden::` regenerates them; look at every one before
//! committing).

use crate::common::golden::check;
use crate::common::scenes::{domain_wall, kink_state, ladder};
use jacobs_ladder::render::charts::{self, line_chart};
use jacobs_ladder::render::compose::{self, filmstrip};
use jacobs_ladder::render::snapshot::render_snapshot;
use jacobs_ladder::render::{Palette, Role};

const RED: [u8; 3] = Palette.color(Role::Series(1));
const BLUE: [u8; 3] = Palette.color(Role::Series(2));
const GREEN: [u8; 3] = Palette.color(Role::Series(3));
const DARK: [u8; 3] = Palette.color(Role::Ink);
use jacobs_ladder::render::{
    Axis, ChartSpec, FilmstripOptions, Frame, Kymograph, Layout, Legend, Marker, Panel, Picture,
    Series, Snapshot,
};

fn ground(alpha: f64, title: &str) -> tiny_skia::Pixmap {
    let l = ladder(alpha);
    let q = l.ground_state();
    let snap = Snapshot::new(&l, &q).unwrap().with_title(title);
    render_snapshot(&crate::common::screen(), &snap, 170, 420).unwrap()
}

#[test]
fn snapshot_ground_plus60() {
    check("snapshot-ground-plus60", &ground(60.0, "α = +60°"));
}

#[test]
fn snapshot_ground_minus60() {
    check("snapshot-ground-minus60", &ground(-60.0, "α = −60°"));
}

#[test]
fn snapshot_with_ghost_and_time() {
    let l = ladder(60.0);
    let g = l.ground_state();
    let q = kink_state(&l, 4.3);
    let snap = Snapshot::new(&l, &q)
        .unwrap()
        .with_ghost(&l, &g)
        .unwrap()
        .with_time(1234.0);
    check(
        "snapshot-ghost-time",
        &render_snapshot(&crate::common::screen(), &snap, 170, 420).unwrap(),
    );
}

#[test]
fn filmstrip_kink() {
    let l = ladder(60.0);
    let walls = [0.0, 3.5, 7.0, 11.0];
    let states: Vec<Vec<f64>> = walls.iter().map(|&w| kink_state(&l, w)).collect();
    let frames: Vec<Frame> = states
        .iter()
        .enumerate()
        .map(|(k, q)| Frame {
            time: 500.0 * k as f64,
            q,
        })
        .collect();
    let opts = FilmstripOptions {
        frame_size: Some((90, 300)),
        label: Some("(a1)".into()),
        ..Default::default()
    };
    check(
        "filmstrip-kink",
        &filmstrip(&crate::common::screen(), &l, &frames, &opts).unwrap(),
    );
}

fn kymo() -> charts::Chart {
    let (times, values) = domain_wall(10, 400, 3000.0);
    let mut k = Kymograph::new(&times, &values, 10);
    k.title = Some("kink, α = 60°");
    charts::kymograph(&crate::common::screen(), &k, 360, 300).unwrap()
}

#[test]
fn kymograph_domain_wall() {
    check("kymograph-domain-wall", &kymo().pixmap);
}

/// A double well per a/b, like Fig. 2c.
fn wells() -> ChartSpec {
    let theta: Vec<f64> = (0..=180).map(|k| -90.0 + k as f64).collect();
    let well = |a: f64| -> Vec<(f64, f64)> {
        theta
            .iter()
            .map(|&t| {
                let x = t / a;
                (t, 0.5 * (x * x - 1.0).powi(2) - 1.0)
            })
            .collect()
    };
    ChartSpec::new(Axis::new("θ (degrees)"), Axis::new("U / (m g s)"))
        .title("U(θ), b/s = 1.2")
        .series(Series::line("a/b = 1.1", well(40.0), RED))
        .series(Series::line("a/b = 1.3", well(55.0), BLUE).dashed())
        .series(Series::line("a/b = 1.6", well(70.0), GREEN).with_marker(Marker::Circle))
}

#[test]
fn line_chart_with_legend() {
    let mut spec = wells();
    spec.series[2].points = spec.series[2].points.iter().step_by(10).copied().collect();
    check(
        "line-chart-legend",
        &line_chart(&crate::common::screen(), &spec, 420, 300)
            .unwrap()
            .pixmap,
    );
}

#[test]
fn loglog_chart() {
    let pts = |p: i32, c: f64| -> Vec<(f64, f64)> {
        (0..6)
            .map(|k| {
                let dt = 0.1 / 2f64.powi(k);
                (1000.0 / dt, c * dt.powi(p))
            })
            .collect()
    };
    let spec = ChartSpec::new(
        Axis::new("force evaluations").log(),
        Axis::new("max |Δθ| (rad)").log(),
    )
    .title("work–precision")
    .series(Series::line("verlet", pts(2, 1.0), RED).with_marker(Marker::Circle))
    .series(Series::line("rk4", pts(4, 0.5), BLUE).with_marker(Marker::Square))
    .series(Series::scatter(
        "diverged",
        vec![(2e4, 1.0)],
        DARK,
        Marker::Cross,
    ));
    check(
        "loglog-chart",
        &line_chart(&crate::common::screen(), &spec, 420, 300)
            .unwrap()
            .pixmap,
    );
}

#[test]
fn parametric_equal_aspect() {
    let curve = |r: f64, c: f64| -> Vec<(f64, f64)> {
        (0..=120)
            .map(|k| {
                let q = std::f64::consts::TAU * k as f64 / 120.0;
                (c + r * q.cos(), r * q.sin())
            })
            .collect()
    };
    let mut spec = ChartSpec::new(Axis::new("Re det C(q)"), Axis::new("Im det C(q)"))
        .title("winding")
        .series(Series::line("α > 0: n_C = 1", curve(1.0, 0.4), RED))
        .series(Series::line("α < 0: n_C = 0", curve(0.5, 1.2), BLUE).dashed())
        .series(Series::scatter("", vec![(0.0, 0.0)], DARK, Marker::Cross));
    spec.equal_aspect = true;
    spec.zero_lines = true;
    spec.legend = Legend::Auto;
    check(
        "parametric-equal-aspect",
        &line_chart(&crate::common::screen(), &spec, 420, 300)
            .unwrap()
            .pixmap,
    );
}

#[test]
fn composed_panels() {
    let l = ladder(75.0);
    let lm = ladder(-75.0);
    let (qp, qm) = (l.ground_state(), lm.ground_state());
    let a = render_snapshot(
        &crate::common::screen(),
        &Snapshot::new(&l, &qp).unwrap(),
        120,
        300,
    )
    .unwrap();
    let b = render_snapshot(
        &crate::common::screen(),
        &Snapshot::new(&lm, &qm).unwrap(),
        120,
        300,
    )
    .unwrap();
    let c = line_chart(&crate::common::screen(), &wells(), 380, 300)
        .unwrap()
        .pixmap;
    let panels = vec![
        Panel::new(Picture::of_image(&crate::common::screen(), a))
            .label("(a)")
            .caption("α = +75°"),
        Panel::new(Picture::of_image(&crate::common::screen(), b))
            .label("(b)")
            .caption("α = −75°"),
        Panel::new(Picture::of_image(&crate::common::screen(), c)).label("(c)"),
    ];
    let img = compose::compose(
        &panels,
        &Layout::row(&crate::common::screen(), 3).title("two ground states and U(θ)"),
    )
    .unwrap();
    check("composed-panels", &img);
}

/// A catalogue figure drawn at a print style, at `dpi` pixels per inch.
fn styled_figure(id: &str, name: jacobs_ladder::render::StyleName, dpi: f32) -> tiny_skia::Pixmap {
    use jacobs_ladder::render::Style;
    let style = Style {
        dpi,
        ..Style::named(name)
    };
    let scene = jacobs_ladder::catalog::find(jacobs_ladder::scene::Kind::Figure, id)
        .unwrap()
        .scene
        .clone();
    let theme = jacobs_ladder::render::Theme::of(&style);
    let pic = jacobs_ladder::scenes::figure_picture(&theme, &scene)
        .unwrap()
        .0;
    pic.rasterize(style.png_scale(pic.width())).unwrap()
}

/// The barrier ΔU(α) at `--style paper` (3.375 in wide, 8 pt serif text),
/// 200 dpi: 675 pixels wide.
#[test]
fn figure_barrier_at_paper() {
    let img = styled_figure("barrier", jacobs_ladder::render::StyleName::Paper, 200.0);
    assert_eq!(img.width(), 675, "3.375 in at 200 dpi");
    check("figure-barrier-paper", &img);
}

/// The surface zero mode at `--style slide` (13.333 in wide, 20 pt sans
/// text), 72 dpi: 960 pixels wide.
#[test]
fn figure_edge_mode_at_slide() {
    let img = styled_figure("edge-mode", jacobs_ladder::render::StyleName::Slide, 72.0);
    assert_eq!(img.width(), 960, "13.333 in at 72 dpi");
    check("figure-edge-mode-slide", &img);
}
