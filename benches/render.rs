//! Per-frame cost of movies: rasterise a 10-block snapshot at 640×480 and
//! append it to a GIF (budget: 1 ms per frame). Also prints the size of a
//! 200-frame kink-sweep movie.

use criterion::{Criterion, criterion_group, criterion_main};
use jacobs_ladder::encode::GifWriter;
use jacobs_ladder::model::ladder::itheta;
use jacobs_ladder::model::{Ladder, Params};
use jacobs_ladder::render::snapshot::render_snapshot_into;
use jacobs_ladder::render::{Snapshot, View};
use std::hint::black_box;
use tiny_skia::Pixmap;

const W: u32 = 640;
const H: u32 = 480;
const FRAMES: usize = 200;

/// A kink sweep: the domain wall passes block after block, so block angles
/// flip one by one from +α to −α over `FRAMES` frames.
fn sweep_states(ladder: &Ladder) -> Vec<Vec<f64>> {
    let alpha = ladder.params.alpha;
    (0..FRAMES)
        .map(|k| {
            let wall = 11.0 * k as f64 / (FRAMES - 1) as f64;
            let mut q = ladder.ground_state();
            for i in 0..ladder.n() {
                q[itheta(i)] = alpha * ((i as f64 + 1.0 - wall) / 0.8).tanh();
            }
            q
        })
        .collect()
}

fn frame(ladder: &Ladder, q: &[f64], view: View, k: usize, canvas: &mut Pixmap) {
    let t = 15.0 * k as f64;
    let snap = Snapshot::new(ladder, q)
        .expect("state matches ladder")
        .with_view(view)
        .with_time(t);
    render_snapshot_into(
        &jacobs_ladder::render::Theme::of(&Default::default()),
        canvas,
        &snap,
    );
}

fn movie_bytes(ladder: &Ladder, states: &[Vec<f64>], view: View) -> Vec<u8> {
    let mut canvas = Pixmap::new(W, H).expect("frame size");
    let mut gif = GifWriter::new(W, H, 25.0, jacobs_ladder::render::Palette.gif()).expect("gif");
    for (k, q) in states.iter().enumerate() {
        frame(ladder, q, view, k, &mut canvas);
        gif.push_frame(&canvas).expect("push");
    }
    gif.finish().expect("finish")
}

fn bench(c: &mut Criterion) {
    let ladder = Ladder::new(Params::paper(60.0).expect("params"));
    let states = sweep_states(&ladder);
    let view = View::fit(&[&ladder.ground_state()]);
    let bytes = movie_bytes(&ladder, &states, view);
    println!(
        "200-frame 640x480 kink-sweep GIF: {} bytes ({:.1} KiB)",
        bytes.len(),
        bytes.len() as f64 / 1024.0
    );

    let mut canvas = Pixmap::new(W, H).expect("frame size");
    c.bench_function("snapshot 640x480 (10 blocks)", |b| {
        let mut k = 0;
        b.iter(|| {
            frame(&ladder, &states[k % FRAMES], view, k, &mut canvas);
            k += 1;
            black_box(&canvas);
        })
    });
    c.bench_function("snapshot + GIF frame 640x480", |b| {
        let mut gif =
            GifWriter::new(W, H, 25.0, jacobs_ladder::render::Palette.gif()).expect("gif");
        let mut k = 0;
        b.iter(|| {
            frame(&ladder, &states[k % FRAMES], view, k, &mut canvas);
            gif.push_frame(&canvas).expect("push");
            k += 1;
        })
    });
}

criterion_group! {
    name = benches;
    // No HTML plots: criterion's plotters backend finds no system font here.
    config = Criterion::default().without_plots();
    targets = bench
}
criterion_main!(benches);
