//! Numbers as text, a leaf that every floor may use: [`plain`] for a
//! message (as the user typed it, exponent form when tiny or huge) and
//! [`typeset`] for a picture or a title (as a reader writes it, with a
//! typographic minus sign).

/// A user's number for a message: as typed for ordinary magnitudes, in
/// exponent form when tiny or huge (so that 1e308 does not print 309
/// digits).
pub fn plain(x: f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-4..1e9).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A computed number for a message: [`plain`] to six significant
/// digits (3234.8106590649163 → 3234.81, a duration converted to τ),
/// so a value the user typed with six or fewer reads as typed.
pub fn brief(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return plain(x);
    }
    let magnitude = x.abs().log10().floor() as i32;
    let rounded: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    if !(-4..9).contains(&magnitude) {
        return plain(rounded);
    }
    let decimals = (5 - magnitude).max(0) as usize;
    let s = format!("{rounded:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A number as a reader writes it: 60, 1.3, 0.0002 → 2e-4, with a
/// typographic minus sign.
pub fn typeset(x: f64) -> String {
    let s = if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e6) {
        // Twelve significant digits: 1.9999999999999998e-4, a converted
        // value's rounding noise, reads 2e−4.
        let e = format!("{x:.11e}");
        let (mantissa, exponent) = e.split_once('e').unwrap_or((&e, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exponent}").replace("e-", "e−")
    } else {
        let r = (x * 1e9).round() / 1e9;
        format!("{r}")
    };
    s.replace('-', "−")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_keeps_ordinary_numbers_and_shortens_extremes() {
        assert_eq!(plain(1.3), "1.3");
        assert_eq!(plain(-60.0), "-60");
        assert_eq!(plain(1e308), "1e308");
        assert_eq!(plain(2e-5), "2e-5");
        assert_eq!(plain(0.0), "0");
    }

    #[test]
    fn brief_keeps_six_significant_digits() {
        assert_eq!(brief(3234.8106590649163), "3234.81");
        assert_eq!(brief(2000.0), "2000");
        assert_eq!(brief(0.125), "0.125");
        assert_eq!(brief(-1.0 / 3.0), "-0.333333");
        assert_eq!(brief(123456789.0), "123457000");
        assert_eq!(brief(1e12 / 3.0), "3.33333e11");
        assert_eq!(brief(2e-5 / 3.0), "6.66667e-6");
        assert_eq!(brief(0.0), "0");
        assert_eq!(brief(f64::INFINITY), "inf");
    }

    #[test]
    fn typeset_uses_the_minus_sign_and_rounds_noise() {
        assert_eq!(typeset(-60.0), "−60");
        assert_eq!(typeset(2e-4), "2e−4");
        assert_eq!(typeset(0.1 + 0.2), "0.3");
        assert_eq!(typeset(1.5e6), "1.5e6");
        assert_eq!(typeset(1.9999999999999998e-4), "2e−4");
        assert_eq!(typeset(-1.234e-7), "−1.234e−7");
    }
}
