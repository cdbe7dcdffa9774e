//! Every figure and movie of the paper as data (SPEC section 4): what it
//! shows, its parameters, and the least model that draws it (a drawing, a
//! formula, the linear theory, or a simulation with the integrator and step
//! chosen by measurement, `ladder bench work-precision`).

use crate::error::{Error, Result};
use crate::model::Params;
use crate::sim::{self, Drive, IntegratorConfig, IntegratorKind, Scenario};

/// Figure (PNG) or movie (GIF plus kymograph PNG).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    Figure,
    Movie,
}

/// How much model a scene needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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

/// The drive of block 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DriveSpec {
    /// α → −α over [0, T_d] (kink for α > 0, antikink for α < 0).
    Single,
    /// α → −α over [0, T_d], back over [second, second + T_d].
    TwoFlips { second: f64 },
}

/// The integrator every simulated scene uses: velocity Verlet at dt = 0.25 τ.
/// Measured (`ladder bench work-precision`, docs/performance.md): arrival
/// times within 0.02 τ of the dopri5 reference at 1/25 of the paper's cost.
pub const SCENE_INTEGRATOR: IntegratorConfig = IntegratorConfig {
    kind: IntegratorKind::Verlet,
    dt: 0.25,
    rtol: None,
};

/// Largest arrival-time error of [`SCENE_INTEGRATOR`] over the simulated
/// scenes, in τ, measured against dopri5 (tests/scenes_accuracy.rs checks
/// that it stays below this).
pub const SCENE_ARRIVAL_ERROR: f64 = 0.02;

/// A simulation: the paper's parameters with α, b, N, a drive and a window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimSpec {
    pub alpha_deg: f64,
    pub b: f64,
    pub n: usize,
    pub drive: DriveSpec,
    /// Simulated window [0, t_end]: the drive and the whole wave, no more.
    pub t_end: f64,
}

impl SimSpec {
    /// The paper's N = 10, b/s = 1.3 and single flip at `alpha_deg`.
    pub const fn paper(alpha_deg: f64, t_end: f64) -> Self {
        Self {
            alpha_deg,
            b: 1.3,
            n: 10,
            drive: DriveSpec::Single,
            t_end,
        }
    }

    pub fn params(&self) -> Result<Params> {
        Ok(Params::paper(self.alpha_deg)?.with(self.n, self.b, self.alpha_deg)?)
    }

    /// The scenario: ground state of sign α at rest, block 1 driven.
    pub fn scenario(&self) -> Result<Scenario> {
        let params = self.params()?;
        let t_d = sim::PAPER_DRIVE_TIME;
        let drive = match self.drive {
            DriveSpec::Single => Drive::single_flip(params.alpha, t_d)?,
            DriveSpec::TwoFlips { second } => Drive::two_flips(params.alpha, t_d, second)?,
        };
        Scenario::with_drive(params, drive, self.t_end)
    }

    /// "α = 60°, b/s = 1.3, N = 10, T_d = 1000 τ".
    pub fn describe(&self) -> String {
        let drive = match self.drive {
            DriveSpec::Single => "block 1 turned α → −α over 0 ≤ t ≤ 1000 τ".to_string(),
            DriveSpec::TwoFlips { second } => format!(
                "block 1 turned α → −α over 0 ≤ t ≤ 1000 τ and back over {second} ≤ t ≤ {} τ",
                second + 1000.0
            ),
        };
        format!(
            "α = {}°, b/s = {}, N = {}, γ = 0.02, G = 2e-4; {drive}; simulated to t = {} τ",
            self.alpha_deg, self.b, self.n, self.t_end
        )
    }
}

/// One panel of snapshots over time (figures 1c, 3 and 4a).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StripSpec {
    pub label: &'static str,
    pub sim: SimSpec,
    pub times: &'static [f64],
}

/// The static figures drawn from geometry or linear theory.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TheoryFigure {
    UnitSchematic,
    GravityPotential,
    GroundStates,
    Gapless,
    ZeroModes,
    Dispersion,
    Winding,
    EdgeMode,
    Barrier,
}

/// What a scene draws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Content {
    /// Filmstrips of snapshots, one row per strip.
    Strips(&'static [StripSpec]),
    /// Arrival time t_n against n for kink and antikink at each |α|.
    Arrivals(&'static [f64]),
    Theory(TheoryFigure),
    /// A GIF and its kymograph; `follow_kink` moves the view with the kink.
    Movie {
        sim: SimSpec,
        follow_kink: bool,
    },
}

/// A catalogue entry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    pub id: &'static str,
    pub output: Output,
    pub title: &'static str,
    pub caption: &'static str,
    pub content: Content,
}

impl Entry {
    pub fn fidelity(&self) -> Fidelity {
        match self.content {
            Content::Strips(_) | Content::Arrivals(_) | Content::Movie { .. } => {
                Fidelity::Simulation
            }
            Content::Theory(TheoryFigure::UnitSchematic)
            | Content::Theory(TheoryFigure::GroundStates)
            | Content::Theory(TheoryFigure::Gapless) => Fidelity::Drawing,
            Content::Theory(TheoryFigure::GravityPotential)
            | Content::Theory(TheoryFigure::Barrier)
            | Content::Theory(TheoryFigure::ZeroModes) => Fidelity::Formula,
            Content::Theory(_) => Fidelity::LinearTheory,
        }
    }

    /// File names this entry writes.
    pub fn files(&self) -> Vec<String> {
        match self.output {
            Output::Figure => vec![format!("figure-{}.png", self.id)],
            Output::Movie => vec![
                format!("movie-{}.gif", self.id),
                format!("movie-{}-kymograph.png", self.id),
            ],
        }
    }

    /// Parameters in words, for `ladder list` and the gallery.
    pub fn parameters(&self) -> String {
        let model = match self.content {
            Content::Strips(strips) => strips
                .iter()
                .map(|s| s.sim.describe())
                .collect::<Vec<_>>()
                .join(" | "),
            Content::Movie { sim, .. } => sim.describe(),
            Content::Arrivals(alphas) => format!(
                "α = ±{}°, b/s = 1.3, N = 10, T_d = 1000 τ",
                alphas
                    .iter()
                    .map(|a| a.to_string())
                    .collect::<Vec<_>>()
                    .join("°, ±")
            ),
            Content::Theory(_) => String::new(),
        };
        let level = match self.fidelity() {
            Fidelity::Simulation => format!(
                "simulation: {} with {} (arrival times within {SCENE_ARRIVAL_ERROR} τ of a \
                 dopri5 reference at rtol 1e-10, tests/scenes_accuracy.rs)",
                SCENE_INTEGRATOR.kind,
                SCENE_INTEGRATOR.describe_step()
            ),
            f => f.name().to_string(),
        };
        if model.is_empty() {
            level
        } else {
            format!("{model}; {level}")
        }
    }
}

const KINK_60: SimSpec = SimSpec::paper(60.0, 2200.0);
const ANTIKINK_60: SimSpec = SimSpec::paper(-60.0, 3700.0);
const KINK_50: SimSpec = SimSpec::paper(50.0, 1800.0);
const ANTIKINK_50: SimSpec = SimSpec::paper(-50.0, 2400.0);
const KINK_86: SimSpec = SimSpec::paper(86.0, 2800.0);
const ANTIKINK_86: SimSpec = SimSpec::paper(-86.0, 2900.0);
const PAIR_86: SimSpec = SimSpec {
    drive: DriveSpec::TwoFlips { second: 1500.0 },
    ..SimSpec::paper(86.0, 4600.0)
};
const ANNIHILATION_60: SimSpec = SimSpec {
    drive: DriveSpec::TwoFlips { second: 1500.0 },
    ..SimSpec::paper(-60.0, 3600.0)
};
const WATER_TANK: SimSpec = SimSpec {
    b: 1.5,
    ..SimSpec::paper(86.0, 2900.0)
};

/// The catalogue, in the paper's order.
pub const CATALOGUE: &[Entry] = &[
    Entry {
        id: "1c",
        output: Output::Figure,
        title: "Fig. 1c: a kink runs down a nearly symmetric ladder",
        caption: "Simulated analogue of the water-tank sequence: a kink separating the two \
                  orientations of the blocks propagates down the ladder. Time runs from left to right.",
        content: Content::Strips(&[StripSpec {
            label: "",
            sim: WATER_TANK,
            times: &[
                0.0, 800.0, 1100.0, 1400.0, 1700.0, 2000.0, 2300.0, 2600.0, 2900.0,
            ],
        }]),
    },
    Entry {
        id: "2b",
        output: Output::Figure,
        title: "Fig. 2b: one unit of the asymmetric ladder",
        caption: "Two blocks of length s joined by an A link (length a, red) and a B link \
                  (length b, green); θ is the block angle, Δx and Δy the offsets of the centres.",
        content: Content::Theory(TheoryFigure::UnitSchematic),
    },
    Entry {
        id: "2c",
        output: Output::Figure,
        title: "Fig. 2c: the gravitational double well U(θ)",
        caption: "Net gravitational potential per pair of blocks against the zig-zag angle θ \
                  for several a/b at b/s = 1.2, with the ladder at its minimum as an inset.",
        content: Content::Theory(TheoryFigure::GravityPotential),
    },
    Entry {
        id: "2d",
        output: Output::Figure,
        title: "Fig. 2d: the two degenerate ground states",
        caption: "The equilibrium configurations for α = +75° and α = −75°, N = 10: the centres \
                  coincide and only the tilt of the blocks differs.",
        content: Content::Theory(TheoryFigure::GroundStates),
    },
    Entry {
        id: "3",
        output: Output::Figure,
        title: "Fig. 3: finite-amplitude waves, N = 10, b/s = 1.3",
        caption: "(a1) kink α = 60°; (a2) antikink α = −60°, slower, which leaves the last block \
                  unflipped; (b1) kink α = 50°; (b2) antikink α = −50°, pinned near the top. \
                  Time in units of τ = sqrt(m/k).",
        content: Content::Strips(&[
            StripSpec {
                label: "(a1)",
                sim: KINK_60,
                times: &[0.0, 900.0, 1100.0, 1350.0, 1600.0, 1850.0, 2200.0],
            },
            StripSpec {
                label: "(a2)",
                sim: ANTIKINK_60,
                times: &[0.0, 1000.0, 1650.0, 2350.0, 3000.0, 3350.0, 3600.0],
            },
            StripSpec {
                label: "(b1)",
                sim: KINK_50,
                times: &[0.0, 880.0, 1020.0, 1220.0, 1410.0, 1570.0, 1800.0],
            },
            StripSpec {
                label: "(b2)",
                sim: ANTIKINK_50,
                times: &[0.0, 500.0, 900.0, 1200.0, 1600.0, 2000.0, 2400.0],
            },
        ]),
    },
    Entry {
        id: "4a",
        output: Output::Figure,
        title: "Fig. 4a: kink–antikink pair annihilation (simulated)",
        caption: "α = −60°: an antikink launched over 0–1000 τ is caught by the faster kink \
                  launched over 1500–2500 τ; at the collision the blocks pass the criss-cross \
                  configuration and both walls vanish.",
        content: Content::Strips(&[StripSpec {
            label: "",
            sim: ANNIHILATION_60,
            times: &[
                1000.0, 1800.0, 2300.0, 2600.0, 2800.0, 2950.0, 3100.0, 3600.0,
            ],
        }]),
    },
    Entry {
        id: "S3",
        output: Output::Figure,
        title: "Fig. S3: the gapless configuration α = 0",
        caption: "For a² = b² + 4s² the bistability is lost and the ladder takes the \
                  high-symmetry configuration with horizontal blocks (N = 10).",
        content: Content::Theory(TheoryFigure::Gapless),
    },
    Entry {
        id: "S4",
        output: Output::Figure,
        title: "Fig. S4: zero-mode shapes",
        caption: "Deformed zero modes of the N = 10 ladder (black) over the ground state (grey), \
                  b/s = 1.2, α = 75°: (a) m = 1, ε₀ = 0.1; (b) m = 5, ε₀ = 0.05. (a), (b): the model's \
                  true zero modes; (a′), (b′): the paper's eq:zm_n shapes, which stretch the \
                  springs (docs/paper-errata.md item 5).",
        content: Content::Theory(TheoryFigure::ZeroModes),
    },
    Entry {
        id: "S5",
        output: Output::Figure,
        title: "Fig. S5: phonon dispersion",
        caption: "ω±(q)/ω₀ against qb for several α, b/s = 1.3: ω+ red, ω− blue; dashed lines \
                  the printed closed form, solid lines the same × √2 (ω₀ = √(k/m), errata item 9), \
                  dots the eigenvalues of the model's constrained periodic chain.",
        content: Content::Theory(TheoryFigure::Dispersion),
    },
    Entry {
        id: "S6",
        output: Output::Figure,
        title: "Fig. S6: arrival times of kinks and antikinks",
        caption: "Arrival time t_n of the flip at block n for kinks (α > 0) and antikinks \
                  (α < 0), with the fitted speeds in blocks per 1000 τ.",
        content: Content::Arrivals(&[50.0, 60.0, 86.0]),
    },
    Entry {
        id: "winding",
        output: Output::Figure,
        title: "Winding of det C(q)",
        caption: "det C(q) traced over the Brillouin zone in the complex plane for α > 0 \
                  (encloses the origin, n_C = 1) and α < 0 (n_C = 0).",
        content: Content::Theory(TheoryFigure::Winding),
    },
    Entry {
        id: "edge-mode",
        output: Output::Figure,
        title: "The surface zero mode",
        caption: "|δθ_n| of the reduced chain's zero mode against n, numerical (dots) and \
                  e^{−κ n b} (line).",
        content: Content::Theory(TheoryFigure::EdgeMode),
    },
    Entry {
        id: "barrier",
        output: Output::Figure,
        title: "The energy barrier ΔU(α)",
        caption: "Barrier of the criss-cross configuration θ = 0 per pair of blocks against the \
                  equilibrium angle α, b/s = 1.3.",
        content: Content::Theory(TheoryFigure::Barrier),
    },
    movie(
        "3",
        "Movie 3: the kink of movie 4 in the frame moving with it",
        KINK_60,
        true,
    ),
    movie("4", "Movie 4: kink, α = 60°", KINK_60, false),
    movie("5", "Movie 5: antikink, α = −60°", ANTIKINK_60, false),
    movie("6", "Movie 6: kink, α = 50°", KINK_50, false),
    movie(
        "7",
        "Movie 7: antikink, α = −50° (pinned)",
        ANTIKINK_50,
        false,
    ),
    movie("8", "Movie 8: kink, α = 86°", KINK_86, false),
    movie("9", "Movie 9: antikink, α = −86°", ANTIKINK_86, false),
    movie(
        "10",
        "Movie 10: kink and antikink coexisting, α = 86°",
        PAIR_86,
        false,
    ),
    movie(
        "11",
        "Movie 11: pair annihilation, α = −60°",
        ANNIHILATION_60,
        false,
    ),
];

const fn movie(id: &'static str, title: &'static str, sim: SimSpec, follow_kink: bool) -> Entry {
    Entry {
        id,
        output: Output::Movie,
        title,
        caption: title,
        content: Content::Movie { sim, follow_kink },
    }
}

/// The entry of `output` kind with this ID.
pub fn find(output: Output, id: &str) -> Result<&'static Entry> {
    CATALOGUE
        .iter()
        .find(|e| e.output == output && e.id == id)
        .ok_or_else(|| {
            let ids: Vec<&str> = entries(output).map(|e| e.id).collect();
            let what = match output {
                Output::Figure => "figure",
                Output::Movie => "movie",
            };
            Error::bad_input(format!(
                "unknown {what} '{id}'; choose one of {} or all",
                ids.join(", ")
            ))
        })
}

/// Entries of one kind, in catalogue order.
pub fn entries(output: Output) -> impl Iterator<Item = &'static Entry> {
    CATALOGUE.iter().filter(move |e| e.output == output)
}

/// `ladder list`: one line per entry.
pub fn listing() -> String {
    let mut s = String::new();
    for e in CATALOGUE {
        let kind = match e.output {
            Output::Figure => "figure",
            Output::Movie => "movie ",
        };
        s.push_str(&format!(
            "{kind} {:<9} {:<14} {}\n",
            e.id,
            e.fidelity().name(),
            e.title
        ));
    }
    s
}
