//! The values of one axis of a sweep, as a scene file or a flag types
//! them: ranges `"start:stop:step"` (inclusive, rounded to the decimals
//! written) and single numbers, in any mix.

use super::Param;
use serde::de::{self, SeqAccess, Visitor};
use serde::ser::SerializeSeq;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// Largest number of values of one axis (the run cap bounds the product).
pub const MAX_AXIS_VALUES: usize = 1_000_000;

/// What the message of [`MAX_AXIS_VALUES`] adds: it is a range, which no
/// cap raises (the grid's runs have their own cap).
const AXIS_HINT: &str = " (a fixed range that no flag raises: use a coarser step; \
                         the runs of the whole grid have their own cap)";

/// One piece of an axis: an inclusive range or a single number.
#[derive(Debug, Clone, PartialEq)]
pub enum Piece {
    /// `start:stop:step`, inclusive of `stop` when the steps land on it;
    /// kept as typed, so that values are rounded to the decimals written.
    Range {
        text: String,
    },
    Value(f64),
}

/// The values of one axis: pieces, concatenated in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Values(pub Vec<Piece>);

impl Values {
    /// Parses a command-line value: `start:stop:step`, or a comma list of
    /// numbers and ranges (`0.01,0.02` or `40:89:1,-40:-89:-1`).
    ///
    /// The one parser of an axis's text: a scene file's string (`alpha =
    /// "40:45:1,47:50:1"`, or such a string in a list) is read by it too
    /// ([`pieces_of`]), its errors reported when the sweep is checked,
    /// naming the key.
    pub fn parse(text: &str) -> Result<Values, String> {
        let values = Values(pieces_of(text));
        for p in &values.0 {
            match p {
                Piece::Range { text } => {
                    range_values(text)?;
                }
                Piece::Value(v) if !v.is_finite() => {
                    return Err(format!("'{v}' is not a finite number"));
                }
                Piece::Value(_) => {}
            }
        }
        Ok(values)
    }

    /// The values, in order; an error names the malformed piece.
    pub fn expand(&self, param: Param) -> Result<Vec<f64>, String> {
        let mut out = Vec::new();
        for p in &self.0 {
            match p {
                Piece::Range { text } => out.extend(range_values(text)?),
                Piece::Value(v) if v.is_finite() => out.push(*v),
                Piece::Value(v) => return Err(format!("{v} is not a finite number")),
            }
            if out.len() > MAX_AXIS_VALUES {
                return Err(format!(
                    "more than {MAX_AXIS_VALUES} values on one axis{AXIS_HINT}"
                ));
            }
        }
        if out.is_empty() {
            return Err("needs at least one value".into());
        }
        if param == Param::N
            && let Some(v) = out.iter().find(|v| v.fract() != 0.0 || **v < 0.0)
        {
            return Err(format!("n takes whole numbers of blocks, got {v}"));
        }
        Ok(out)
    }
}

/// The pieces of an axis's text, unchecked: its comma-separated parts,
/// each a number or (anything else) a range, checked by [`range_values`].
fn pieces_of(text: &str) -> Vec<Piece> {
    text.split(',')
        .map(|part| {
            let part = part.trim();
            match part.parse::<f64>() {
                Ok(v) if !part.contains(':') => Piece::Value(v),
                _ => Piece::Range { text: part.into() },
            }
        })
        .collect()
}

/// The values of `start:stop:step`, inclusive: start, start + step, ...
/// up to stop (within a millionth of a step), each rounded to the decimals
/// written in the range, so that `0.01:0.05:0.01` gives 0.03, not
/// 0.030000000000000002.
pub fn range_values(text: &str) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = text.split(':').map(str::trim).collect();
    let [start, stop, step] = parts[..] else {
        return Err(if parts.len() == 1 {
            format!("'{text}' is not a number or a range start:stop:step")
        } else {
            format!("'{text}' is not a range start:stop:step (three numbers)")
        });
    };
    let num = |s: &str| -> Result<f64, String> {
        let v: f64 = s
            .parse()
            .map_err(|_| format!("range '{text}': '{s}' is not a number"))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("range '{text}': '{s}' is not a finite number"))
        }
    };
    let (a, b, h) = (num(start)?, num(stop)?, num(step)?);
    if h == 0.0 {
        return Err(format!("range '{text}': the step must not be 0"));
    }
    if (b - a) * h < 0.0 {
        return Err(format!(
            "range '{text}': a step of {step} never reaches {stop} from {start}; use a step of sign {}",
            if b > a { "+" } else { "-" }
        ));
    }
    let count = ((b - a) / h + 1e-6).floor() + 1.0;
    if !(count.is_finite() && count <= MAX_AXIS_VALUES as f64) {
        return Err(format!(
            "range '{text}' has more than {MAX_AXIS_VALUES} values{AXIS_HINT}"
        ));
    }
    let decimals = [start, stop, step]
        .iter()
        .map(|s| decimals_of(s))
        .max()
        .unwrap_or(0);
    let scale = 10f64.powi(decimals.min(15) as i32);
    Ok((0..count as usize)
        .map(|k| {
            let v = a + k as f64 * h;
            let r = (v * scale).round() / scale;
            if r == 0.0 { 0.0 } else { r }
        })
        .collect())
}

/// Decimals a number is written with ("0.005" → 3, "1e-4" → 4, "45" → 0).
fn decimals_of(s: &str) -> u32 {
    let s = s.trim_start_matches(['+', '-']);
    let (mantissa, exp) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (s, 0),
    };
    let frac = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    (frac - exp).max(0) as u32
}

impl Serialize for Values {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if let [Piece::Range { text }] = &self.0[..] {
            return s.serialize_str(text);
        }
        let mut seq = s.serialize_seq(Some(self.0.len()))?;
        for p in &self.0 {
            match p {
                Piece::Range { text } => seq.serialize_element(text)?,
                Piece::Value(v) => seq.serialize_element(v)?,
            }
        }
        seq.end()
    }
}

impl<'de> Deserialize<'de> for Values {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Values;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(
                    "a range \"start:stop:step\", a number, or a list of numbers and ranges",
                )
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Values, E> {
                // As the command line reads it (`Values::parse`); checked
                // by `SweepSpec::check`, which names the key.
                Ok(Values(pieces_of(v)))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Values, E> {
                Ok(Values(vec![Piece::Value(v)]))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Values, E> {
                Ok(Values(vec![Piece::Value(v as f64)]))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Values, E> {
                Ok(Values(vec![Piece::Value(v as f64)]))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Values, A::Error> {
                let mut pieces = Vec::new();
                while let Some(one) = seq.next_element::<Values>()? {
                    pieces.extend(one.0);
                }
                Ok(Values(pieces))
            }
        }
        d.deserialize_any(V)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_file_reads_an_axis_as_the_command_line_does() {
        for text in ["40:45:1,47:50:1", "0.01,0.02", "-45:-50:-1, 60", "7"] {
            let flag = Values::parse(text).unwrap();
            let file: Values = serde_json::from_value(serde_json::json!(text)).unwrap();
            let listed: Values = serde_json::from_value(serde_json::json!([text])).unwrap();
            let want = flag.expand(Param::Alpha).unwrap();
            assert_eq!(file.expand(Param::Alpha).unwrap(), want, "{text}");
            assert_eq!(listed.expand(Param::Alpha).unwrap(), want, "{text}");
        }
        assert_eq!(
            Values::parse("40:45:1,47:50:1")
                .unwrap()
                .expand(Param::Alpha)
                .unwrap()
                .len(),
            10
        );
        // The same error either way.
        let file: Values = serde_json::from_value(serde_json::json!("40:45,x")).unwrap();
        let e = file.expand(Param::Alpha).unwrap_err();
        assert_eq!(Values::parse("40:45,x").unwrap_err(), e);
        let file: Values = serde_json::from_value(serde_json::json!("40,x")).unwrap();
        assert_eq!(
            file.expand(Param::Alpha).unwrap_err(),
            Values::parse("40,x").unwrap_err()
        );
    }
}
