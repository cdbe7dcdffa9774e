//! serde's messages about a scene file, said in a reader's words: "a
//! number", "a whole number", "a list", never `f64`, `usize` or `struct
//! Flip`, with the expected form of the key and an example.

/// `message` (serde's, from the TOML reader) in plain words, with the
/// form `key` takes (its last named segment: `drive.flips.0` → `flips`).
pub fn plain(message: &str, key: Option<&str>) -> String {
    let name = key.and_then(|k| k.rsplit('.').find(|p| p.parse::<usize>().is_err()));
    let example = name.and_then(example);
    let worded = if let Some(rest) = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
    {
        match rest.split_once(", expected ") {
            Some((got, want)) => format!("expected {}, got {}", expected(want), got_word(got)),
            None => message.to_string(),
        }
    } else {
        message.to_string()
    };
    match example {
        Some(e) if !worded.contains(e) => format!("{worded}; for example {e}"),
        _ => worded,
    }
}

/// What serde expected, in words.
fn expected(want: &str) -> String {
    let want = want.trim();
    match want {
        "f64" | "f32" => "a number".into(),
        // Unsigned: a negative whole number is refused here, and "expected
        // a whole number, got the whole number -3" would not say why.
        "usize" | "u64" | "u32" | "u16" | "u8" => "a whole number of 0 or more".into(),
        "isize" | "i64" | "i32" => "a whole number".into(),
        "a sequence" => "a list [ ... ]".into(),
        "a boolean" | "a string" => want.into(),
        "struct Flip" => "a flip { start = T, duration = TD } (times in τ)".into(),
        "struct Panel" => "a variant table with any of label, model, t_end, times".into(),
        "struct ZeroMode" => "a zero mode { m = M, epsilon = E }".into(),
        w if w.starts_with("struct ") || w == "a map" || w.starts_with("internally tagged") => {
            "a table".into()
        }
        w => w.trim_matches('`').to_string(),
    }
}

/// What the file gave, in words: `integer `0`` → 0, `string "x"` → the
/// text "x".
fn got_word(got: &str) -> String {
    let got = got.trim();
    let inner = |s: &str| s.trim().trim_matches('`').to_string();
    if let Some(v) = got.strip_prefix("integer ") {
        format!("the whole number {}", inner(v))
    } else if let Some(v) = got.strip_prefix("floating point ") {
        format!("the number {}", inner(v))
    } else if let Some(v) = got.strip_prefix("string ") {
        format!("the text {}", v.trim())
    } else if let Some(v) = got.strip_prefix("boolean ") {
        inner(v)
    } else {
        match got {
            "sequence" => "a list".into(),
            "map" => "a table".into(),
            other => other.into(),
        }
    }
}

/// An example of each key of a scene file (docs/scenes.md).
fn example(key: &str) -> Option<&'static str> {
    Some(match key {
        "name" => "name = \"k70\"",
        "label" => "label = \"Movie 4\"",
        "title" => "title = \"a kink\"",
        "caption" => "caption = \"What the picture shows.\"",
        "alpha" => "alpha = 60",
        "n" => "n = 20",
        "b" => "b = 1.3",
        "gamma" => "gamma = 0.02",
        "gravity" => "gravity = 2e-4",
        "inertia" => "inertia = 0.25",
        "flips" => "flips = [{ start = 0, duration = 1000 }, { start = 1500, duration = 1000 }]",
        "start" => "flips = [{ start = 0, duration = 1000 }]",
        "duration" => "flips = [{ start = 0, duration = 1000 }]",
        "t_end" => "t_end = 4000",
        "integrator" => "integrator = \"auto\"",
        "dt" => "dt = 0.01",
        "rtol" => "rtol = 1e-6",
        "tolerance" => "tolerance = 0.1",
        "camera" => "camera = \"follow\"",
        "times" => "times = [0, 900, 1100, 1350]",
        "panels" => "[[output.panels]] label = \"(a)\" model = { alpha = 50 }",
        "curves" => "[[output.curves]] label = \"50°\" model = { alpha = 50 }",
        "model" => "model = { alpha = 50 }",
        "alphas" => "alphas = [50, 60, 75]",
        "a_over_b" => "a_over_b = [0.8, 1.0, 1.2]",
        "modes" => "modes = [{ m = 1, epsilon = 0.1 }]",
        "m" => "modes = [{ m = 1, epsilon = 0.1 }]",
        "epsilon" => "modes = [{ m = 1, epsilon = 0.1 }]",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rust_types_become_words() {
        assert_eq!(
            plain(
                "invalid type: integer `0`, expected struct Flip",
                Some("drive.flips.0")
            ),
            "expected a flip { start = T, duration = TD } (times in τ), got the whole number 0; \
             for example flips = [{ start = 0, duration = 1000 }, { start = 1500, duration = 1000 }]"
        );
        let n = plain(
            "invalid type: floating point `2.5`, expected usize",
            Some("model.n"),
        );
        assert_eq!(
            n,
            "expected a whole number of 0 or more, got the number 2.5; for example n = 20"
        );
        let negative = plain(
            "invalid value: integer `-3`, expected usize",
            Some("model.n"),
        );
        assert_eq!(
            negative,
            "expected a whole number of 0 or more, got the whole number -3; for example n = 20"
        );
        let a = plain(
            "invalid type: string \"sixty\", expected f64",
            Some("model.alpha"),
        );
        assert_eq!(
            a,
            "expected a number, got the text \"sixty\"; for example alpha = 60"
        );
    }
}
