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
}
