//! No allocation inside the step loop: a run twice as long makes at most a
//! few hundred more allocations (the wave tracker allocates per event, a
//! launched wave or a sign change of block N, never per step), against the
//! tens of thousands of extra steps it takes (counted by a global allocator in this test binary,
//! on the thread that runs the simulation only: the test harness's own
//! thread may allocate at any time).
//!
//! Memory at each documented bound (docs/limits.md, "Data files and
//! memory"): the peak of live heap bytes, on every thread, while a scene
//! is rendered and its data file streamed to disk, against the formula the
//! docs state, at two sizes (the formula's scaling), and the data file's
//! size against its estimate. The tests of this binary take one lock, so
//! that no other test allocates while a peak is measured.

use jacobs_ladder::error::Error;
use jacobs_ladder::limits::Resource;
use jacobs_ladder::model::Params;
use jacobs_ladder::scene::{self, Scene};
use jacobs_ladder::scenes::{self, MovieOptions, Outputs};
use jacobs_ladder::sim::{self, IntegratorConfig, IntegratorKind, Scenario, Stepping};
use std::io::Write as _;

#[path = "common/heap.rs"]
mod heap;

#[global_allocator]
static GLOBAL: heap::Counting = heap::Counting;

/// Allocations made by one run of the kink scene of `n` blocks to `t_end`.
fn allocations(n: usize, t_end: f64, config: &IntegratorConfig, stepping: Stepping) -> u64 {
    let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
    let scenario = Scenario::single_flip(params, 1000.0, t_end).unwrap();
    heap::count_this_thread(true);
    let before = heap::allocations();
    let traj = sim::run(
        &scenario,
        &[],
        config,
        &sim::RunOptions::default().stepping(stepping),
    )
    .unwrap();
    let after = heap::allocations();
    assert!(traj.steps > 0);
    after - before
}

/// Allocations a longer run may add for events (a wave launched, a sign
/// change of block N recorded), not steps: the longer runs below take at
/// least 8 × 10⁴ more steps, so one allocation per step (or per hundred)
/// exceeds this by far.
const EVENTS: u64 = 400;

/// The window of the shorter run of `config` (the longer run's is twice
/// it): 8000 τ, or 2000 τ and 400 τ for the small steps of the paper's
/// scheme (0.01 τ) and explicit Euler (0.002 τ), whose longer runs still
/// take 2 × 10⁵ more steps (8000 τ took 4 × 10⁶ of them, for nothing the
/// count needs).
fn short_window(config: &IntegratorConfig) -> f64 {
    match config.kind {
        IntegratorKind::ExplicitEuler => 400.0,
        IntegratorKind::SymplecticEuler => 2000.0,
        _ => 8000.0,
    }
}

#[test]
fn step_loop_does_not_allocate() {
    let _one = heap::lock();
    let configs = [
        IntegratorConfig::paper(),
        IntegratorConfig::fixed(IntegratorKind::ExplicitEuler, 0.002),
        IntegratorConfig::fixed(IntegratorKind::Verlet, 0.1),
        IntegratorConfig::fixed(IntegratorKind::Rk4, 0.1),
        IntegratorConfig::adaptive(1e-6),
    ];
    for config in configs {
        for stepping in [Stepping::Fastest, Stepping::Portable] {
            let t = short_window(&config);
            let short = allocations(10, t, &config, stepping);
            let long = allocations(10, 2.0 * t, &config, stepping);
            assert!(
                long - short <= EVENTS,
                "{config:?}, {stepping:?}: {short} then {long}"
            );
        }
    }
    // The chain kernel (N > 32).
    let config = IntegratorConfig::paper();
    let t = short_window(&config);
    let short = allocations(40, t, &config, Stepping::Fastest);
    let long = allocations(40, 2.0 * t, &config, Stepping::Fastest);
    assert!(long - short <= EVENTS, "chain kernel: {short} then {long}");
}

/// The peak of live heap bytes, above what was live before, while `f` runs.
fn peak_of<R>(f: impl FnOnce() -> R) -> (R, u64) {
    let (r, peak, _) = heap::measure(f);
    (r, peak)
}

/// A scene of `n` blocks drawn as `output` (a TOML `[output]` table's
/// body), on a short window with a fixed step (the memory, not the
/// physics, is measured).
fn scene(n: usize, output: &str) -> Scene {
    let text = format!(
        "name = \"mem\"\n[model]\nn = {n}\n[[drive.flips]]\nstart = 0.0\nduration = 20.0\n\
         [run]\nt_end = 40.0\nintegrator = \"verlet\"\ndt = 0.05\n[output]\n{output}\n"
    );
    scene::file::parse(&text, "alloc.rs", "mem").unwrap()
}

/// Renders `scene` as the command line does: each file streamed into a
/// file of `dir` as it is drawn. Returns the data file's size and the
/// peak heap bytes.
fn render_peak(scene: &Scene, movie: &MovieOptions, dir: &std::path::Path) -> (u64, u64) {
    let outputs = Outputs::default();
    let (data_bytes, peak) = peak_of(|| {
        let mut data_bytes = 0;
        scenes::render_to(scene, movie, &outputs, &|| {}, &mut |name, fill| {
            let path = dir.join(name);
            let mut f = std::fs::File::create(&path).unwrap();
            fill(&mut f).unwrap();
            if name.ends_with(".json") {
                data_bytes = std::fs::metadata(&path).unwrap().len();
            }
            Ok(())
        })
        .unwrap();
        data_bytes
    });
    (data_bytes, peak)
}

/// docs/limits.md's bound on the memory of a simulated scene with its
/// data file: 0.4 kB per block, 48 bytes per block and kept sample (the
/// state and velocity of the trajectory), 8 bytes per block and sample
/// for the kymograph's colours, and a fixed 64 MB for the picture
/// (frames, fonts, encoders).
fn documented_bound(n: usize, samples: usize) -> f64 {
    let bs = (n * samples) as f64;
    400.0 * n as f64 + (48.0 + 8.0) * bs + 64e6
}

#[test]
fn memory_of_a_data_file_stays_within_the_documented_bound() {
    let _one = heap::lock();
    let dir = std::env::temp_dir().join(format!("ladder-alloc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let rows = 400; // a kymograph figure's rows (scenes::KYMOGRAPH_ROWS)
    let movie = MovieOptions {
        frames: 40,
        width: 160,
        height: 120,
        fps: 10.0,
    };
    let mut report = Vec::new();
    for (what, output, samples) in [
        ("kymograph", "kind = \"kymograph\"", rows),
        ("movie", "kind = \"movie\"", movie.frames),
    ] {
        let mut peaks = Vec::new();
        for n in [1500, 3000] {
            let s = scene(n, output);
            let (bytes, peak) = render_peak(&s, &movie, &dir);
            let bound = documented_bound(n, samples);
            let (estimate, _) = scenes::data::estimated_bytes(&s, &movie, rows);
            report.push(format!(
                "{what} N = {n}: peak {:.1} MB (bound {:.1} MB), data file {:.1} MB (estimate {:.1} MB)",
                peak as f64 / 1e6,
                bound / 1e6,
                bytes as f64 / 1e6,
                estimate / 1e6
            ));
            assert!(
                (peak as f64) <= bound,
                "{what}, N = {n}: peak {peak} bytes past the documented {bound}"
            );
            // The estimate is an upper bound, and not a loose one.
            assert!(
                bytes as f64 <= estimate && bytes as f64 >= 0.3 * estimate,
                "{what}, N = {n}: data file {bytes} bytes against the estimate {estimate}"
            );
            // Were the data file held in memory, the peak would exceed it.
            assert!(
                peak < bytes + 48 * (n * samples) as u64,
                "{what}: {peak} vs {bytes}"
            );
            peaks.push(peak as f64);
        }
        // The formula's scaling: twice the blocks, at most twice the bytes
        // beyond the fixed part (with 20 % slack for allocator rounding).
        let grown = peaks[1] / peaks[0];
        assert!(grown <= 2.2, "{what}: peak grew {grown}× for 2× N");
    }
    let _ = std::fs::remove_dir_all(&dir);
    for line in report {
        let mut err = std::io::stderr().lock();
        let _ = writeln!(err, "{line}");
    }
}

#[test]
fn a_data_file_past_its_cap_is_refused_before_any_work() {
    let _one = heap::lock();
    let s = scene(100_000, "kind = \"kymograph\"");
    let movie = MovieOptions::default();
    let (estimate, bs) = scenes::data::estimated_bytes(&s, &movie, 400);
    // 400 rows × 100,000 blocks × 4 numbers × 40 bytes: 6.4 GB.
    assert_eq!(bs, 4e7);
    assert!(estimate > 6.4e9 && estimate < 6.5e9, "{estimate}");
    let (result, peak) =
        peak_of(|| scenes::render_to(&s, &movie, &Outputs::default(), &|| {}, &mut |_, _| Ok(())));
    match result {
        Err(Error::Limit(l)) => {
            assert_eq!(l.resource, Resource::DataBytes);
            assert!(l.to_string().contains("bytes"), "{l}");
        }
        other => panic!("expected the data-file cap, got {other:?}"),
    }
    assert!(peak < 10_000_000, "refused before any work: {peak} bytes");
}
