//! A render makes once the runs two of its outputs make alike
//! (`scenes::shared`): movies 3 and 4 (one scene, two cameras) and the
//! tank's positions at 0.2 Hz and its level 3. Every file is the same,
//! byte for byte, as each output rendered alone, and the timings say who
//! made the run and who took it (decided from the outputs' own runs,
//! never from a clock).

use crate::common::tempdir::TempDir;
use jacobs_ladder::catalog;
use jacobs_ladder::front::render::{Progress, into_folder_timed};
use jacobs_ladder::front::timings::{Timing, Timings};
use jacobs_ladder::scene::{Kind, Scene};
use jacobs_ladder::scenes::{MovieOptions, Outputs};
use std::collections::BTreeMap;
use std::path::Path;

fn scene(kind: Kind, id: &str) -> Scene {
    catalog::find(kind, id).unwrap().scene.clone()
}

/// Renders `scenes` together into `dir`; every file's bytes by name, and
/// the timings.
fn render(scenes: &[Scene], dir: &Path) -> (BTreeMap<String, Vec<u8>>, Timings) {
    let movie = MovieOptions {
        frames: 12,
        width: 160,
        height: 120,
        ..MovieOptions::default()
    };
    let (files, timings) = into_folder_timed(
        scenes,
        dir,
        &movie,
        &Outputs::default(),
        false,
        &Progress::quiet(),
    )
    .unwrap();
    let bytes = files
        .into_iter()
        .map(|f| {
            let b = std::fs::read(dir.join(&f)).unwrap();
            (f, b)
        })
        .collect();
    (bytes, timings)
}

fn row<'a>(t: &'a Timings, name: &str) -> &'a Timing {
    t.outputs.iter().find(|o| o.name == name).unwrap()
}

#[test]
fn runs_two_outputs_make_alike_are_made_once_and_change_no_byte() {
    let together = [
        scene(Kind::Movie, "3"),
        scene(Kind::Movie, "4"),
        scene(Kind::Figure, "tank-positions"),
        scene(Kind::Figure, "tank-levels"),
    ];
    let dir = TempDir::new("shared-runs");
    let (files, timings) = render(&together, &dir.join("together"));
    let mut alone = BTreeMap::new();
    let mut alone_rows = Vec::new();
    for (k, s) in together.iter().enumerate() {
        let (f, t) = render(std::slice::from_ref(s), &dir.join(format!("alone-{k}")));
        alone.extend(f);
        alone_rows.push(t.outputs[0].clone());
    }
    assert_eq!(files.len(), alone.len());
    for (name, b) in &alone {
        assert!(files[name] == *b, "{name} differs from its render alone");
    }
    // Alone, each makes its own runs and takes none.
    for r in &alone_rows {
        assert!(r.runs > 0 && r.reused == 0, "{r:?}");
    }
    let (m3, m4) = (row(&timings, "3"), row(&timings, "4"));
    let (pos, lev) = (
        row(&timings, "tank-positions"),
        row(&timings, "tank-levels"),
    );
    // Movie 4's run (an automatic step: its pair) made once, for movie 3.
    assert_eq!((m3.runs, m3.reused), (alone_rows[0].runs, 0));
    assert_eq!(
        (m4.runs, m4.block_steps, m4.reused),
        (0, 0, alone_rows[1].runs)
    );
    // Of the levels' 21 runs, its level 3's kink and antikink are the
    // positions' runs at 0.2 Hz: made for the positions (6 runs), taken.
    assert_eq!((pos.runs, pos.reused), (6, 0));
    assert_eq!((lev.runs, lev.reused), (19, 2));
    assert_eq!(alone_rows[3].runs, 21);
    // Every run an output makes alone is made once together: by it, or
    // by another output that it takes the run from. (Summed over the
    // outputs' own tallies: the process's total also counts the runs of
    // tests running beside this one in this binary.)
    let made_or_taken: u64 = timings.outputs.iter().map(|o| o.runs + o.reused).sum();
    let alone_made: u64 = alone_rows.iter().map(|r| r.runs).sum();
    assert_eq!(made_or_taken, alone_made, "every run made once");
}
