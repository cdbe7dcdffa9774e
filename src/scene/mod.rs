//! The scene: everything one output needs (docs/scenes.md), as owned data.
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
pub mod check;
pub mod describe;
pub mod drive;
pub mod file;
pub mod model;
pub mod names;
pub mod output;
pub mod params;
pub mod run;
pub mod sweep;

pub use check::check_text;
pub use drive::{DriveSpec, Flip};
pub use model::{Model, ModelPatch};
pub use output::{Camera, OutputSpec, Panel, TheoryFigure, TheorySpec, ZeroMode};
pub use run::{AUTO_T_END, DEFAULT_DT, DEFAULT_RTOL, Method, Run};

use crate::error::Result;
use crate::sim::Scenario;
use serde::{Deserialize, Serialize};

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
    /// The ladder (docs/model.md). Default: the paper's values.
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
    /// The ladder as built, in physical units (docs/experiments.md,
    /// `[apparatus]`, `scene::apparatus`). Default none: the model's units.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub apparatus: Option<apparatus::Apparatus>,
    /// The double ring chain (paper Fig. 4b, SI Movie 12; `[rings]`,
    /// docs/rings.md). Default none: the scene is a ladder. A scene with
    /// a ring chain runs it instead of the ladder and makes a movie, a
    /// filmstrip or a kymograph of it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rings: Option<crate::rings::RingChain>,
    /// The caps on what making this output may cost (docs/limits.md):
    /// steps × N, samples × N, frames × pixels, a data file's bytes, a
    /// theory figure's work. Not part of a scene file and never recorded:
    /// the front end sets it (the command line from its `--max-*`
    /// flags), and every run and check made for this scene takes it from
    /// here. Default [`Limits::default`](crate::limits::Limits).
    #[serde(skip)]
    pub limits: crate::limits::Limits,
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
            rings: None,
            limits: crate::limits::Limits::default(),
        }
    }
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

/// The tables of a scene that a flag or a keyword sets.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Table {
    Model,
    Drive,
    Run,
    Apparatus,
}

impl Scene {
    /// Why a value given for `table` (a flag, a Python keyword) would set
    /// nothing this scene runs, or `None` where it would: a ring chain has
    /// no ladder (its keys are `[rings]`'s), and a figure that runs no
    /// simulation (a drawing, a formula, linear theory) has no drive and
    /// no run. A value given there used to be taken and ignored.
    pub fn sets_nothing(&self, table: Table) -> Option<String> {
        if self.rings.is_some() {
            return Some(
                "the ring chain has no ladder to set it on; its keys are [rings]'s \
                 (docs/rings.md)"
                    .into(),
            );
        }
        let fidelity = self.fidelity();
        (fidelity != Fidelity::Simulation && matches!(table, Table::Drive | Table::Run)).then(
            || {
                format!(
                    "this figure is a {} and runs no simulation; block 1's drive and the run do \
                 not apply to it",
                    fidelity.name()
                )
            },
        )
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
    /// With an apparatus, its conversion is made again for the patched
    /// model (`Scene::with_conversion`), so that the variant records the
    /// values its run uses.
    pub fn variant(&self, panel: &Panel) -> Scene {
        let mut s = self.clone();
        s.model = panel.model.apply(&self.model);
        s.output = OutputSpec::Data;
        s.label = None;
        s.title = None;
        s.caption = None;
        match panel.t_end {
            Some(t) => s.with_t_end(t),
            None => s.with_conversion(),
        }
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
        if self.rings.is_some() {
            return Err(crate::error::Error::bad_input(format!(
                "{} is a ring chain ([rings], docs/rings.md): it has no ladder to simulate; \
                 render it (`ladder render`, Python's Scene.render) for its pictures and data file",
                self.name
            )));
        }
        if let Some(a) = &self.apparatus {
            return a.scenario(self);
        }
        let params = self.model.params()?;
        crate::sim::check_simulable(&params)?;
        let drive = self.drive.drive(params.alpha)?;
        Scenario::with_drive(params, drive, self.run.t_end)?.started(self.model.start)
    }

    /// This scene changed from `before` (a built-in, say) with its
    /// window made to follow the chain: where N differs from `before`'s
    /// and the window is still `before`'s number, the window
    /// becomes `"auto"` (docs/sweeps.md: until every wave has a fate, plus
    /// a margin), since a window fitted to the old chain cuts the new one
    /// short (movie 4, t_end = 2200 τ for N = 10, with N = 20 stopped with
    /// the kink at block 11). A filmstrip with times of its own, and a
    /// figure of the linear theory, keep theirs.
    pub fn window_following(mut self, before: &Scene) -> Scene {
        let has_times = match &self.output {
            OutputSpec::Filmstrip { times, panels } => {
                !times.is_empty() || panels.iter().any(|p| !p.times.is_empty())
            }
            OutputSpec::Movie { .. }
            | OutputSpec::Kymograph
            | OutputSpec::Arrivals { .. }
            | OutputSpec::Energy => false,
            OutputSpec::Data
            | OutputSpec::Theory(_)
            | OutputSpec::Sweep(_)
            | OutputSpec::Experiment(_) => true,
        };
        if !has_times
            && self.model.n != before.model.n
            && self.run.t_end == before.run.t_end
            && self.run.t_end != AUTO_T_END
        {
            self.run.t_end = AUTO_T_END;
        }
        self
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
                None => run::auto_config(&scenario)?,
            };
            let options = crate::sim::RunOptions::default().limits(self.limits);
            t_end = t_end.max(crate::sim::window::auto_window(&scenario, &config, &options)?.t_end);
        }
        out.run.t_end = if t_end > 0.0 {
            t_end
        } else {
            Run::default().t_end
        };
        Ok(out)
    }
}

/// `frames` times evenly over [0, t_end], the last exactly t_end
/// (t_end · k / k can round one ulp above t_end, outside the window).
pub fn even_times(t_end: f64, frames: usize) -> Vec<f64> {
    let count = frames.max(2);
    let last = (count - 1) as f64;
    (0..count)
        .map(|k| {
            if k + 1 == count {
                t_end
            } else {
                t_end * k as f64 / last
            }
        })
        .collect()
}
