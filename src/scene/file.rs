//! Scene files: TOML in, TOML out (docs/scenes.md).
//!
//! A file is parsed in two passes: serde reads it into a [`Scene`]
//! (unknown keys and wrong types are caught here, with the position the
//! TOML parser gives), then [`Scene::check`] validates the values and
//! names the offending key, which is located in the source through
//! toml's spanned document. Every error is one line:
//! `FILE:LINE:COLUMN: KEY: what is wrong and what is allowed`.

use super::Scene;
use crate::error::{Error, Result};
use std::ops::Range;
use std::path::Path;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

mod words;

/// Largest scene file read, in bytes.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Parses a scene from TOML `text`; `origin` names it in messages (a
/// path, or `scene 4` for a built-in one). A scene without `name` is
/// called `default_name`.
pub fn parse(text: &str, origin: &str, default_name: &str) -> Result<Scene> {
    let doc =
        DeTable::parse(text).map_err(|e| located(text, origin, e.span(), None, e.message()))?;
    // `[output]` without `kind`: the kind its keys belong to (see
    // `inferred_kind`), written into the text read; spans map back.
    let (read, inserted) = with_inferred_kind(text, doc.get_ref());
    let back = |span: Range<usize>| match inserted {
        Some((at, len)) if span.start >= at + len => span.start - len..span.end - len,
        Some((at, _)) if span.start >= at => at..at,
        _ => span,
    };
    let mut scene: Scene = toml::from_str(&read).map_err(|e| {
        let span = e.span().map(back);
        let (span, key) = match unknown_key(doc.get_ref(), e.message()) {
            Some((path, at)) => (Some(at), Some(path)),
            None => {
                let key = span.clone().and_then(|s| {
                    key_at(doc.get_ref(), s.start)
                        .or_else(|| table_at(text, doc.get_ref(), s.start))
                });
                match key
                    .as_deref()
                    .and_then(|k| typed_key(text, doc.get_ref(), k, e.message()))
                {
                    Some((path, at)) => (Some(at), Some(path)),
                    None => (span, key),
                }
            }
        };
        let message = words::plain(e.message(), key.as_deref());
        located(text, origin, span, key.as_deref(), &message)
    })?;
    if !doc.get_ref().contains_key("name") {
        // Output files are named `KIND-NAME`: a file already named so
        // (`movie-4.toml`, as `assets/scenes/` are) keeps its name once.
        let prefix = format!("{}-", scene.kind().name());
        scene.name = match default_name.strip_prefix(&prefix) {
            Some(rest) if !rest.is_empty() => rest.to_string(),
            _ => default_name.to_string(),
        };
    }
    // A movie or figure that sets no window shows every wave's fate.
    let sets_t_end = doc
        .get_ref()
        .get("run")
        .is_some_and(|r| r.get_ref().get("t_end").is_some());
    if !sets_t_end
        && matches!(scene.kind(), super::Kind::Movie | super::Kind::Figure)
        && scene.fidelity() == super::Fidelity::Simulation
        && !matches!(scene.output, super::OutputSpec::Sweep(_))
    {
        scene.run.t_end = super::AUTO_T_END;
    }
    scene.check().map_err(|(key, msg)| {
        let span = span_of(doc.get_ref(), &key);
        located(text, origin, span, Some(&key), &msg)
    })?;
    // The conversion, recorded in data files; a `duration` (s) is the
    // run's window in τ.
    Ok(scene.with_conversion())
}

/// The `kind` of an `[output]` table that names none, from its keys:
/// `times` or `panels` a filmstrip, `curves` an arrival chart, `figure` a
/// theory figure, `grid` a sweep; otherwise none (serde's default, a
/// movie, applies).
fn inferred_kind(output: &DeTable<'_>) -> Option<&'static str> {
    if output.contains_key("kind") {
        return None;
    }
    let has = |k: &str| output.contains_key(k);
    if has("times") || has("panels") {
        Some("filmstrip")
    } else if has("curves") {
        Some("arrivals")
    } else if has("figure") {
        Some("theory")
    } else if has("grid") {
        Some("sweep")
    } else {
        None
    }
}

/// `text` with `kind = "..."` added to an `[output]` table that names no
/// kind but whose keys say it, and where (byte offset) and how much was
/// inserted.
fn with_inferred_kind(text: &str, doc: &DeTable<'_>) -> (String, Option<(usize, usize)>) {
    let Some((key, value)) = doc.get_key_value("output") else {
        return (text.to_string(), None);
    };
    let DeValue::Table(table) = value.get_ref() else {
        return (text.to_string(), None);
    };
    let Some(kind) = inferred_kind(table) else {
        return (text.to_string(), None);
    };
    let v = value.span();
    let (at, insert) = if text.get(v.start..).is_some_and(|t| t.starts_with('{')) {
        (v.start + 1, format!(" kind = \"{kind}\","))
    } else {
        // A `[output]` header (not `[output.grid]`): the line after it.
        let line_start = text[..key.span().start].rfind('\n').map_or(0, |i| i + 1);
        let header_end = text[key.span().end..]
            .find('\n')
            .map_or(text.len(), |i| key.span().end + i + 1);
        let header: String = text[line_start..header_end]
            .split('#')
            .next()
            .unwrap_or("")
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect();
        if header != "[output]" {
            return (text.to_string(), None);
        }
        (header_end, format!("kind = \"{kind}\"\n"))
    };
    let mut read = text.to_string();
    if at > read.len() {
        read.push('\n');
    }
    let at = at.min(read.len());
    read.insert_str(at, &insert);
    (read, Some((at, insert.len())))
}

/// For serde's "unknown field `X`", the dotted path and span of the key X
/// in the file (inside `[output]` serde gives no place of its own).
fn unknown_key(doc: &DeTable<'_>, message: &str) -> Option<(String, Range<usize>)> {
    let name = message.strip_prefix("unknown field `")?.split('`').next()?;
    fn find(
        table: &DeTable<'_>,
        name: &str,
        path: &mut Vec<String>,
    ) -> Option<(String, Range<usize>)> {
        for (k, v) in table.iter() {
            path.push(k.get_ref().to_string());
            if k.get_ref() == name {
                return Some((path.join("."), k.span()));
            }
            if let DeValue::Table(t) = v.get_ref()
                && let Some(hit) = find(t, name, path)
            {
                return Some(hit);
            }
            if let DeValue::Array(a) = v.get_ref() {
                for (i, item) in a.iter().enumerate() {
                    path.push(i.to_string());
                    if let DeValue::Table(t) = item.get_ref()
                        && let Some(hit) = find(t, name, path)
                    {
                        return Some(hit);
                    }
                    path.pop();
                }
            }
            path.pop();
        }
        None
    }
    find(doc, name, &mut Vec::new())
}

/// For serde's "invalid type: integer `5`, expected …" placed at a whole
/// table (serde reads an `[output]` table of one kind as a whole, and
/// says no more), the dotted path and span of the one key under `table`
/// whose value is written as serde quotes it.
fn typed_key(
    text: &str,
    doc: &DeTable<'_>,
    table: &str,
    message: &str,
) -> Option<(String, Range<usize>)> {
    let got = message
        .strip_prefix("invalid type: ")?
        .split(", expected")
        .next()?;
    let written = match got.split('`').nth(1) {
        Some(v) => v.to_string(),
        None => got.strip_prefix("string ")?.to_string(),
    };
    let mut here = doc.get(table.split('.').next()?)?;
    for part in table.split('.').skip(1) {
        here = here.get_ref().get(part)?;
    }
    let DeValue::Table(t) = here.get_ref() else {
        return None;
    };
    fn walk(
        text: &str,
        t: &DeTable<'_>,
        written: &str,
        path: &mut Vec<String>,
        hits: &mut Vec<(String, Range<usize>)>,
    ) {
        for (k, v) in t.iter() {
            path.push(k.get_ref().to_string());
            match v.get_ref() {
                DeValue::Table(inner) => walk(text, inner, written, path, hits),
                DeValue::Array(_) => {}
                _ if text.get(v.span()).map(str::trim) == Some(written) => {
                    hits.push((path.join("."), v.span()));
                }
                _ => {}
            }
            path.pop();
        }
    }
    let mut hits = Vec::new();
    walk(text, t, &written, &mut vec![table.to_string()], &mut hits);
    if hits.len() == 1 { hits.pop() } else { None }
}

/// The top-level table whose `[header]` starts at byte `offset` (where
/// serde places an error about the table as a whole).
fn table_at(text: &str, doc: &DeTable<'_>, offset: usize) -> Option<String> {
    doc.iter()
        .filter(|(_, v)| matches!(v.get_ref(), DeValue::Table(_)))
        .find(|(k, _)| {
            k.span().start >= offset
                && text
                    .get(offset..k.span().start)
                    .is_some_and(|t| !t.contains('\n'))
        })
        .map(|(k, _)| k.get_ref().to_string())
}

/// Reads and parses the scene file at `path`; a scene without `name` is
/// named after the file (`k70.toml` → `k70`).
pub fn load(path: &Path) -> Result<Scene> {
    let shown = path.display().to_string();
    let meta = std::fs::metadata(path)
        .map_err(|e| Error::bad_input(format!("cannot read {shown}: {}", reason(&e))))?;
    if !meta.is_file() {
        return Err(Error::bad_input(format!(
            "cannot read {shown}: not a regular file"
        )));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(Error::bad_input(format!(
            "{shown}: a scene file must be at most {MAX_FILE_BYTES} bytes, got {}",
            meta.len()
        )));
    }
    let bytes = std::fs::read(path)
        .map_err(|e| Error::bad_input(format!("cannot read {shown}: {}", reason(&e))))?;
    let text = String::from_utf8(bytes)
        .map_err(|_| Error::bad_input(format!("{shown}: a scene file must be UTF-8 text")))?;
    let stem = path
        .file_stem()
        .map(|s| sanitize(&s.to_string_lossy()))
        .unwrap_or_else(|| "custom".into());
    parse(&text, &shown, &stem)
}

/// The scene as TOML, every parameter written out (defaults included),
/// without its `name` (a file takes its name from its file name).
pub fn to_toml(scene: &Scene) -> Result<String> {
    let mut table = toml::Table::try_from(scene)
        .map_err(|e| Error::failed(format!("cannot write the scene as TOML: {e}")))?;
    table.remove("name");
    toml::to_string(&table)
        .map_err(|e| Error::failed(format!("cannot write the scene as TOML: {e}")))
}

/// A file stem turned into a legal scene name.
fn sanitize(stem: &str) -> String {
    let s: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .take(64)
        .collect();
    let s = s.trim_start_matches('.').to_string();
    if s.is_empty() { "custom".into() } else { s }
}

fn reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => e.to_string().to_lowercase(),
    }
}

/// One line: `origin:line:column: key: message`.
fn located(
    text: &str,
    origin: &str,
    span: Option<Range<usize>>,
    key: Option<&str>,
    message: &str,
) -> Error {
    let at = match span {
        Some(s) => {
            let (line, col) = line_col(text, s.start);
            format!("{origin}:{line}:{col}")
        }
        None => origin.to_string(),
    };
    let message: String = message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    match key {
        Some(k) if !k.is_empty() => Error::bad_input(format!("{at}: {k}: {message}")),
        _ => Error::bad_input(format!("{at}: {message}")),
    }
}

/// 1-based line and column (in characters) of byte `offset`.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// The dotted key path (`model.alpha`, `drive.flips.1.start`) of the
/// deepest key, or scalar value, whose span contains `offset`. Every
/// table is searched: a `[table]`'s own span covers only its header.
fn key_at(table: &DeTable<'_>, offset: usize) -> Option<String> {
    fn inside(r: Range<usize>, offset: usize) -> bool {
        r.start <= offset && offset < r.end.max(r.start + 1)
    }
    fn walk(
        value: &DeValue<'_>,
        offset: usize,
        path: &mut Vec<String>,
        best: &mut Option<Vec<String>>,
    ) {
        let mut visit = |name: String, span_hit: bool, child: &DeValue<'_>| {
            path.push(name);
            let scalar = !matches!(child, DeValue::Table(_) | DeValue::Array(_));
            if span_hit && (scalar || best.as_ref().is_none_or(|b| b.len() < path.len())) {
                *best = Some(path.clone());
            }
            walk(child, offset, path, best);
            path.pop();
        };
        match value {
            DeValue::Table(t) => {
                for (k, v) in t.iter() {
                    let hit = inside(k.span(), offset)
                        || (!matches!(v.get_ref(), DeValue::Table(_)) && inside(v.span(), offset));
                    visit(k.get_ref().to_string(), hit, v.get_ref());
                }
            }
            DeValue::Array(a) => {
                for (i, v) in a.iter().enumerate() {
                    visit(i.to_string(), inside(v.span(), offset), v.get_ref());
                }
            }
            _ => {}
        }
    }
    let mut best = None;
    walk(
        &DeValue::Table(table.clone()),
        offset,
        &mut Vec::new(),
        &mut best,
    );
    best.map(|p| p.join("."))
}

/// The span of the value at dotted `key`, or of its nearest ancestor
/// present in the file (a defaulted key has no place of its own).
fn span_of(table: &DeTable<'_>, key: &str) -> Option<Range<usize>> {
    let mut best: Option<Range<usize>> = None;
    let mut here: Option<&Spanned<DeValue<'_>>> = None;
    for part in key.split('.') {
        let next = match here {
            None => table.get(part),
            Some(v) => match part.parse::<usize>() {
                Ok(i) => v.get_ref().get(i),
                Err(_) => v.get_ref().get(part),
            },
        };
        match next {
            Some(v) => {
                best = Some(v.span());
                here = Some(v);
            }
            None => break,
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_count_characters() {
        let t = "a = 1\nαβ = 2\n";
        assert_eq!(line_col(t, 0), (1, 1));
        assert_eq!(line_col(t, 6), (2, 1));
        assert_eq!(line_col(t, t.find('=').unwrap()), (1, 3));
        let second = t.rfind('=').unwrap();
        assert_eq!(line_col(t, second), (2, 4));
    }

    #[test]
    fn a_file_named_after_its_output_keeps_its_name_once() {
        let movie = "[output]\nkind = \"movie\"\n";
        // assets/scenes/movie-4.toml renders to movie-4.gif, not movie-movie-4.gif.
        assert_eq!(
            parse(movie, "movie-4.toml", "movie-4").unwrap().stem(),
            "movie-4"
        );
        assert_eq!(parse(movie, "k70.toml", "k70").unwrap().stem(), "movie-k70");
        // Only the prefix of its own kind, and never down to nothing.
        assert_eq!(
            parse(movie, "figure-4.toml", "figure-4").unwrap().stem(),
            "movie-figure-4"
        );
        assert_eq!(
            parse(movie, "movie-.toml", "movie-").unwrap().stem(),
            "movie-movie-"
        );
        let named = "name = \"movie-x\"\n[output]\nkind = \"movie\"\n";
        assert_eq!(parse(named, "a.toml", "a").unwrap().name, "movie-x");
    }

    #[test]
    fn an_out_of_range_value_is_located() {
        let text = "[model]\nn = 20\nalpha = 120\n";
        let e = parse(text, "s.toml", "s").unwrap_err().to_string();
        assert!(e.starts_with("s.toml:3:9: model.alpha: "), "{e}");
        assert!(e.contains("120"), "{e}");
    }

    #[test]
    fn unknown_keys_and_wrong_types_are_located() {
        let e = parse("[model]\nalpah = 60\n", "f", "f")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("f:2:1: model.alpah: unknown field"), "{e}");
        let e = parse("[model]\nn = \"ten\"\n", "f", "f")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(
                "f:2:5: model.n: expected a whole number of 0 or more, got the text \"ten\""
            ),
            "{e}"
        );
    }

    #[test]
    fn a_wrong_type_in_output_names_its_key() {
        // serde reads `[output]` as a whole and places the error at it.
        let e = parse("[model]\nn = 10\n\n[output]\ntimes = 5\n", "f", "f")
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "f:5:9: output.times: expected a list [ ... ], got the whole number 5; for example \
             times = [0, 900, 1100, 1350]"
        );
    }

    #[test]
    fn overlapping_flips_name_the_flip() {
        let text =
            "[drive]\nflips = [{ start = 0, duration = 1000 }, { start = 500, duration = 1000 }]\n";
        let e = parse(text, "f", "f").unwrap_err().to_string();
        assert!(e.starts_with("f:2:42: drive.flips.1: "), "{e}");
        assert!(e.contains("overlap"), "{e}");
    }

    #[test]
    fn a_printed_scene_reads_back_equal() {
        let mut s = Scene::default();
        s.model.alpha = -70.5;
        s.model.n = 20;
        s.drive = super::super::DriveSpec::flips_at(&[0.0, 1500.0], 800.0);
        let text = to_toml(&s).unwrap();
        let back = parse(&text, "x", "custom").unwrap();
        assert_eq!(back, s, "{text}");
    }
}
