//! The parameter table: one declaration per parameter of a run
//! (docs/model.md, "Parameters"), from which everything that names a
//! parameter is made: the model's fields and their defaults
//! (`scene::Model`, `Params::paper`), the command line's flags and their
//! help, a scene file's `[model]` keys, a sweep's axes, the data file's
//! fields, the words of titles and parameter lines, and the Python
//! keywords and their docs (through [`Param::ALL`] and [`Spec`]).
//!
//! Adding a coefficient is one entry in [`parameter_table!`], its physics
//! (`Params` and the forces) and its line in docs/model.md.

use std::fmt;

/// Whether a parameter takes whole numbers (N) or any real number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Int,
    Float,
}

impl Kind {
    /// "int" or "float" (Python's type names).
    pub fn name(self) -> &'static str {
        match self {
            Self::Int => "int",
            Self::Float => "float",
        }
    }
}

/// Which table of a scene holds the parameter: `[model]` or `[drive]`
/// (the drive time, the duration of every flip of block 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    Model,
    Drive,
}

/// The values a parameter accepts (in its unit: α in degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Range {
    /// |x| ≤ the bound (|α| ≤ 90°: the symmetric toy at 90°, the gapless
    /// ladder at 0); a simulation asks 0 < |x| < the bound.
    Symmetric(f64),
    /// From the first to the second, inclusive.
    Between(f64, f64),
    /// Above the bound, exclusive (a duration).
    Above(f64),
    /// The bound or more, finite.
    AtLeast(f64),
}

impl Range {
    /// The least value accepted (exclusive for [`Range::Above`]).
    pub fn min(self) -> f64 {
        match self {
            Self::Symmetric(m) => -m,
            Self::Between(lo, _) | Self::Above(lo) | Self::AtLeast(lo) => lo,
        }
    }

    /// The largest value accepted (+∞: any finite number).
    pub fn max(self) -> f64 {
        match self {
            Self::Symmetric(m) | Self::Between(_, m) => m,
            Self::Above(_) | Self::AtLeast(_) => f64::INFINITY,
        }
    }

    /// Whether `x` is accepted (a simulation's stricter ask for α aside).
    pub fn contains(self, x: f64) -> bool {
        x.is_finite()
            && match self {
                Self::Symmetric(m) => x.abs() <= m,
                Self::Between(lo, hi) => (lo..=hi).contains(&x),
                Self::Above(lo) => x > lo,
                Self::AtLeast(lo) => x >= lo,
            }
    }
}

/// One parameter's declaration: everything the program says of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spec {
    /// The key in `[model]` (or the drive keyword), the flag without its
    /// dashes (`_` → `-`), the sweep axis, the CSV column and the Python
    /// keyword: `alpha`, `drive_time`.
    pub name: &'static str,
    /// Its mark in a file name made from what differs from a built-in
    /// scene (`a70-n20`, docs/scenes.md): a, n, b, gamma, grav, inertia,
    /// td.
    pub tag: &'static str,
    /// The paper's symbol: α, N, b/s, γ, G, I, T_d.
    pub symbol: &'static str,
    /// The unit of its values ("" for a pure number): °, s, m s², τ.
    pub unit: &'static str,
    /// The symbol with its unit, for chart axes: "α (°)".
    pub label: &'static str,
    /// The flag's value name in `--help`: DEG, N, B.
    pub value_name: &'static str,
    /// What it is, in a sentence without its range or default (help
    /// texts, docstrings, the scene file's docs).
    pub doc: &'static str,
    /// What a value must be, in an error: "degrees", "a length".
    pub what: &'static str,
    /// The paper's value (supplement, "Details of numerical simulation").
    pub default: f64,
    pub range: Range,
    pub kind: Kind,
    pub place: Place,
}

impl Spec {
    /// The range in words, as help texts and errors give it: "|alpha| <=
    /// 90", "from 1e-3 to 1e3", ">= 0"; `simulated` gives α's stricter
    /// range, "0 < |alpha| < 90".
    pub fn range_text(&self, simulated: bool) -> String {
        // Bounds of a real range in exponent form (1e-3 to 1e3), as the
        // limits are written (docs/limits.md).
        let bound = |x: f64| match self.kind {
            Kind::Float if x != 0.0 => format!("{x:e}"),
            _ => format!("{x}"),
        };
        match self.range {
            Range::Symmetric(m) if simulated => format!("0 < |{}| < {m}", self.name),
            Range::Symmetric(m) => format!("|{}| <= {m}", self.name),
            Range::Between(lo, hi) => format!("from {} to {}", bound(lo), bound(hi)),
            Range::Above(lo) => format!("> {lo}"),
            Range::AtLeast(lo) => format!(">= {lo}"),
        }
    }

    /// "α = 60°", "N = 10", "b/s = 1.3", "I = 0.25 m s²", "T_d = 1000 τ":
    /// the symbol and a value with its unit, `num` writing the number.
    pub fn equation(&self, x: f64, num: impl Fn(f64) -> String) -> String {
        let unit = match self.unit {
            "" => String::new(),
            "°" => "°".into(),
            // b/s: the symbol is the ratio already.
            u if self.symbol.ends_with(&format!("/{u}")) => String::new(),
            u => format!(" {u}"),
        };
        format!("{} = {}{unit}", self.symbol, num(x))
    }

    /// The default as a flag's help prints it: 60, 10, 1.3, 2e-4.
    pub fn default_text(&self) -> String {
        short(self.default)
    }

    /// `x` checked against the range: `Err("must be a length from 1e-3
    /// to 1e3, got -1.3")`. `simulated` asks α's stricter range.
    pub fn check(&self, x: f64, simulated: bool) -> Result<(), String> {
        let ok = match self.range {
            Range::Symmetric(m) if simulated => x.is_finite() && x != 0.0 && x.abs() < m,
            r => r.contains(x) && (self.kind == Kind::Float || x.fract() == 0.0),
        };
        if ok {
            return Ok(());
        }
        let range = self.range_text(simulated);
        let sep = match self.range {
            Range::Symmetric(_) => " with ",
            _ => " ",
        };
        Err(format!(
            "must be {}{sep}{range}, got {}",
            self.what,
            crate::numfmt::plain(x)
        ))
    }
}

/// A number as a help text gives it: 60, 1.3, 0.02, 1000; 2e-4 and 1e6
/// in exponent form.
pub fn short(x: f64) -> String {
    if x != 0.0 && !(1e-2..1e5).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// The table: `$then!` is called with every parameter's declaration, the
/// model's (in `[model]`, the order of docs/model.md) and the drive's.
/// Each entry: `name: type = Variant { tag, symbol, unit, label,
/// value_name, default, range, what, doc }`.
#[macro_export]
#[doc(hidden)]
macro_rules! parameter_table {
    ($then:ident) => {
        $then! {
            model {
                alpha: f64 = Alpha {
                    tag: "a", symbol: "α", unit: "°", label: "α (°)", value_name: "DEG",
                    default: 60.0, range: Symmetric(90.0), what: "degrees",
                    doc: "Equilibrium angle alpha in degrees; its sign picks the ground state \
                          (alpha > 0 launches a kink, alpha < 0 an antikink)",
                },
                n: usize = N {
                    tag: "n", symbol: "N", unit: "", label: "number of blocks N", value_name: "N",
                    default: 10.0, range: Between(2.0, $crate::limits::MAX_BLOCKS as f64), what: "a number of blocks",
                    doc: "Number of blocks N; block 1 is the driven top block",
                },
                b: f64 = B {
                    tag: "b", symbol: "b/s", unit: "s", label: "b / s", value_name: "B",
                    default: 1.3, range: Between($crate::limits::MIN_LENGTH, $crate::limits::MAX_LENGTH), what: "a length",
                    doc: "Rest length b of the B springs, in units of the block length s",
                },
                gamma: f64 = Gamma {
                    tag: "gamma", symbol: "γ", unit: "", label: "damping γ (m/τ)", value_name: "G",
                    default: 0.02, range: AtLeast(0.0), what: "a finite number",
                    doc: "Damping gamma (force -gamma*dX/dt, torque -gamma*r^2*dtheta/dt)",
                },
                gravity: f64 = Gravity {
                    tag: "grav", symbol: "G", unit: "", label: "gravity G = mg/(ks)", value_name: "G",
                    default: 2e-4, range: AtLeast(0.0), what: "a finite number",
                    doc: "Gravity G = mg/(ks)",
                },
                inertia: f64 = Inertia {
                    tag: "inertia", symbol: "I", unit: "m s²", label: "moment of inertia I / (m s²)",
                    value_name: "I", default: 0.25,
                    range: Between($crate::limits::MIN_INERTIA, $crate::limits::MAX_INERTIA),
                    what: "a number",
                    doc: "Moment of inertia I of a block, in units of m s^2",
                },
            }
            drive {
                drive_time: f64 = DriveTime {
                    tag: "td", symbol: "T_d", unit: "τ", label: "drive time T_d / τ", value_name: "TD",
                    default: 1000.0, range: Above(0.0), what: "a finite time",
                    doc: "Time T_d each flip of block 1 takes (alpha -> -alpha, then back), in tau",
                },
            }
        }
    };
}

/// The parameter enum and its specs, made from the table.
macro_rules! declare_params {
    (
        model { $($m:ident : $mt:ty = $mv:ident { $($mk:ident : $mx:expr),* $(,)? }),* $(,)? }
        drive { $($d:ident : $dt:ty = $dv:ident { $($dk:ident : $dx:expr),* $(,)? }),* $(,)? }
    ) => {
        /// A parameter of a run: the model's (`[model]`) and the drive
        /// time (`[drive]`), in the table's order.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Param {
            $($mv,)*
            $($dv,)*
        }

        /// Number of parameters of the model (`[model]`).
        pub const MODEL_COUNT: usize = [$(stringify!($m)),*].len();
        /// Number of parameters.
        pub const COUNT: usize = MODEL_COUNT + [$(stringify!($d)),*].len();

        const SPECS: [Spec; COUNT] = [
            $(Spec {
                name: stringify!($m),
                kind: <$mt as ParamValue>::KIND,
                place: Place::Model,
                $($mk: declare_params!(@field $mk $mx),)*
            },)*
            $(Spec {
                name: stringify!($d),
                kind: <$dt as ParamValue>::KIND,
                place: Place::Drive,
                $($dk: declare_params!(@field $dk $dx),)*
            },)*
        ];

        impl Param {
            /// Every parameter, the model's first, in the table's order
            /// (a sweep's axes, the CSV's columns).
            pub const ALL: [Param; COUNT] = [$(Param::$mv,)* $(Param::$dv,)*];
            /// The model's parameters (`[model]`), in order.
            pub const MODEL: [Param; MODEL_COUNT] = [$(Param::$mv,)*];
        }
    };
    (@field range $x:expr) => { { use Range::*; $x } };
    (@field $k:ident $x:expr) => { $x };
}

parameter_table!(declare_params);

/// The Rust types of parameters' values: `usize` (N) or `f64`.
pub trait ParamValue: Copy {
    const KIND: Kind;
    fn to_f64(self) -> f64;
    /// From a value checked whole where `KIND` is `Int`.
    fn from_f64(x: f64) -> Self;
}

impl ParamValue for f64 {
    const KIND: Kind = Kind::Float;
    fn to_f64(self) -> f64 {
        self
    }
    fn from_f64(x: f64) -> Self {
        x
    }
}

impl ParamValue for usize {
    const KIND: Kind = Kind::Int;
    fn to_f64(self) -> f64 {
        self as f64
    }
    fn from_f64(x: f64) -> Self {
        x as usize
    }
}

impl Param {
    /// Its declaration.
    pub fn spec(self) -> &'static Spec {
        &Self::specs()[self as usize]
    }

    /// Every declaration, in the table's order.
    pub fn specs() -> &'static [Spec] {
        &SPECS
    }

    /// The key, flag, axis, column and keyword: `alpha`, `drive_time`.
    pub fn name(self) -> &'static str {
        self.spec().name
    }

    /// The command-line flag: `--alpha`, `--drive-time`.
    pub fn flag(self) -> String {
        format!("--{}", self.name().replace('_', "-"))
    }

    /// The symbol with its unit, for chart axes: "α (°)", "drive time
    /// T_d / τ".
    pub fn label(self) -> &'static str {
        self.spec().label
    }

    /// The symbol: α, N, b/s, γ, G, I, T_d.
    pub fn symbol(self) -> &'static str {
        self.spec().symbol
    }

    /// The paper's value (a constant: `sim::PAPER_DRIVE_TIME` is the
    /// drive time's).
    pub const fn default_value(self) -> f64 {
        SPECS[self as usize].default
    }

    pub fn from_name(s: &str) -> Option<Param> {
        Self::ALL.into_iter().find(|p| p.name() == s)
    }

    /// The names, for messages: "alpha, n, b, gamma, gravity, inertia or
    /// drive_time".
    pub fn names() -> String {
        let names: Vec<&str> = Self::ALL.iter().map(|p| p.name()).collect();
        format!(
            "{} or {}",
            names[..names.len() - 1].join(", "),
            names[names.len() - 1]
        )
    }

    /// The help text of its flag: the doc, the range (α's for a
    /// simulation where `simulated`) and the default ("Rest length b
    /// ..., from 1e-3 to 1e3 [default: 1.3]").
    pub fn help(self, simulated: bool) -> String {
        let s = self.spec();
        format!(
            "{}, {} [default: {}]",
            s.doc,
            s.range_text(simulated),
            s.default_text()
        )
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_in_order_and_complete() {
        for (k, p) in Param::ALL.into_iter().enumerate() {
            assert_eq!(p as usize, k);
            assert_eq!(p.spec().name, Param::specs()[k].name);
            assert_eq!(Param::from_name(p.name()), Some(p));
            let s = p.spec();
            assert!(s.range.contains(s.default), "{}", s.name);
            assert!(s.check(s.default, true).is_ok(), "{}", s.name);
        }
        assert_eq!(Param::MODEL.len(), MODEL_COUNT);
        assert!(Param::MODEL.iter().all(|p| p.spec().place == Place::Model));
        assert_eq!(Param::N.spec().kind, Kind::Int);
        assert_eq!(
            Param::N.spec().range.max(),
            crate::limits::MAX_BLOCKS as f64
        );
        assert_eq!(
            Param::B.spec().range,
            Range::Between(crate::limits::MIN_LENGTH, crate::limits::MAX_LENGTH)
        );
        assert_eq!(
            Param::Inertia.spec().range,
            Range::Between(crate::limits::MIN_INERTIA, crate::limits::MAX_INERTIA)
        );
    }

    #[test]
    fn checks_are_worded_from_the_table() {
        let b = Param::B.spec();
        assert_eq!(
            b.check(-1.3, true).unwrap_err(),
            "must be a length from 1e-3 to 1e3, got -1.3"
        );
        let a = Param::Alpha.spec();
        assert_eq!(
            a.check(120.0, true).unwrap_err(),
            "must be degrees with 0 < |alpha| < 90, got 120"
        );
        assert!(a.check(0.0, true).is_err() && a.check(0.0, false).is_ok());
        assert_eq!(
            Param::N.spec().check(1.0, true).unwrap_err(),
            "must be a number of blocks from 2 to 100000, got 1"
        );
        assert!(Param::N.spec().check(2.5, true).is_err());
        assert_eq!(
            Param::Gamma.spec().check(-1.0, true).unwrap_err(),
            "must be a finite number >= 0, got -1"
        );
    }
}
