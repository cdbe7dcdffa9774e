//! Tick labels and short number formatting (10⁻³, 1×10⁻⁶, −2).

use super::Scale;

/// Tick label: powers of ten as 10⁻³ on log axes, otherwise a short number.
pub fn tick_label(v: f64, scale: Scale) -> String {
    if scale == Scale::Log && v > 0.0 {
        let e = v.log10();
        if (e - e.round()).abs() < 1e-9 {
            return format!("10{}", superscript(e.round() as i64));
        }
    }
    short_number(v)
}

/// A number with at most four significant digits and no trailing zeros,
/// negative numbers with a typographic minus sign (U+2212).
pub fn short_number(v: f64) -> String {
    plain_number(v).replace('-', "−")
}

fn plain_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_finite() {
            "0".into()
        } else {
            format!("{v}")
        };
    }
    let a = v.abs();
    if !(1e-3..1e5).contains(&a) {
        let e = a.log10().floor() as i64;
        let m = v / 10f64.powi(e as i32);
        return format!("{}×10{}", trim(format!("{m:.2}")), superscript(e));
    }
    let decimals = (3 - a.log10().floor() as i64).clamp(0, 6) as usize;
    trim(format!("{v:.decimals$}"))
}

/// Labels of `values` in one number format, two significant digits: all
/// as m×10ⁿ when they span more than a factor 100 or any lies outside
/// [0.01, 10⁴), else all with the same number of decimals (a colour bar's
/// ticks: "4.8×10⁻⁴ … 5×10⁻³", never "0.004982" beside "4.76×10⁻⁴").
pub fn same_format(values: &[f64]) -> Vec<String> {
    let mags: Vec<f64> = values
        .iter()
        .map(|v| v.abs())
        .filter(|a| *a > 0.0 && a.is_finite())
        .collect();
    let (lo, hi) = mags
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), a| (l.min(*a), h.max(*a)));
    if mags.is_empty() {
        return values.iter().map(|v| short_number(*v)).collect();
    }
    if hi / lo > 100.0 || lo < 0.01 || hi >= 1e4 {
        return values
            .iter()
            .map(|&v| {
                if v == 0.0 {
                    return "0".into();
                }
                let e = v.abs().log10().floor();
                let m = v / 10f64.powf(e);
                let m = trim(format!("{m:.1}"));
                format!("{m}×10{}", superscript(e as i64)).replace('-', "−")
            })
            .collect();
    }
    let decimals = (1.0 - lo.log10().floor()).clamp(0.0, 6.0) as usize;
    values
        .iter()
        .map(|v| format!("{v:.decimals$}").replace('-', "−"))
        .collect()
}

fn trim(s: String) -> String {
    if !s.contains('.') {
        return s;
    }
    let t = s.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" { "0".into() } else { t.into() }
}

fn superscript(e: i64) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if e < 0 {
        s.push('⁻');
    }
    for c in e.unsigned_abs().to_string().chars() {
        s.push(DIGITS[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(short_number(0.5), "0.5");
        assert_eq!(short_number(1200.0), "1200");
        assert_eq!(short_number(-2.0), "−2");
        assert_eq!(short_number(1e-6), "1×10⁻⁶");
        assert_eq!(tick_label(1e-3, Scale::Log), "10⁻³");
        assert_eq!(tick_label(100.0, Scale::Log), "10²");
    }

    #[test]
    fn colour_bar_labels_share_one_format() {
        // The phase diagram's bar of the issue: 4.76×10⁻⁴ to 0.004982.
        let l = same_format(&[4.76e-4, (4.76e-4f64 * 0.004982).sqrt(), 0.004982]);
        assert_eq!(l, ["4.8×10⁻⁴", "1.5×10⁻³", "5×10⁻³"]);
        assert_eq!(same_format(&[0.1, 0.55, 1.0]), ["0.10", "0.55", "1.00"]);
        assert_eq!(same_format(&[-1.0, 0.0, 1.0]), ["−1.0", "0.0", "1.0"]);
    }
}
