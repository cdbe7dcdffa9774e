//! The toy as built in the scenes' pictures (docs/experiments.md, "The
//! toy as built"): the ladder a movie or filmstrip draws carries the
//! blocks' thickness and the ribbons (`render::blocks` draws them), and
//! each impact of the run (`sim::impacts`) is marked on the frames that
//! follow it.

use crate::error::Result;
use crate::model::Ladder;
use crate::scene::Scene;
use crate::sim::impacts::Impact;

/// How many frame intervals an impact stays marked: the frame at or
/// after it and the next two (a brief mark, long enough to be seen at 25
/// frames/s).
pub const IMPACT_FRAMES: f64 = 3.0;

/// The ladder `scene`'s pictures draw: the paper's model, or, for an
/// apparatus built with ribbons, the ladder its run simulates (blocks
/// with thickness and ribbons, `Ladder::built`).
pub fn drawn_ladder(scene: &Scene) -> Result<Ladder> {
    let mut ladder = Ladder::new(scene.model.params()?);
    if scene.apparatus.is_some() {
        ladder.built = scene.scenario()?.ladder.built;
    }
    Ok(ladder)
}

/// For each frame time, the pairs of blocks (zero-based) whose impact it
/// marks: those with an impact in (t − [`IMPACT_FRAMES`] Δ, t], Δ the
/// interval between frames. Empty lists without impacts.
pub fn impacts_by_frame(impacts: Option<&[Impact]>, times: &[f64]) -> Vec<Vec<[usize; 2]>> {
    let Some(impacts) = impacts else {
        return vec![Vec::new(); times.len()];
    };
    let dt = match times {
        [a, b, ..] => b - a,
        _ => f64::INFINITY,
    };
    times
        .iter()
        .map(|&t| {
            let mut pairs: Vec<[usize; 2]> = impacts
                .iter()
                .filter(|i| i.t <= t && i.t > t - IMPACT_FRAMES * dt)
                .map(|i| [i.blocks[0] - 1, i.blocks[1] - 1])
                .collect();
            pairs.sort_unstable();
            pairs.dedup();
            pairs
        })
        .collect()
}

/// The impacts as marks of a kymograph (`render::Kymograph::marks`): an
/// impact between blocks n and m at (n + m)/2 across, at its time.
pub fn kymograph_marks(impacts: Option<&[Impact]>) -> Vec<(f64, f64)> {
    impacts
        .unwrap_or(&[])
        .iter()
        .map(|i| (0.5 * (i.blocks[0] + i.blocks[1]) as f64, i.t))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_impact_is_marked_on_the_frame_after_it_and_the_next_two() {
        let times: Vec<f64> = (0..10).map(|k| k as f64).collect();
        let hit = Impact {
            t: 3.5,
            blocks: [2, 3],
            speed: 0.1,
        };
        let shown = impacts_by_frame(Some(&[hit, hit]), &times);
        let frames: Vec<usize> = (0..10).filter(|&k| !shown[k].is_empty()).collect();
        assert_eq!(frames, vec![4, 5, 6]);
        assert_eq!(shown[4], vec![[1, 2]]);
        assert!(impacts_by_frame(None, &times).iter().all(|f| f.is_empty()));
    }
}
