//! Rendering scenes into a folder, as `ladder figure|movie|render|all`
//! and Python's `Scene.save` both do: every target checked before any
//! work, each file written atomically as soon as it is drawn (the data
//! file streamed into place), the scenes in parallel, the gallery page
//! last.

use crate::error::{Error, Result};
use crate::front::timings::{self, Timing, Timings};
use crate::output;
use crate::scene::{self, Kind, Scene};
use crate::scenes::{self, MovieOptions, Outputs};
use crate::sim::tally;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What a front end is told while a folder is rendered.
pub struct Progress<'a> {
    /// After each frame of a movie.
    pub frame: &'a (dyn Fn() + Sync),
    /// After each scene, its files written.
    pub scene: &'a (dyn Fn(&Scene) + Sync),
    /// Before each file is written and again before it is put in place: a
    /// front end that was stopped (Python's Ctrl-C) unwinds here, so
    /// nothing is written after it, and the file being written is removed
    /// as the work unwinds.
    pub file: &'a (dyn Fn() + Sync),
    /// A failed scene's error, worded for the front end (a divergence's
    /// hint names flags or scene-file keys).
    pub hint: &'a (dyn Fn(Error, &Scene) -> Error + Sync),
}

impl Progress<'_> {
    /// Nothing shown; errors as they are.
    pub fn quiet() -> Progress<'static> {
        Progress {
            frame: &|| {},
            scene: &|_| {},
            file: &|| {},
            hint: &|e, _| e,
        }
    }
}

/// Renders `scenes` into the folder `out`, in parallel (rayon), each file
/// written atomically as soon as it is ready; with `index`, a PNG of every
/// figure and `out/index.html` (the gallery) too. Every target, every
/// scene's checks and costs come before any rendering. Returns the names
/// of the files written, in order, the gallery page last.
pub fn into_folder(
    scenes: &[Scene],
    out: &Path,
    movie: &MovieOptions,
    outputs: &Outputs,
    index: bool,
    progress: &Progress<'_>,
) -> Result<Vec<String>> {
    into_folder_timed(scenes, out, movie, outputs, index, progress).map(|(files, _)| files)
}

/// [`into_folder`], and where its time went: each output's wall time and
/// the runs and block-steps it simulated, the process's CPU time
/// (`front::timings` says exactly what is measured).
pub fn into_folder_timed(
    scenes: &[Scene],
    out: &Path,
    movie: &MovieOptions,
    outputs: &Outputs,
    index: bool,
    progress: &Progress<'_>,
) -> Result<(Vec<String>, Timings)> {
    let start = timings::Start::now();
    // The gallery shows a PNG of every figure: one is made if none is asked.
    let outputs = &Outputs {
        preview: index,
        ..outputs.clone()
    };
    check_out_dir(out)?;
    // Every target, index.html included, before anything is rendered.
    let names: Vec<String> = scenes.iter().map(|s| format!("scene {}", s.name)).collect();
    check_distinct_outputs(scenes, &names, out, outputs)?;
    let mut targets: Vec<PathBuf> = scenes
        .iter()
        .flat_map(|s| scenes::file_names_for(s, outputs))
        .map(|name| out.join(name))
        .collect();
    if index {
        targets.push(out.join("index.html"));
    }
    output::check_targets(&targets)?;
    // Every scene's checks and costs before any is rendered.
    for s in scenes {
        scenes::check(s, movie, outputs).map_err(|e| (progress.hint)(e, s))?;
    }
    warn_replaced(scenes, out)?;
    // The runs two outputs make alike, made once before any output starts
    // (`scenes::shared`), each charged to the first output that makes it.
    let tallies: Vec<Arc<tally::Tally>> = scenes.iter().map(|_| Arc::default()).collect();
    let shared = scenes::shared::prepare(scenes, movie, &tallies)?;
    let mut written: Vec<Rendered> = in_order(&jobs(scenes, movie), |job| {
        render_job(scenes, job, &tallies, out, movie, outputs, progress)
    })?
    .into_iter()
    .flatten()
    .collect();
    drop(shared);
    written.sort_by_key(|w| w.0);
    let written: Vec<(Vec<String>, Timing)> = written.into_iter().map(|w| w.1).collect();
    let (written, timed): (Vec<Vec<String>>, Vec<Timing>) = written.into_iter().unzip();
    let mut files: Vec<String> = written.iter().flatten().cloned().collect();
    if index {
        let items: Vec<crate::gallery::Item<'_>> = scenes
            .iter()
            .zip(&written)
            .map(|(scene, files)| crate::gallery::Item {
                scene,
                files: files.clone(),
            })
            .collect();
        let page = crate::gallery::index_html(&items)?;
        output::write_atomic(&out.join("index.html"), page.as_bytes())?;
        files.push("index.html".into());
    }
    Ok((files, start.finish(timed)))
}

/// The order in which the lone scenes start, the most work first: a ring
/// chain's (each several times any other output's work:
/// docs/performance.md), then the others by the work they may take
/// (`scenes::cost::expected_work`), ties in the order given. Started
/// last, a long output would end the render alone on one core.
fn longest_first(scenes: &[Scene], movie: &MovieOptions) -> Vec<usize> {
    let work: Vec<f64> = scenes
        .iter()
        .map(|s| match s.rings {
            Some(_) => f64::INFINITY,
            None => scenes::cost::expected_work(s, movie),
        })
        .collect();
    let mut order: Vec<usize> = (0..scenes.len()).collect();
    order.sort_by(|&a, &b| work[b].total_cmp(&work[a]));
    order
}

/// A scene rendered: its index, its files and its timing.
type Rendered = (usize, (Vec<String>, Timing));

/// The scenes in jobs, in the order they start ([`longest_first`]): each
/// group of ring scenes that share one run (`scenes::shared::ring_groups`:
/// figure 4b and movie 12) one job, its latest end first, then every
/// other scene a job of its own.
fn jobs(scenes: &[Scene], movie: &MovieOptions) -> Vec<Vec<usize>> {
    let mut jobs = scenes::shared::ring_groups(scenes);
    let grouped: Vec<usize> = jobs.iter().flatten().copied().collect();
    let lone = longest_first(scenes, movie)
        .into_iter()
        .filter(|i| !grouped.contains(i))
        .map(|i| vec![i]);
    jobs.extend(lone);
    jobs
}

/// Runs `work` on every job of `jobs` strictly in their order: each core
/// takes the next job as it finishes one (a parallel iterator would cut
/// the list in halves, one a core, and the last job of a half could start
/// last whatever its size). A job's own parallel runs go to whichever
/// core is free. After a job fails no other starts; the first failure
/// found is returned.
fn in_order<T: Send>(
    jobs: &[Vec<usize>],
    work: impl Fn(&[usize]) -> Result<T> + Sync,
) -> Result<Vec<T>> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
    let (next, failed) = (AtomicUsize::new(0), AtomicBool::new(false));
    let workers = rayon::current_num_threads().clamp(1, jobs.len().max(1));
    let done: Vec<Result<Vec<T>>> = (0..workers)
        .into_par_iter()
        .map(|_| {
            let mut out = Vec::new();
            while !failed.load(Ordering::Relaxed) {
                let Some(job) = jobs.get(next.fetch_add(1, Ordering::Relaxed)) else {
                    break;
                };
                let done = work(job);
                failed.fetch_or(done.is_err(), Ordering::Relaxed);
                out.push(done?);
            }
            Ok(out)
        })
        .collect();
    Ok(done
        .into_iter()
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .flatten()
        .collect())
}

/// Renders the scenes of one job in turn, each timed ([`timed`]). A group
/// of ring scenes makes its one run in its first scene's time, charged to
/// it (`scenes::shared::make_ring_runs`), and holds it until the last is
/// rendered: no output waits for another's run, and the run needs no
/// other task (it makes none), so made in the first output's task it
/// cannot wait for itself.
fn render_job(
    scenes: &[Scene],
    job: &[usize],
    tallies: &[Arc<tally::Tally>],
    out: &Path,
    movie: &MovieOptions,
    outputs: &Outputs,
    progress: &Progress<'_>,
) -> Result<Vec<Rendered>> {
    let mut held = None;
    let mut done = Vec::with_capacity(job.len());
    for (n, &i) in job.iter().enumerate() {
        let s = &scenes[i];
        let render = || {
            if n == 0 && job.len() > 1 {
                let group: Vec<&Scene> = job.iter().map(|&j| &scenes[j]).collect();
                held = Some(scenes::shared::make_ring_runs(&group, movie, &tallies[i]));
            }
            render_scene(s, out, movie, outputs, progress)
        };
        done.push((i, timed(s, &tallies[i], render)?));
    }
    drop(held);
    Ok(done)
}

/// `render` of `scene` timed: its wall time, and the CPU time and runs
/// of its tasks counted on whichever thread they ran in its `tally`
/// (`sim::tally`), with the runs made for it before it started
/// (`scenes::shared`).
fn timed<T>(
    scene: &Scene,
    tally: &Arc<tally::Tally>,
    render: impl FnOnce() -> Result<T>,
) -> Result<(T, Timing)> {
    let at = std::time::Instant::now();
    let done = tally::within(Some(tally.clone()), render)?;
    let timing = Timing {
        kind: scene.kind(),
        name: scene.name.clone(),
        wall_s: at.elapsed().as_secs_f64(),
        cpu_s: tally.cpu_s(),
        runs: tally.runs(),
        block_steps: tally.block_steps(),
        reused: tally.reused(),
    };
    Ok((done, timing))
}

/// Renders one scene into `out`: each file streamed into its temporary
/// file as it is drawn; the scene's files put in place together once all
/// are complete, its data file first (`output::group`). Returns their
/// names.
fn render_scene(
    s: &Scene,
    out: &Path,
    movie: &MovieOptions,
    outputs: &Outputs,
    progress: &Progress<'_>,
) -> Result<Vec<String>> {
    let mut files: Vec<String> = Vec::new();
    let mut group = output::group::Group::new();
    let rendered = scenes::render_to(s, movie, outputs, progress.frame, &mut |name, fill| {
        (progress.file)();
        group.write_with(&out.join(name), |f| {
            fill(f)?;
            (progress.file)();
            Ok(())
        })?;
        files.push(name.to_string());
        Ok(())
    });
    rendered
        .and_then(|()| group.commit())
        .map_err(|e| (progress.hint)(e, s))?;
    (progress.scene)(s);
    Ok(files)
}

/// Refuses two scenes of one command that would write one file (the same
/// scene file twice, or two files with one `name`); `sources` say where
/// each scene comes from.
pub fn check_distinct_outputs(
    scenes: &[Scene],
    sources: &[String],
    out: &Path,
    outputs: &Outputs,
) -> Result<()> {
    let targets: Vec<(PathBuf, String)> = scenes
        .iter()
        .zip(sources)
        .flat_map(|(s, src)| {
            scenes::file_names_for(s, outputs)
                .into_iter()
                .map(move |name| (out.join(name), src.clone()))
        })
        .collect();
    output::check_distinct(&targets, "give each scene its own name")
}

/// File extensions that make `--out` look like a file name.
const FILE_EXTENSIONS: [&str; 8] = ["png", "svg", "pdf", "gif", "mp4", "json", "html", "toml"];

/// `--out` names a folder: refuse an existing file, and a path that does
/// not exist yet but ends like a file name (`--out x.svg`).
pub fn check_out_dir(out: &Path) -> Result<()> {
    let shown = out.display();
    if out.exists() && !out.is_dir() {
        return Err(Error::bad_input(format!(
            "--out is a folder, and {shown} is a file; give a folder (the files are named after the scene, e.g. figure-3.png)"
        )));
    }
    let ext = out
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if let Some(ext) = ext.filter(|e| FILE_EXTENSIONS.contains(&e.as_str()))
        && !out.exists()
    {
        return Err(Error::bad_input(format!(
            "--out is a folder, not a file name: got {shown}; use --out DIR (the files are \
             named after the scene) and --format {ext}"
        )));
    }
    Ok(())
}

/// Says so, one line a scene, where a scene's files replace those of a
/// different scene: its data file in `out` (`<stem>.json`) records the
/// scene that made them. The same scene again replaces them silently.
pub fn warn_replaced(scenes: &[Scene], out: &Path) -> Result<()> {
    for s in scenes {
        let data = out.join(format!("{}.json", s.stem()));
        let Ok(text) = std::fs::read_to_string(&data) else {
            continue;
        };
        let old = serde_json::from_str::<serde_json::Value>(&text)
            .ok()
            .and_then(|mut v| v.get_mut("scene").map(serde_json::Value::take));
        let new = serde_json::to_value(s).ok();
        if old.is_some() && old.as_ref().map(without_words) == new.as_ref().map(without_words) {
            continue;
        }
        let what = match old.and_then(|v| serde_json::from_value::<Scene>(v).ok()) {
            Some(o) => format!(" ({})", scene::describe::parameters(&o)),
            None => String::new(),
        };
        output::eprint(&format!(
            "ladder: warning: replacing the files of {}, which {} says were made from a \
             different scene{what}; give --name (or the scene's name) to keep both\n",
            s.stem(),
            data.display()
        ))?;
    }
    Ok(())
}

/// A recorded scene without its words (label, title, caption): a scene
/// whose caption was edited is still the same scene.
fn without_words(scene: &serde_json::Value) -> serde_json::Value {
    let mut v = scene.clone();
    if let Some(map) = v.as_object_mut() {
        for key in ["label", "title", "caption"] {
            map.remove(key);
        }
    }
    v
}

/// "1 file", "3 files".
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// What a render wrote, in words: the files by name for one scene
/// ("wrote figure-3.png and figure-3.json (figure 3)"), else the count of
/// each kind ("wrote 13 figures and 9 movies, each with its data file, and
/// index.html (54 files)").
pub fn summary(scenes: &[Scene], files: &[String], index: bool) -> String {
    let and_list = |items: &[String]| match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    };
    if let [one] = scenes {
        return format!(
            "wrote {} ({} {})",
            and_list(files),
            one.kind().name(),
            one.name
        );
    }
    let mut parts = Vec::new();
    for (kind, one, many) in [
        (Kind::Figure, "figure", "figures"),
        (Kind::Movie, "movie", "movies"),
        (Kind::Data, "data run", "data runs"),
    ] {
        let n = scenes.iter().filter(|s| s.kind() == kind).count();
        if n > 0 {
            parts.push(count(n, one, many));
        }
    }
    let page = if index { ", and index.html" } else { "" };
    format!(
        "wrote {}, each with its data file{page} ({})",
        and_list(&parts),
        count(files.len(), "file", "files")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_must_be_a_folder() {
        assert!(check_out_dir(Path::new("some/new/dir")).is_ok());
        let e = check_out_dir(Path::new("x.svg")).unwrap_err().to_string();
        assert!(e.starts_with("--out is a folder"), "{e}");
        assert!(e.contains("--format svg"), "{e}");
        let e = check_out_dir(Path::new("Cargo.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("is a file"), "{e}");
    }

    #[test]
    fn the_summary_names_what_was_written() {
        let fig = crate::catalog::find(Kind::Figure, "3")
            .unwrap()
            .scene
            .clone();
        let movie = crate::catalog::find(Kind::Movie, "4")
            .unwrap()
            .scene
            .clone();
        let names = |s: &Scene| scenes::file_names(s);
        assert_eq!(
            summary(std::slice::from_ref(&fig), &names(&fig), false),
            "wrote figure-3.png and figure-3.json (figure 3)"
        );
        assert_eq!(
            summary(std::slice::from_ref(&movie), &names(&movie), false),
            "wrote movie-4.gif, movie-4-kymograph.png and movie-4.json (movie 4)"
        );
        let both = [fig.clone(), movie.clone()];
        let mut files = [names(&fig), names(&movie)].concat();
        files.push("index.html".into());
        assert_eq!(
            summary(&both, &files, true),
            "wrote 1 figure and 1 movie, each with its data file, and index.html (6 files)"
        );
        assert_eq!(count(1, "file", "files"), "1 file");
        assert_eq!(count(0, "file", "files"), "0 files");
    }
}
