//! `ladder figure`, `movie`, `render`, `all` and `scene`: which scenes a
//! command names, and their files rendered into a folder.

use crate::catalog::{self, Entry};
use crate::cli::commands::Call;
use crate::cli::hints::{Words, with_divergence_hint};
use crate::cli::progress::progress_bar;
use crate::cli::*;
use crate::error::{Error, Result};
use crate::front;
use crate::output;
use crate::scene::{self, Kind, Scene};
use crate::scenes::{MovieOptions, Outputs};
use std::time::Instant;

/// `e` from the scene of `file`, the file named before its message (an
/// error of bad input; the others are the run's own).
pub(crate) fn in_file(file: &std::path::Path, e: Error) -> Error {
    match e {
        Error::BadInput(m) => Error::bad_input(format!("{}: {m}", file.display())),
        e => e,
    }
}

/// The catalogue entry `ladder scene` names: `ID` (a figure first, then a
/// movie), `KIND ID` or `KIND-ID` (KIND `figure` or `movie`).
pub(crate) fn scene_entry(words: &[String]) -> Result<&'static Entry> {
    let kind_of = |word: &str| match word.to_ascii_lowercase().as_str() {
        "figure" | "fig" => Some(Kind::Figure),
        "movie" => Some(Kind::Movie),
        _ => None,
    };
    match words {
        [kind, id] => match kind_of(kind) {
            Some(k) => catalog::find(k, id),
            None => Err(Error::bad_input(format!(
                "'{}' is not a kind of scene: say `figure {id}` or `movie {id}`",
                kind.escape_debug()
            ))),
        },
        [id] => match id
            .split_once('-')
            .and_then(|(k, rest)| Some((kind_of(k)?, rest)))
        {
            Some((k, rest)) => catalog::find(k, rest),
            None => catalog::find_any(id),
        },
        _ => Err(Error::bad_input(
            "ladder scene takes an ID, or a kind and an ID",
        )),
    }
}

/// The scenes of `ladder movie`: a built-in one, all of them, or a custom
/// one from the flags (on the paper's scene, or on the named one, whose
/// window and label it keeps). No ID and no flag: the catalogue and usage.
pub(crate) fn movie_scenes(args: &MovieArgs) -> Result<Vec<Scene>> {
    let flags = args.model.any() || args.drive.any() || args.run.any();
    let custom = flags || args.name.is_some() || args.camera.is_some();
    let make = |origin: crate::cli::custom::Origin<'_>| {
        crate::cli::custom::movie_scene(
            origin,
            args.name.as_deref(),
            args.camera,
            &args.model,
            &args.drive,
            &args.run,
        )
    };
    match args.id.as_deref() {
        Some("all") if custom => Err(Error::bad_input(
            "model, drive and run flags apply to one movie, not to all",
        )),
        Some("all") => Ok(builtin(Kind::Movie)?),
        Some(id) => {
            let entry = catalog::find(Kind::Movie, id)?;
            if !custom {
                return Ok(vec![entry.scene.clone()]);
            }
            Ok(vec![make(Some((&entry.id, &entry.scene)))?])
        }
        None if !custom => Err(what_to_make(Kind::Movie)?),
        None => Ok(vec![make(None)?]),
    }
}

/// The scenes of `ladder figure`, as [`movie_scenes`] for figures.
pub(crate) fn figure_scenes(args: &FigureArgs) -> Result<Vec<Scene>> {
    let flags = args.model.any() || args.drive.any() || args.run.any();
    let custom = flags || args.name.is_some() || args.view.is_some() || args.times.is_some();
    let make = |origin: crate::cli::custom::Origin<'_>| {
        crate::cli::custom::figure_scene(
            origin,
            args.name.as_deref(),
            args.view,
            args.times.as_deref(),
            (&args.model, &args.drive, &args.run),
        )
    };
    match args.id.as_deref() {
        Some("all") if custom => Err(Error::bad_input(
            "model, drive and run flags apply to one figure, not to all",
        )),
        Some("all") => builtin(Kind::Figure),
        Some(id) => {
            let entry = catalog::find(Kind::Figure, id)?;
            if !custom {
                return Ok(vec![entry.scene.clone()]);
            }
            Ok(vec![make(Some((&entry.id, &entry.scene)))?])
        }
        None if !custom => Err(what_to_make(Kind::Figure)?),
        None => Ok(vec![make(None)?]),
    }
}

/// `ladder figure` or `ladder movie` with neither an ID nor a flag: the
/// entries of that kind and the ways to call it (exit 2).
pub(crate) fn what_to_make(kind: Kind) -> Result<Error> {
    let name = kind.name();
    let mut text = format!(
        "{name} needs an ID, all, or model flags for your own {name}. The built-in {name}s:\n"
    );
    for e in catalog::entries(kind)? {
        text.push_str(&format!(
            "  {:<14} {}\n",
            e.id,
            scene::describe::title(&e.scene)
        ));
    }
    let own = match kind {
        Kind::Movie => "ladder movie --alpha 70 --n 20      your own movie (see --help)",
        _ => "ladder figure --alpha 70 --times 0,900,1100   your own filmstrip (see --help)",
    };
    text.push_str(&format!(
        "Usage:\n  ladder {name} ID       one of the above\n  ladder {name} all      every one\n  {own}"
    ));
    Ok(Error::bad_input(text))
}

pub(crate) fn builtin(kind: Kind) -> Result<Vec<Scene>> {
    Ok(catalog::entries(kind)?
        .into_iter()
        .map(|e: &Entry| e.scene.clone())
        .collect())
}

/// Renders `scenes` into `out` ([`front::render::into_folder`]) with a
/// progress bar, then says what it wrote.
pub(crate) fn render_into(
    scenes: &[Scene],
    out: &OutArgs,
    movie: &MovieOptions,
    outputs: &Outputs,
    words: Words,
    index: bool,
) -> Result<()> {
    render_into_timed(scenes, out, movie, outputs, words, index, false)
}

/// [`render_into`], and with `timings` the table of where the time went
/// ([`front::timings`]) on standard output after the summary.
pub(crate) fn render_into_timed(
    scenes: &[Scene],
    out: &OutArgs,
    movie: &MovieOptions,
    outputs: &Outputs,
    words: Words,
    index: bool,
    timings: bool,
) -> Result<()> {
    let (out, verbose) = (out.out.as_path(), out.verbose);
    let start = Instant::now();
    // One movie: a bar over its frames; several scenes: over the scenes.
    let one_movie = scenes.len() == 1 && scenes[0].kind() == Kind::Movie;
    let bar = if one_movie {
        progress_bar(movie.frames as u64, &format!("movie {}", scenes[0].name))
    } else {
        progress_bar(scenes.len() as u64, "rendering")
    };
    let progress = front::render::Progress {
        frame: &|| {
            if one_movie {
                bar.inc(1);
            }
        },
        scene: &|s| {
            if !one_movie {
                bar.set_message(format!("{} {}", s.kind().name(), s.name));
                bar.inc(1);
            }
        },
        file: &|| {},
        hint: &|e, s| with_divergence_hint(e, s, words),
    };
    let files = front::render::into_folder_timed(scenes, out, movie, outputs, index, &progress);
    bar.finish_and_clear();
    let (files, table) = files?;
    if verbose {
        let list: String = files
            .iter()
            .map(|f| format!("{}\n", out.join(f).display()))
            .collect();
        output::eprint(&list)?;
    }
    output::eprint(&format!(
        "ladder: {} into {} in {:.2} s\n",
        front::render::summary(scenes, &files, index),
        out.display(),
        start.elapsed().as_secs_f64()
    ))?;
    if timings {
        output::print(&table.table())?;
    }
    Ok(())
}

/// `ladder figure`: a built-in figure, all of them, or a filmstrip (or
/// kymograph, arrival chart) of the user's own ladder.
pub(crate) fn figure(args: &FigureArgs, call: &Call<'_>) -> Result<()> {
    let outputs = recorded(args.figure_format.outputs()?, call.command_line);
    let scenes = call.capped(figure_scenes(args)?);
    let movie = MovieOptions::default();
    render_into(&scenes, &args.out, &movie, &outputs, Words::Flags, false)
}

/// `ladder movie`: a built-in movie, all of them, or the user's own.
pub(crate) fn movie(args: &MovieArgs, call: &Call<'_>) -> Result<()> {
    let opts = args.format.options()?;
    let outputs = recorded(
        Outputs {
            mp4_quality: args.format.mp4_quality(),
            ..front::options::movie_outputs(&args.formats, &opts, args.scale)?
        },
        call.command_line,
    );
    let scenes = call.capped(movie_scenes(args)?);
    if let Some(line) = front::options::movie_formats_line(&args.formats, &outputs) {
        output::eprint(&format!("ladder: {line}\n"))?;
    }
    render_into(&scenes, &args.out, &opts, &outputs, Words::Flags, false)
}

/// `ladder render FILE...`: scene files, or with `--check` only the checks
/// rendering makes before its work.
pub(crate) fn render(args: &RenderArgs, call: &Call<'_>) -> Result<()> {
    let (opts, outputs) = mixed(&args.format, &args.formats, call.command_line)?;
    let scenes = call.capped(
        args.files
            .iter()
            .map(|f| scene::file::load(f))
            .collect::<Result<Vec<_>>>()?,
    );
    args.formats.check_covers(&scenes)?;
    let sources: Vec<String> = args.files.iter().map(|f| f.display().to_string()).collect();
    front::render::check_distinct_outputs(&scenes, &sources, &args.out.out, &outputs)?;
    if !args.check {
        return render_into(&scenes, &args.out, &opts, &outputs, Words::Keys, false);
    }
    // The checks rendering makes before its work, in one place.
    for (file, s) in args.files.iter().zip(&scenes) {
        crate::scenes::check(s, &opts, &outputs).map_err(|e| in_file(file, e))?;
    }
    for (file, s) in args.files.iter().zip(&scenes) {
        // Every run it may make (an experiment figure's variants).
        let runs = crate::scenes::cost::planned_runs(s, opts.frames)
            .map_err(|e| in_file(file, e))?
            .len();
        output::print(&format!(
            "{}: {} {} ({} run{}): {}\n",
            file.display(),
            s.kind().name(),
            s.name,
            runs,
            if runs == 1 { "" } else { "s" },
            scene::describe::parameters(s)
        ))?;
    }
    Ok(())
}

/// `ladder all`: every built-in figure and movie, and the gallery page.
pub(crate) fn all(args: &AllArgs, call: &Call<'_>) -> Result<()> {
    let (opts, outputs) = mixed(&args.format, &args.formats, call.command_line)?;
    let scenes: Vec<Scene> = call.capped(
        catalog::catalogue()?
            .iter()
            .map(|e| e.scene.clone())
            .collect(),
    );
    render_into_timed(
        &scenes,
        &args.out,
        &opts,
        &outputs,
        Words::Flags,
        true,
        args.timings,
    )
}

/// The movie options and the outputs of `render` and `all`.
fn mixed(
    format: &MovieFormat,
    formats: &MixedFormat,
    command_line: &[String],
) -> Result<(MovieOptions, Outputs)> {
    let opts = format.options()?;
    let outputs = Outputs {
        mp4_quality: format.mp4_quality(),
        ..formats.outputs(&opts)?
    };
    Ok((opts, recorded(outputs, command_line)))
}

/// `outputs`, recording `command_line` (the program's arguments, word by
/// word) in the data files they write.
fn recorded(outputs: Outputs, command_line: &[String]) -> Outputs {
    Outputs {
        command_line: command_line.to_vec(),
        ..outputs
    }
}
