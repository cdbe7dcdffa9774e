//! The scene: everything one output needs (SPEC section 6), as owned data.
//!
//! A scene names the model (N, b, α, γ, G, I), the drive of block 1 (any
//! number of flips), the time window and integrator, and what to render.
//! Every field has the paper's value as its default (one `impl Default`
//! per table), so a scene file names only what differs. The built-in
//! catalogue, the command line and users' TOML files all become a
//! [`Scene`]; everything downstream takes one.
//!
//! Floors: this module knows the model and the simulation's types (it
//! builds [`Params`] and [`Scenario`]); it knows no command-line flag.

pub mod apparatus;
pub mod describe;
pub mod file;
pub mod sweep;

use crate::error::{Error, Result};
use crate::model::Params;
use crate::sim::{Drive, IntegratorConfig, IntegratorKind, Scenario, Start};
use serde::{Deserialize, Serialize};
use std::fmt;

/// One output: a model, a drive, a window, an integrator and a picture.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scene {
    /// Name of the output files: `figure-NAME.png`, `movie-NAME.gif`.
    /// Letters, digits, `-`, `_` and `.`. Default `custom`.
    pub name: String,
    /// A short label put before the title, such as "Movie 4" or "Fig. 3".
    /// Default none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<String>,
    /// Title drawn on the picture. Default: generated from the fields
    /// ("kink, α = 70°, N = 20").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub title: Option<String>,
    /// What the picture shows, in a sentence or two, for the gallery.
    /// Default: none (the parameter line is always generated).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub caption: Option<String>,
    /// The ladder (SPEC section 1). Default: the paper's values.
    pub model: Model,
    /// What block 1 does. Default: one flip over [0, 1000 τ].
    pub drive: DriveSpec,
    /// Window and integrator. Default: [0, 4000 τ], `auto`, tolerance 0.1 τ.
    pub run: Run,
    /// What to render. Default: a movie with a fixed camera.
    pub output: OutputSpec,
    /// How figures look and the page they are printed on (`[style]`:
    /// `name`, `width`, `height`, `font_size`, `font`, `dpi`, `text`).
    /// Default: the `screen` style; command-line flags override it.
    #[serde(skip_serializing_if = "crate::render::StyleSpec::is_empty")]
    pub style: crate::render::StyleSpec,
    /// The ladder as built, in physical units (SPEC section 12,
    /// `[apparatus]`, `scene::apparatus`). Default none: the model's units.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub apparatus: Option<apparatus::Apparatus>,
}

impl Default for Scene {
    fn default() -> Self {
        Self {
            name: "custom".into(),
            label: None,
            title: None,
            caption: None,
            model: Model::default(),
            drive: DriveSpec::default(),
            run: Run::default(),
            output: OutputSpec::default(),
            style: crate::render::StyleSpec::default(),
            apparatus: None,
        }
    }
}

/// The model's parameters (SPEC section 1, `[model]` in a scene file).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Model {
    /// Equilibrium angle α in degrees; its sign picks the ground state
    /// (α > 0: kink, α < 0: antikink). Default 60.
    pub alpha: f64,
    /// Number of blocks N; block 1 is the driven top block. Default 10.
    pub n: usize,
    /// Rest length b of the B springs, in units of s. Default 1.3.
    pub b: f64,
    /// Damping γ: force −γẊ, torque −γr²θ̇. Default 0.02.
    pub gamma: f64,
    /// Gravity G = mg/(ks). Default 2e-4.
    pub gravity: f64,
    /// Moment of inertia I of a block, in m s². Default 0.25 (m s²/4).
    pub inertia: f64,
    /// How the run starts: `ground` (at rest in the ground state, springs
    /// at rest length) or `relaxed` (at rest hanging under gravity with
    /// block 1 clamped, `sim::relax`). Default `ground` (docs/model.md,
    /// "The hanging start", gives the measurement behind it).
    pub start: Start,
}

impl Default for Model {
    /// The paper's simulation values (supplement, "Details of numerical
    /// simulation").
    fn default() -> Self {
        Self {
            alpha: 60.0,
            n: 10,
            b: 1.3,
            gamma: 0.02,
            gravity: 2e-4,
            inertia: 0.25,
            start: Start::default(),
        }
    }
}

impl Model {
    /// Validated model parameters.
    pub fn params(&self) -> Result<Params> {
        Ok(Params::new(
            self.n,
            self.b,
            self.alpha,
            self.gamma,
            self.gravity,
            self.inertia,
        )?)
    }

    /// "kink" for α > 0, "antikink" for α < 0.
    pub fn wave(&self) -> &'static str {
        if self.alpha >= 0.0 {
            "kink"
        } else {
            "antikink"
        }
    }
}

/// Overrides of some model fields (a filmstrip panel, a chart curve, a
/// sweep point). Missing fields keep the scene's value.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelPatch {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gravity: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia: Option<f64>,
}

impl ModelPatch {
    pub fn apply(&self, m: &Model) -> Model {
        Model {
            alpha: self.alpha.unwrap_or(m.alpha),
            n: self.n.unwrap_or(m.n),
            b: self.b.unwrap_or(m.b),
            gamma: self.gamma.unwrap_or(m.gamma),
            gravity: self.gravity.unwrap_or(m.gravity),
            inertia: self.inertia.unwrap_or(m.inertia),
            start: m.start,
        }
    }
}

/// Block 1's drive: a sequence of flips, each turning block 1 from the
/// ground state it is in to the other one (α → −α, then −α → α, ...)
/// linearly over `duration` from `start` (SPEC sections 1 and 6).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DriveSpec {
    /// The flips, in time order, not overlapping. Default: one flip
    /// starting at 0 over the paper's T_d = 1000 τ. An empty list holds
    /// block 1 at α.
    pub flips: Vec<Flip>,
}

impl Default for DriveSpec {
    fn default() -> Self {
        Self {
            flips: vec![Flip::default()],
        }
    }
}

/// One flip of block 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Flip {
    /// When the flip starts, in τ. Default 0.
    pub start: f64,
    /// How long it takes, T_d, in τ. Default 1000.
    pub duration: f64,
}

impl Default for Flip {
    fn default() -> Self {
        Self {
            start: 0.0,
            duration: crate::sim::PAPER_DRIVE_TIME,
        }
    }
}

impl Flip {
    pub fn end(&self) -> f64 {
        self.start + self.duration
    }
}

impl DriveSpec {
    /// Flips at `start_k`, each over `duration`.
    pub fn flips_at(starts: &[f64], duration: f64) -> Self {
        Self {
            flips: starts
                .iter()
                .map(|&start| Flip { start, duration })
                .collect(),
        }
    }

    /// θ_1(t) as a piecewise-linear drive, α in radians.
    pub fn drive(&self, alpha: f64) -> Result<Drive> {
        self.check().map_err(|(_, msg)| Error::bad_input(msg))?;
        if self.flips.is_empty() {
            return Ok(Drive::hold(alpha));
        }
        let mut knots = Vec::with_capacity(2 * self.flips.len() + 1);
        let mut theta = alpha;
        if self.flips[0].start > 0.0 {
            knots.push((0.0, theta));
        }
        for f in &self.flips {
            if knots.last().is_none_or(|k: &(f64, f64)| k.0 < f.start) {
                knots.push((f.start, theta));
            }
            theta = -theta;
            knots.push((f.end(), theta));
        }
        Drive::new(knots)
    }

    /// End of the last flip (0 when there is none).
    pub fn end(&self) -> f64 {
        self.flips.last().map_or(0.0, Flip::end)
    }

    /// Checks the flips: finite, start ≥ 0, duration > 0, in order and not
    /// overlapping. On error: (index of the offending flip, message).
    pub fn check(&self) -> std::result::Result<(), (usize, String)> {
        let mut prev_end = 0.0;
        for (k, f) in self.flips.iter().enumerate() {
            if !(f.start.is_finite() && f.start >= 0.0) {
                return Err((
                    k,
                    format!("start must be a finite time >= 0, got {}", f.start),
                ));
            }
            if !(f.duration.is_finite() && f.duration > 0.0) {
                return Err((
                    k,
                    format!("duration must be a finite time > 0, got {}", f.duration),
                ));
            }
            // The end must be a finite time after the start in floating
            // point too (start + duration can round to start, or overflow).
            if !(f.end().is_finite() && f.end() > f.start) {
                return Err((
                    k,
                    format!(
                        "a flip from {} for {} ends at {}: the duration must be finite and \
                         not lost in the rounding of the start",
                        crate::error::num(f.start),
                        crate::error::num(f.duration),
                        crate::error::num(f.end())
                    ),
                ));
            }
            if k > 0 && f.start < prev_end {
                return Err((
                    k,
                    format!(
                        "flip {} starts at {} before flip {} ends at {prev_end}; flips must not overlap",
                        k + 1,
                        f.start,
                        k
                    ),
                ));
            }
            prev_end = f.end();
        }
        Ok(())
    }
}

/// Which integrator a run uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Chosen by the program and verified (SPEC section 6): velocity Verlet
    /// at a step below the stability bound, checked against a run at half
    /// the step and tightened until every arrival time is within the
    /// scene's tolerance.
    #[default]
    Auto,
    /// One of the five schemes, at the scene's `dt` (or `rtol`).
    Fixed(IntegratorKind),
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Auto => f.write_str("auto"),
            Self::Fixed(k) => f.write_str(k.name()),
        }
    }
}

impl std::str::FromStr for Method {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        if s == "auto" {
            return Ok(Self::Auto);
        }
        s.parse::<IntegratorKind>()
            .map(Self::Fixed)
            .map_err(|e| Error::bad_input(format!("{e}, or auto")))
    }
}

impl Serialize for Method {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Method {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(|e: Error| serde::de::Error::custom(e))
    }
}

/// The time window and the integrator (`[run]` in a scene file).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Run {
    /// End of the simulated window [0, t_end], in τ, or `"auto"` (held as
    /// +∞ until [`Scene::with_auto_window`] resolves it: until every wave
    /// has a fate, plus a margin, `sim::window`). Default 4000; a movie or
    /// figure whose file or flags set none uses `"auto"`.
    #[serde(with = "t_end_value")]
    pub t_end: f64,
    /// `auto` (default) or explicit-euler, symplectic-euler, verlet, rk4,
    /// dopri5.
    pub integrator: Method,
    /// Time step of a fixed-step integrator (first trial step of dopri5).
    /// Default 0.01; `auto` picks its own.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// Tolerance of adaptive dopri5. Default 1e-6.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    /// Largest error `auto` accepts in any arrival time, in τ. Default 0.1.
    pub tolerance: f64,
}

impl Default for Run {
    fn default() -> Self {
        Self {
            t_end: 4000.0,
            integrator: Method::Auto,
            dt: None,
            rtol: None,
            tolerance: 0.1,
        }
    }
}

/// `run.t_end = "auto"` before it is resolved ([`Scene::with_auto_window`]).
pub const AUTO_T_END: f64 = f64::INFINITY;

/// `t_end` in a scene file: a number of τ or `"auto"` ([`AUTO_T_END`]).
mod t_end_value {
    use super::AUTO_T_END;
    use serde::{Deserializer, Serializer, de};

    pub fn serialize<S: Serializer>(t: &f64, s: S) -> Result<S::Ok, S::Error> {
        if *t == AUTO_T_END {
            s.serialize_str("auto")
        } else {
            s.serialize_f64(*t)
        }
    }

    struct Visitor;

    impl de::Visitor<'_> for Visitor {
        type Value = f64;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a time in τ or \"auto\"")
        }
        fn visit_f64<E: de::Error>(self, x: f64) -> Result<f64, E> {
            Ok(x)
        }
        fn visit_i64<E: de::Error>(self, x: i64) -> Result<f64, E> {
            Ok(x as f64)
        }
        fn visit_u64<E: de::Error>(self, x: u64) -> Result<f64, E> {
            Ok(x as f64)
        }
        fn visit_str<E: de::Error>(self, s: &str) -> Result<f64, E> {
            if s == "auto" {
                Ok(AUTO_T_END)
            } else {
                Err(E::custom(format!(
                    "must be a time in τ or \"auto\", got \"{s}\""
                )))
            }
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        d.deserialize_any(Visitor)
    }
}

/// Default step of a fixed-step integrator: the paper's 0.01 τ.
pub const DEFAULT_DT: f64 = 0.01;
/// Default tolerance of adaptive dopri5.
pub const DEFAULT_RTOL: f64 = 1e-6;

impl Run {
    /// The fixed integrator's configuration; `None` for `auto`.
    pub fn fixed_config(&self) -> Result<Option<IntegratorConfig>> {
        match self.integrator {
            Method::Auto => Ok(None),
            Method::Fixed(kind) => {
                let rtol = match kind {
                    IntegratorKind::Dopri5 => Some(self.rtol.unwrap_or(DEFAULT_RTOL)),
                    _ => None,
                };
                Ok(Some(
                    IntegratorConfig {
                        kind,
                        dt: self.dt.unwrap_or(DEFAULT_DT),
                        rtol,
                    }
                    .validated()?,
                ))
            }
        }
    }
}

/// What a scene renders (`[output]`; `kind` picks the variant).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum OutputSpec {
    /// A GIF of the ladder beside its live kymograph, plus the kymograph
    /// PNG (`movie-NAME.gif`, `movie-NAME-kymograph.png`).
    Movie {
        /// `auto` (default: `fixed` when the whole ladder fits the frame
        /// with blocks large enough to see, otherwise the ladder folded
        /// into columns side by side, every block in the frame), `fixed`
        /// (one window that fits every frame) or `follow` (a window that
        /// moves with the kink, movie 3).
        #[serde(default)]
        camera: Camera,
    },
    /// Snapshots at given times, one strip per panel (`figure-NAME.png`).
    Filmstrip {
        /// Times of the snapshots, in τ, within [0, t_end]. Used by
        /// panels that give none. Default: seven times evenly over the
        /// window.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        times: Vec<f64>,
        /// Strips, each a variant of the scene. Default: one strip of the
        /// scene itself.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        panels: Vec<Panel>,
    },
    /// The kymograph of sin θ_n alone (`figure-NAME.png`).
    Kymograph,
    /// Arrival time t_n against n, one curve per variant
    /// (`figure-NAME.png`), with the fitted speeds.
    Arrivals {
        /// Curves. Default: one curve of the scene itself.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        curves: Vec<Panel>,
    },
    /// No picture: the run's numbers only (`data-NAME.json`).
    Data,
    /// A figure of the linear theory or a drawing (`figure-NAME.png`).
    Theory(TheorySpec),
    /// The scene run over a grid of parameters, each run's outcome
    /// decided, charted (`figure-NAME.png`) and tabulated
    /// (`figure-NAME.csv`); `ladder sweep` writes `sweep-NAME.*`
    /// (SPEC section 7, `sweep::SweepSpec`).
    Sweep(sweep::SweepSpec),
}

impl Default for OutputSpec {
    fn default() -> Self {
        Self::Movie {
            camera: Camera::Auto,
        }
    }
}

/// A movie's camera.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Camera {
    /// Fixed when the whole ladder fits with blocks of at least
    /// [`MIN_BLOCK_PIXELS`], otherwise the ladder folded into columns side
    /// by side, like lines of text (`render::fold`).
    #[default]
    Auto,
    /// One window that fits every frame.
    Fixed,
    /// A window that moves with the kink (movie 3).
    Follow,
}

/// A variant of the scene: one strip of a filmstrip or one curve of an
/// arrival chart.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Panel {
    /// Label before the strip's generated title ("(a1)"). Default none.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub label: String,
    /// Model fields that differ from the scene's `[model]`.
    #[serde(skip_serializing_if = "is_default_patch")]
    pub model: ModelPatch,
    /// End of this variant's window, in τ. Default: the scene's t_end.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_end: Option<f64>,
    /// Snapshot times of this strip. Default: the filmstrip's `times`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub times: Vec<f64>,
}

fn is_default_patch(p: &ModelPatch) -> bool {
    *p == ModelPatch::default()
}

/// The figures of the linear theory and the drawings (SPEC section 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TheoryFigure {
    /// Fig. 2b: one unit, drawn.
    UnitSchematic,
    /// Fig. 2c: U(θ) for several a/b.
    GravityPotential,
    /// Fig. 2d: the ground states ±α.
    GroundStates,
    /// Fig. S3: α = 0.
    Gapless,
    /// Fig. S4: zero-mode shapes.
    ZeroModes,
    /// Fig. S5: ω±(q).
    Dispersion,
    /// det C(q) over the Brillouin zone.
    Winding,
    /// The surface zero mode.
    EdgeMode,
    /// ΔU(α).
    Barrier,
}

impl TheoryFigure {
    /// How much model the figure needs.
    pub fn fidelity(self) -> Fidelity {
        match self {
            Self::UnitSchematic | Self::GroundStates | Self::Gapless => Fidelity::Drawing,
            Self::GravityPotential | Self::Barrier | Self::ZeroModes => Fidelity::Formula,
            Self::Dispersion | Self::Winding | Self::EdgeMode => Fidelity::LinearTheory,
        }
    }
}

/// Parameters of a theory figure beyond the scene's `[model]` (which gives
/// N, b and α).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TheorySpec {
    /// Which figure.
    pub figure: TheoryFigure,
    /// Angles α of the dispersion curves (Fig. S5), in degrees.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub alphas: Vec<f64>,
    /// Ratios a/b of the U(θ) curves (Fig. 2c).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub a_over_b: Vec<f64>,
    /// Zero modes (Fig. S4): mode number m and amplitude ε₀ of each panel.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub modes: Vec<ZeroMode>,
}

/// One zero-mode panel of Fig. S4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ZeroMode {
    /// Mode number m.
    pub m: usize,
    /// Amplitude ε₀.
    pub epsilon: f64,
}

/// How much model an output needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Fidelity {
    /// A drawn schematic or a ground state: geometry only.
    Drawing,
    /// A closed-form curve.
    Formula,
    /// Linear algebra on the model (compatibility matrix, Hessian).
    LinearTheory,
    /// Nonlinear time integration.
    Simulation,
}

impl Fidelity {
    pub fn name(self) -> &'static str {
        match self {
            Self::Drawing => "drawing",
            Self::Formula => "formula",
            Self::LinearTheory => "linear theory",
            Self::Simulation => "simulation",
        }
    }
}

/// Whether a scene makes a figure or a movie.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    Figure,
    Movie,
    Data,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Self::Figure => "figure",
            Self::Movie => "movie",
            Self::Data => "data",
        }
    }
}

/// Smallest length, in pixels, of a block (s) in a movie frame (or a
/// filmstrip's snapshot) before an `auto` camera folds the ladder into
/// columns instead of drawing it whole.
pub const MIN_BLOCK_PIXELS: f64 = 14.0;

/// Largest number of flips of block 1.
pub const MAX_FLIPS: usize = 1000;
/// Largest number of panels or curves.
pub const MAX_PANELS: usize = 64;
/// Largest number of snapshots in a strip.
pub const MAX_TIMES: usize = 64;
/// Number of snapshots of a filmstrip that names no times.
pub const DEFAULT_STRIP_FRAMES: usize = 7;

impl Scene {
    pub fn kind(&self) -> Kind {
        match self.output {
            OutputSpec::Movie { .. } => Kind::Movie,
            OutputSpec::Data => Kind::Data,
            _ => Kind::Figure,
        }
    }

    pub fn fidelity(&self) -> Fidelity {
        match &self.output {
            OutputSpec::Theory(t) => t.figure.fidelity(),
            _ => Fidelity::Simulation,
        }
    }

    /// The file name stem: `figure-NAME`, `movie-NAME` or `data-NAME`.
    pub fn stem(&self) -> String {
        format!("{}-{}", self.kind().name(), self.name)
    }

    /// The single-run scene of variant `panel` (its model patched, its own
    /// window), rendered as plain data.
    pub fn variant(&self, panel: &Panel) -> Scene {
        let mut s = self.clone();
        s.model = panel.model.apply(&self.model);
        if let Some(t) = panel.t_end {
            s.run.t_end = t;
        }
        s.output = OutputSpec::Data;
        s.label = None;
        s.title = None;
        s.caption = None;
        s
    }

    /// Every simulation this scene runs, as single-run scenes, with the
    /// snapshot times of each (empty where only arrivals are drawn).
    pub fn runs(&self) -> Vec<(Scene, Vec<f64>)> {
        match &self.output {
            OutputSpec::Theory(_) => Vec::new(),
            OutputSpec::Filmstrip { times, panels } => {
                let one = [Panel::default()];
                let panels: &[Panel] = if panels.is_empty() { &one } else { panels };
                panels
                    .iter()
                    .map(|p| {
                        let v = self.variant(p);
                        let t = if !p.times.is_empty() {
                            p.times.clone()
                        } else if !times.is_empty() {
                            times.clone()
                        } else {
                            even_times(v.run.t_end, DEFAULT_STRIP_FRAMES)
                        };
                        (v, t)
                    })
                    .collect()
            }
            OutputSpec::Arrivals { curves } => {
                if curves.is_empty() {
                    vec![(self.variant(&Panel::default()), Vec::new())]
                } else {
                    curves
                        .iter()
                        .map(|p| (self.variant(p), Vec::new()))
                        .collect()
                }
            }
            _ => vec![(self.variant(&Panel::default()), Vec::new())],
        }
    }

    /// The simulation of this (single-run) scene: at rest in the ground
    /// state of sign α or hanging from it (`model.start`), block 1 driven
    /// as `drive` says, over [0, t_end].
    pub fn scenario(&self) -> Result<Scenario> {
        if let Some(a) = &self.apparatus {
            return a.scenario(self);
        }
        let params = self.model.params()?;
        crate::sim::check_simulable(&params)?;
        let drive = self.drive.drive(params.alpha)?;
        Scenario::with_drive(params, drive, self.run.t_end)?.started(self.model.start)
    }

    /// This scene with `run.t_end = "auto"` resolved (`sim::window`): the
    /// longest automatic window of its runs (every panel or curve that
    /// sets no `t_end` of its own). A scene with a number keeps it.
    pub fn with_auto_window(&self) -> Result<Scene> {
        let mut out = self.clone();
        if self.run.t_end != AUTO_T_END
            || self.apparatus.is_some()
            || self.fidelity() != Fidelity::Simulation
            || matches!(self.output, OutputSpec::Sweep(_))
        {
            return Ok(out);
        }
        let mut t_end: f64 = 0.0;
        for (mut v, _) in self.runs() {
            if v.run.t_end != AUTO_T_END {
                continue;
            }
            v.run.t_end = crate::sim::window::AUTO_CAP;
            let scenario = v.scenario()?;
            let config = match v.run.fixed_config()? {
                Some(c) => c,
                None => IntegratorConfig::auto(crate::theory::dispersion::omega_max_clamped(
                    &scenario.ladder.params,
                )?),
            };
            t_end = t_end.max(crate::sim::window::auto_window(&scenario, &config)?.t_end);
        }
        out.run.t_end = if t_end > 0.0 {
            t_end
        } else {
            Run::default().t_end
        };
        Ok(out)
    }

    /// Checks every field; `Err((key path, message))` names the first bad
    /// one, for the file loader to locate (`model.alpha`,
    /// `drive.flips.1.start`, ...).
    pub fn check(&self) -> std::result::Result<(), (String, String)> {
        let bad = |key: &str, msg: String| Err((key.to_string(), msg));
        if self.name.is_empty()
            || self.name.len() > 64
            || !self
                .name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
            || self.name.starts_with('.')
        {
            return bad(
                "name",
                format!(
                    "must be 1 to 64 letters, digits, '-', '_' or '.' (not first), got '{}'",
                    self.name.escape_debug()
                ),
            );
        }
        for (key, text, lines) in [
            ("label", &self.label, false),
            ("title", &self.title, false),
            ("caption", &self.caption, true),
        ] {
            if let Some(t) = text {
                check_text(key, t, lines)?;
            }
        }
        check_model(
            "model",
            &self.model,
            self.fidelity() == Fidelity::Simulation,
        )?;
        if self.drive.flips.len() > MAX_FLIPS {
            return bad(
                "drive.flips",
                format!("at most {MAX_FLIPS} flips, got {}", self.drive.flips.len()),
            );
        }
        if let Some(a) = &self.apparatus {
            a.check().map_err(|(k, m)| (format!("apparatus.{k}"), m))?;
        }
        if let Err((k, msg)) = self.drive.check() {
            return Err((format!("drive.flips.{k}"), msg));
        }
        let r = &self.run;
        if !((r.t_end.is_finite() || r.t_end == AUTO_T_END) && r.t_end > 0.0) {
            return bad(
                "run.t_end",
                format!("must be a finite time > 0 or \"auto\", got {}", r.t_end),
            );
        }
        if let Some(dt) = r.dt
            && !(dt.is_finite() && dt > 0.0)
        {
            return bad("run.dt", format!("must be a finite number > 0, got {dt}"));
        }
        if let Some(rtol) = r.rtol
            && !(rtol.is_finite() && rtol > 0.0 && rtol < 1.0)
        {
            return bad(
                "run.rtol",
                format!("must be a number in (0, 1), got {rtol}"),
            );
        }
        if r.rtol.is_some() && r.integrator != Method::Fixed(IntegratorKind::Dopri5) {
            return bad("run.rtol", "applies only to integrator = \"dopri5\"".into());
        }
        if r.dt.is_some() && r.integrator == Method::Auto {
            return bad(
                "run.dt",
                "integrator \"auto\" picks its own step; name an integrator to set dt".into(),
            );
        }
        if !(r.tolerance.is_finite() && r.tolerance >= 1e-6 && r.tolerance <= 1e3) {
            return bad(
                "run.tolerance",
                format!("must be a time in [1e-6, 1000] τ, got {}", r.tolerance),
            );
        }
        self.check_output()
    }

    fn check_output(&self) -> std::result::Result<(), (String, String)> {
        let simulated = self.fidelity() == Fidelity::Simulation;
        let check_panels =
            |key: &str, panels: &[Panel]| -> std::result::Result<(), (String, String)> {
                if panels.len() > MAX_PANELS {
                    return Err((
                        key.into(),
                        format!("at most {MAX_PANELS} entries, got {}", panels.len()),
                    ));
                }
                for (k, p) in panels.iter().enumerate() {
                    check_text(&format!("{key}.{k}.label"), &p.label, false)?;
                    let m = p.model.apply(&self.model);
                    check_model(&format!("{key}.{k}.model"), &m, simulated)?;
                    if let Some(t) = p.t_end
                        && !(t.is_finite() && t > 0.0)
                    {
                        return Err((
                            format!("{key}.{k}.t_end"),
                            format!("must be a finite time > 0, got {t}"),
                        ));
                    }
                    let t_end = p.t_end.unwrap_or(self.run.t_end);
                    check_times(&format!("{key}.{k}.times"), &p.times, t_end)?;
                }
                Ok(())
            };
        match &self.output {
            OutputSpec::Filmstrip { times, panels } => {
                if panels.is_empty() || panels.iter().any(|p| p.times.is_empty()) {
                    let t_end = if panels.is_empty() {
                        self.run.t_end
                    } else {
                        panels
                            .iter()
                            .filter(|p| p.times.is_empty())
                            .map(|p| p.t_end.unwrap_or(self.run.t_end))
                            .fold(f64::INFINITY, f64::min)
                    };
                    check_times("output.times", times, t_end)?;
                }
                check_panels("output.panels", panels)
            }
            OutputSpec::Arrivals { curves } => check_panels("output.curves", curves),
            OutputSpec::Theory(t) => check_theory(t),
            OutputSpec::Sweep(spec) => spec.check(Scene::check, self),
            _ => Ok(()),
        }
    }
}

/// Refuses a control character in a text drawn on a picture (a title, a
/// label): most cannot be written in SVG at all, and none draws. A
/// caption (`lines`) may hold line breaks and tabs.
pub fn check_text(key: &str, text: &str, lines: bool) -> std::result::Result<(), (String, String)> {
    match text
        .chars()
        .find(|c| c.is_control() && !(lines && matches!(c, '\n' | '\t')))
    {
        Some(c) => Err((
            key.into(),
            format!(
                "must not contain control characters, got U+{:04X} in \"{}\"",
                u32::from(c),
                text.escape_debug()
            ),
        )),
        None => Ok(()),
    }
}

fn check_model(key: &str, m: &Model, simulated: bool) -> std::result::Result<(), (String, String)> {
    let at = |field: &str, msg: String| Err((format!("{key}.{field}"), msg));
    let max = if simulated { 90.0 } else { 90.0 + 1e-9 };
    if !(m.alpha.is_finite() && m.alpha.abs() < max) || (simulated && m.alpha == 0.0) {
        let range = if simulated {
            "0 < |alpha| < 90"
        } else {
            "|alpha| <= 90"
        };
        return at(
            "alpha",
            format!("must be degrees with {range}, got {}", m.alpha),
        );
    }
    if m.n < 2 || m.n > crate::model::params::MAX_BLOCKS {
        return at(
            "n",
            format!(
                "must be a number of blocks from 2 to {}, got {}",
                crate::model::params::MAX_BLOCKS,
                m.n
            ),
        );
    }
    use crate::limits::{MAX_INERTIA, MAX_LENGTH, MIN_INERTIA, MIN_LENGTH};
    if !(m.b.is_finite() && (MIN_LENGTH..=MAX_LENGTH).contains(&m.b)) {
        return at(
            "b",
            format!(
                "must be a length from {MIN_LENGTH:e} to {MAX_LENGTH:e}, got {}",
                crate::error::num(m.b)
            ),
        );
    }
    if !(m.gamma.is_finite() && m.gamma >= 0.0) {
        return at(
            "gamma",
            format!("must be a finite number >= 0, got {}", m.gamma),
        );
    }
    if !(m.gravity.is_finite() && m.gravity >= 0.0) {
        return at(
            "gravity",
            format!("must be a finite number >= 0, got {}", m.gravity),
        );
    }
    if !(m.inertia.is_finite() && (MIN_INERTIA..=MAX_INERTIA).contains(&m.inertia)) {
        return at(
            "inertia",
            format!(
                "must be a number from {MIN_INERTIA:e} to {MAX_INERTIA:e}, got {}",
                crate::error::num(m.inertia)
            ),
        );
    }
    match m.params() {
        Err(e) => return at("alpha", e.to_string()),
        // What a run will ask (e.g. |alpha| >= 1e-9°), asked here.
        Ok(p) if simulated => {
            if let Err(e) = crate::sim::check_simulable(&p) {
                return at("alpha", e.to_string());
            }
        }
        Ok(_) => {}
    }
    Ok(())
}

fn check_times(key: &str, times: &[f64], t_end: f64) -> std::result::Result<(), (String, String)> {
    if times.len() > MAX_TIMES {
        return Err((
            key.into(),
            format!("at most {MAX_TIMES} times, got {}", times.len()),
        ));
    }
    if let Some(t) = times
        .iter()
        .find(|t| !(t.is_finite() && **t >= 0.0 && **t <= t_end))
    {
        return Err((
            key.into(),
            format!("time {t} lies outside the window [0, t_end = {t_end}]"),
        ));
    }
    Ok(())
}

fn check_theory(t: &TheorySpec) -> std::result::Result<(), (String, String)> {
    if t.alphas.len() > MAX_PANELS || t.a_over_b.len() > MAX_PANELS || t.modes.len() > MAX_PANELS {
        return Err((
            "output".into(),
            format!("at most {MAX_PANELS} alphas, a_over_b or modes"),
        ));
    }
    // The list each figure draws one curve or panel of: never empty.
    let needs = match t.figure {
        TheoryFigure::Dispersion | TheoryFigure::EdgeMode => {
            Some(("alphas", t.alphas.is_empty(), "alphas = [25, 60]"))
        }
        TheoryFigure::GravityPotential => {
            Some(("a_over_b", t.a_over_b.is_empty(), "a_over_b = [1.2, 1.6]"))
        }
        TheoryFigure::ZeroModes => Some((
            "modes",
            t.modes.is_empty(),
            "modes = [{ m = 1, epsilon = 0.1 }]",
        )),
        _ => None,
    };
    if let Some((key, true, example)) = needs {
        return Err((
            format!("output.{key}"),
            format!(
                "this figure draws one curve or panel per entry and needs at least one, e.g. {example}"
            ),
        ));
    }
    if let Some(a) = t
        .alphas
        .iter()
        .find(|a| !(a.is_finite() && a.abs() <= 90.0))
    {
        return Err((
            "output.alphas".into(),
            format!("angles must satisfy |alpha| <= 90, got {a}"),
        ));
    }
    if let Some(r) = t
        .a_over_b
        .iter()
        .find(|r| !(r.is_finite() && **r > 1.0 && **r < 10.0))
    {
        return Err((
            "output.a_over_b".into(),
            format!("ratios must lie in (1, 10), got {r}"),
        ));
    }
    if let Some(m) = t
        .modes
        .iter()
        .find(|m| m.m == 0 || m.m > 1000 || !(m.epsilon.is_finite() && m.epsilon.abs() <= 1.0))
    {
        return Err((
            "output.modes".into(),
            format!(
                "modes need m in 1..=1000 and |epsilon| <= 1, got m = {}, epsilon = {}",
                m.m, m.epsilon
            ),
        ));
    }
    Ok(())
}

/// `frames` times evenly over [0, t_end].
pub fn even_times(t_end: f64, frames: usize) -> Vec<f64> {
    let last = (frames.max(2) - 1) as f64;
    (0..frames.max(2))
        .map(|k| t_end * k as f64 / last)
        .collect()
}
