//! The low-level arguments: what clap collects, as typed by the user, with
//! no validation beyond parsing. `convert` turns them into scenes and
//! options; nothing here builds physics.

use crate::scene::Model;
use crate::scene::params::Param;
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

mod limits;
mod params;
mod sweep;
pub use limits::{DataLimitArgs, LimitArgs, PixelLimitArgs, SimLimitArgs, TheoryLimitArgs};
pub use params::{GridFlags, ParamFlags};
pub use sweep::{GridArgs, SweepArgs, SweepCommand};

#[derive(Parser, Debug)]
#[command(
    name = "ladder",
    version = crate::version::LONG,
    about = "Simulate the Jacob's-ladder toy and render the figures and movies of \
             \"Topological antiqued mechanical toy\" (Wada, Mizobata, Ueno, Yoneda)",
    long_about = "Simulate the Jacob's-ladder toy and render the figures and movies of \
                  \"Topological antiqued mechanical toy\" (Wada, Mizobata, Ueno, Yoneda).\n\n\
                  Every output is a scene: a model, a drive of block 1, a time window, an \
                  integrator and a picture. The paper's figures and movies are built-in scenes \
                  (`ladder list`, `ladder scene ID`); your own ladder comes from the model flags \
                  of `movie` and `figure`, or from a TOML scene file (`ladder render FILE`; the \
                  keys are in docs/scenes.md).\n\n\
                  Limits: N up to 100000 blocks (the linear theory up to 400); a simulation \
                  up to 1e10 steps × N and 5e7 samples × N; a movie up to 5000 frames, 4096 \
                  pixels a side and 5e9 frames × pixels. Time and memory grow linearly in each \
                  (docs/limits.md); the --max-* flags of the commands they limit raise the caps.",
    allow_negative_numbers = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

// One value per process, parsed once: boxing the large variants buys nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Simulate a kink (alpha > 0) or antikink (alpha < 0) driven from the top block
    Simulate(SimulateArgs),
    /// Render a movie: a built-in one by ID, all of them, or your own from the model flags
    Movie(MovieArgs),
    /// Render a figure: a built-in one by ID, all of them, or a filmstrip of your own ladder
    Figure(FigureArgs),
    /// Render scene files (TOML; see docs/scenes.md)
    Render(RenderArgs),
    /// Print a built-in scene as a TOML scene file
    Scene(SceneArgs),
    /// Render every figure and movie, plus OUT/index.html
    All(AllArgs),
    /// List the built-in figures and movies, one line each
    List,
    /// Linear theory of the ladder: potential, zero modes, winding, dispersion
    Theory(TheoryArgs),
    /// Measure the integrators: speed against accuracy, stability limits, kernels
    Bench(BenchArgs),
    /// Run a scene over a grid of parameters and say what the wave did in
    /// each run (propagated, annihilated, stalled, pinned, diverged,
    /// undecided or failed); shard it over processes or machines and gather
    /// the shards
    Sweep(SweepArgs),
    /// Print a shell completion script: `ladder completions bash >
    /// ~/.local/share/bash-completion/completions/ladder` (zsh, fish,
    /// powershell and elvish too)
    Completions(CompletionsArgs),
    /// Print the manual page (roff): `ladder man > ladder.1; man ./ladder.1`
    Man,
}

#[derive(Args, Debug)]
pub struct CompletionsArgs {
    /// The shell: bash, zsh, fish, powershell or elvish
    #[arg(value_name = "SHELL")]
    pub shell: clap_complete::Shell,
}

#[derive(Args, Debug, Clone)]
pub struct OutArgs {
    /// Output folder (created if missing); files are named after the
    /// scene, e.g. DIR/figure-3.pdf
    #[arg(long, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// List every file written, one path a line on stderr, before the summary
    #[arg(short, long)]
    pub verbose: bool,
}

/// The model of a scene (`[model]` of a scene file). Each flag left out
/// keeps the base scene's value (the paper's, or the built-in scene's).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Model (defaults: the paper's values)")]
pub struct ModelArgs {
    /// `--alpha`, `--n`, `--b`, `--gamma`, `--gravity`, `--inertia`: one
    /// flag per parameter of the model's table (`model::table`).
    #[command(flatten)]
    pub params: ParamFlags,
    // How the run starts.
    #[arg(long, value_name = "START", help = with_default(
        "How the run starts: ground (at rest, springs at rest length) or relaxed (at rest \
         hanging under gravity, block 1 clamped)",
        crate::sim::Start::default(),
    ))]
    pub start: Option<StartArg>,
    /// The ladder as built, in cm, g and s (docs/experiments.md): a TOML file
    /// whose [apparatus] table has the keys of a scene file's
    /// (docs/experiments.md); it replaces the scene's apparatus
    #[arg(long, value_name = "FILE")]
    pub apparatus: Option<PathBuf>,
    /// The medium of the scene's apparatus (from --apparatus or the
    /// built-in scene): air or water, each at its own density
    #[arg(long, value_name = "MEDIUM")]
    pub medium: Option<MediumArg>,
}

/// `--medium`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MediumArg {
    Air,
    Water,
}

/// `--start`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum StartArg {
    Ground,
    Relaxed,
}

/// The drive of block 1 (`[drive]`).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Drive of block 1")]
pub struct DriveArgs {
    // The drive time T_d (the table's `drive_time`)
    #[arg(long, value_name = Param::DriveTime.spec().value_name, help = Param::DriveTime.help(true))]
    pub drive_time: Option<f64>,
    // Start times of the flips of block 1.
    #[arg(long, value_name = "T1,T2,..", value_delimiter = ',', num_args = 1..,
          help = with_default(
              "Start times of the flips of block 1, comma-separated; each flip turns it to the other ground state over the drive time",
              crate::scene::Flip::default().start,
          ))]
    pub flips: Option<Vec<f64>>,
    /// Turn block 1 back (-alpha -> alpha) from T as well: the same as --flips 0,T
    #[arg(long, value_name = "T", conflicts_with = "flips")]
    pub second_flip: Option<f64>,
}

/// `--t-end`: a time in τ, or `auto` (the scene's `t_end = "auto"`,
/// [`crate::scene::AUTO_T_END`]). Its range is the scene's check's.
fn parse_t_end(s: &str) -> std::result::Result<f64, String> {
    if s.trim() == "auto" {
        return Ok(crate::scene::AUTO_T_END);
    }
    s.trim()
        .parse()
        .map_err(|_| format!("expected a time in tau or auto, got '{s}'"))
}

/// The window and integrator (`[run]`).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Run")]
pub struct RunArgs {
    /// End time, in units of tau = sqrt(m/k), or auto (until every wave
    /// has a fate) [default: the scene's; auto for your own]
    #[arg(long, value_name = "T", value_parser = parse_t_end)]
    pub t_end: Option<f64>,
    /// auto (choose the method and step, then verify the arrival times to
    /// --tolerance), explicit-euler, symplectic-euler (the paper's),
    /// verlet, rk4, or dopri5 [default: the scene's; auto for your own]
    #[arg(long, value_name = "NAME")]
    pub integrator: Option<String>,
    // The step of a fixed-step integrator.
    #[arg(long, value_name = "DT", help = with_default(
        "Time step of a fixed-step integrator (first trial step for dopri5); auto picks its own",
        crate::scene::DEFAULT_DT,
    ))]
    pub dt: Option<f64>,
    #[command(flatten)]
    pub tol: ToleranceArgs,
}

/// The adaptive integrators' tolerances, under the heading of the struct
/// that flattens them ("Run").
#[derive(Args, Debug, Clone, Default)]
pub struct ToleranceArgs {
    // The tolerance of dopri5.
    #[arg(long, value_name = "R", help = with_default(
        "Error tolerance of dopri5 (relative and absolute)",
        crate::scene::DEFAULT_RTOL,
    ))]
    pub rtol: Option<f64>,
    // The tolerance of auto.
    #[arg(long, value_name = "T", help = with_default(
        "Largest arrival-time error auto accepts, in tau",
        crate::scene::Run::default().tolerance,
    ))]
    pub tolerance: Option<f64>,
}

#[derive(Args, Debug)]
#[command(
    allow_negative_numbers = true,
    // The run flags' defaults are `simulate`'s ([`simulate_run`]).
    mut_arg("t_end", |a| a.help(with_default(
        "End time, in units of tau = sqrt(m/k)",
        simulate_run().t_end,
    ))),
    mut_arg("integrator", |a| a.help(with_default(
        "explicit-euler, symplectic-euler (the paper's), verlet, rk4, dopri5, moreau \
         (inextensible ribbons only), or auto (velocity Verlet with its step chosen and \
         verified to --tolerance)",
        simulate_run().integrator,
    ))),
)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub drive: DriveArgs,
    /// --t-end, --integrator, --dt, --rtol and --tolerance, defaults
    /// [`simulate_run`]'s.
    #[command(flatten)]
    pub run: RunArgs,
    /// Print one JSON object instead of a table
    #[arg(long, help_heading = "Output")]
    pub json: bool,
    /// Write theta_n(t) in degrees (wrapped to (-180, 180]) at the sample
    /// times to this CSV file, and its provenance (program, version,
    /// commit, scene) to the JSON sidecar FILE.json
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub csv: Option<PathBuf>,
    /// Write the whole state at the sample times to this NumPy .npz file: t,
    /// theta (radians), x, y, vx, vy, omega (samples x N), the energies and
    /// metadata (the file's provenance, JSON text)
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub npz: Option<PathBuf>,
    /// Interval between CSV and npz samples, in tau
    #[arg(
        long,
        default_value_t = 10.0,
        value_name = "T",
        help_heading = "Output"
    )]
    pub sample_every: f64,
    /// Code that takes symplectic Euler's steps (the other integrators use
    /// the portable loop): the fused kernel (N <= 32) or the chain kernel
    /// (longer ladders) for the best instruction set of this CPU, the one
    /// for a given set, or the portable loop. All give the same numbers,
    /// bit for bit; only the time differs
    #[arg(long, value_enum, default_value_t = KernelArg::Fastest, value_name = "KERNEL", help_heading = "Output")]
    pub kernel: KernelArg,
    #[command(flatten)]
    pub limits: SimLimitArgs,
}

/// The window and integrator of `ladder simulate` where its flags give
/// none: the paper's run, [0, 4000 τ] with symplectic Euler at dt =
/// 0.01 (`Run::default`'s window; the paper's integrator, not `auto`).
pub fn simulate_run() -> crate::scene::Run {
    crate::scene::Run {
        integrator: crate::scene::Method::Fixed(crate::sim::IntegratorKind::SymplecticEuler),
        ..crate::scene::Run::default()
    }
}

/// A help text with its default read from the program: "TEXT [default:
/// VALUE]" (2e-4, 1e10: exponent form where shorter).
pub(super) fn with_default(text: &str, value: impl std::fmt::Display) -> String {
    let v = value.to_string();
    let v = match v.parse::<f64>() {
        Ok(x) => crate::model::table::short(x),
        Err(_) => v,
    };
    format!("{text} [default: {v}]")
}

/// `simulate --kernel`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum KernelArg {
    Fastest,
    Avx2,
    Avx512,
    Portable,
}

#[derive(Args, Debug, Clone)]
pub struct MovieFormat {
    /// Frames per movie (2..=5000)
    #[arg(long, default_value_t = render_defaults().frames, help_heading = "Movie format")]
    pub frames: usize,
    /// Frame size WxH in pixels, each side 64 to 4096
    #[arg(long, default_value = crate::front::options::DEFAULT_SIZE, value_name = "WxH", value_parser = crate::front::options::parse_size, help_heading = "Movie format")]
    pub size: (u32, u32),
    /// Frames per second
    #[arg(long, default_value_t = render_defaults().fps, help_heading = "Movie format")]
    pub fps: f64,
    /// Quality of MP4 movies: draft, standard, high or best (H.264
    /// quantiser 30, 24, 18, 12; each step about 1.5 to 2 times the bytes;
    /// docs/formats.md gives sizes and PSNR against the GIF)
    #[arg(
        long,
        value_enum,
        default_value_t = QualityArg::of(render_defaults().quality),
        value_name = "LEVEL",
        help_heading = "Movie format"
    )]
    pub quality: QualityArg,
}

/// `--quality` of MP4 movies (`encode::Mp4Quality`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum QualityArg {
    Draft,
    Standard,
    High,
    Best,
}

impl QualityArg {
    /// The flag's word for the encoder's level.
    pub fn of(q: crate::encode::Mp4Quality) -> Self {
        use crate::encode::Mp4Quality as Q;
        match q {
            Q::Draft => Self::Draft,
            Q::Standard => Self::Standard,
            Q::High => Self::High,
            Q::Best => Self::Best,
        }
    }
}

/// The render options' defaults (`front::options::RenderOptions`, which
/// holds every one), for the flags' defaults.
fn render_defaults() -> crate::front::options::RenderOptions {
    crate::front::options::RenderOptions::default()
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct MovieArgs {
    /// Movie ID (see `ladder list`) or all; leave it out to make your own
    /// movie from the model flags
    pub id: Option<String>,
    /// Name of your movie's files: movie-NAME.gif, movie-NAME-kymograph.png,
    /// movie-NAME.json [default: made from what differs from the paper (or
    /// from the movie ID given), e.g. a70-n20 or 4-a70]
    #[arg(long, value_name = "NAME")]
    pub name: Option<String>,
    // The camera.
    #[arg(long, value_name = "CAMERA", help = with_default(
        "Camera: auto (fixed when the ladder fits the frame, else folded into columns), fixed \
         (one window for every frame) or follow (moves with the kink)",
        serde_json::to_value(crate::scene::Camera::default())
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default(),
    ))]
    pub camera: Option<CameraArg>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub drive: DriveArgs,
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub format: MovieFormat,
    /// File formats, comma-separated: gif, mp4 for the movie (H.264; frame
    /// width and height must be even); png, svg, pdf for its kymograph
    /// (png if none)
    #[arg(
        long = "format",
        default_value_t = crate::scenes::Outputs::default().movies.to_string(),
        value_name = "LIST",
        help_heading = "Movie format"
    )]
    pub formats: String,
    /// Scale of the kymograph's PNG: 2 draws it with twice the pixels each
    /// way (0.25..=8)
    #[arg(
        long,
        default_value_t = render_defaults().scale,
        value_name = "S",
        help_heading = "Movie format"
    )]
    pub scale: f32,
    #[command(flatten)]
    pub limits: SimLimitArgs,
    #[command(flatten)]
    pub pixel_limits: PixelLimitArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CameraArg {
    Auto,
    Fixed,
    Follow,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct FigureArgs {
    /// Figure ID (see `ladder list`) or all; leave it out to draw your own
    /// ladder from the model flags
    pub id: Option<String>,
    /// Name of your figure's files: figure-NAME.png, figure-NAME.json
    /// [default: made from what differs from the paper (or from the figure
    /// ID given), e.g. a70-n20 or 3-n20]
    #[arg(long, value_name = "NAME")]
    pub name: Option<String>,
    /// What your figure shows: a filmstrip of snapshots, the kymograph of
    /// sin theta_n, or the arrival times t_n [default: filmstrip]
    #[arg(long, value_name = "VIEW")]
    pub view: Option<ViewArg>,
    /// Times of the filmstrip's snapshots, comma-separated, in tau
    /// [default: seven times evenly over the window]
    #[arg(long, value_name = "T1,T2,..", value_delimiter = ',', num_args = 1..)]
    pub times: Option<Vec<f64>>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub drive: DriveArgs,
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub figure_format: FigureFormat,
    #[command(flatten)]
    pub limits: SimLimitArgs,
    #[command(flatten)]
    pub theory_limits: TheoryLimitArgs,
}

/// `--format` and `--scale` of figures.
#[derive(Args, Debug, Clone)]
pub struct FigureFormat {
    /// File formats, comma-separated: png, svg, pdf (SVG and PDF are vector,
    /// with real text; pdflatex includes the PDF)
    #[arg(
        long = "format",
        default_value_t = crate::scenes::Outputs::default().figures.to_string(),
        value_name = "LIST",
        help_heading = "Figure format"
    )]
    pub formats: String,
    /// Scale of PNG figures: 2 draws the same layout with twice the pixels
    /// each way (0.25..=8)
    #[arg(
        long,
        default_value_t = render_defaults().scale,
        value_name = "S",
        help_heading = "Figure format"
    )]
    pub scale: f32,
    /// Not a figure's option (movies take `--size`): taken only to refuse
    /// it with a pointer to `--scale`.
    #[arg(long, hide = true, value_name = "WxH")]
    pub size: Option<String>,
    #[command(flatten)]
    pub style: StyleArgs,
}

/// How figures look and the page they are printed on (docs/formats.md).
#[derive(Args, Debug, Clone, Default)]
pub struct StyleArgs {
    /// paper (APS column, 3.375 in, 8 pt, serif), paper-wide (7 in),
    /// slide (13.333 x 7.5 in, 20 pt) or screen (pixels; the default)
    #[arg(long, value_name = "NAME", help_heading = "Figure style")]
    pub style: Option<String>,
    /// Page width with a unit: 3.375in, 86mm, 243pt, 640px
    #[arg(long, value_name = "LENGTH", help_heading = "Figure style")]
    pub width: Option<String>,
    /// Page height with a unit (default: the figure's own aspect ratio)
    #[arg(long, value_name = "LENGTH", help_heading = "Figure style")]
    pub height: Option<String>,
    /// Text size in points (axis labels; ticks and titles follow)
    #[arg(long, value_name = "PT", help_heading = "Figure style")]
    pub font_size: Option<f32>,
    /// sans or serif
    #[arg(long, value_name = "FACE", help_heading = "Figure style")]
    pub font: Option<String>,
    /// Pixels per inch of PNG figures at a print style
    #[arg(long, value_name = "DPI", help_heading = "Figure style")]
    pub dpi: Option<f32>,
    /// Text in SVG and PDF: text (the font embedded) or outlines
    #[arg(long, value_name = "MODE", help_heading = "Figure style")]
    pub text: Option<String>,
}

/// `--format` and `--scale` of commands that write figures and movies.
#[derive(Args, Debug, Clone)]
pub struct MixedFormat {
    /// File formats, comma-separated: png, svg, pdf for figures; gif, mp4
    /// for movies (a kind left out keeps its default, png or gif)
    #[arg(
        long = "format",
        default_value_t = render_defaults().formats,
        value_name = "LIST",
        help_heading = "Format"
    )]
    pub formats: String,
    /// Scale of PNG figures: 2 draws the same layout with twice the pixels
    /// each way (0.25..=8)
    #[arg(long, default_value_t = render_defaults().scale, value_name = "S", help_heading = "Format")]
    pub scale: f32,
    #[command(flatten)]
    pub style: StyleArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ViewArg {
    Filmstrip,
    Kymograph,
    Arrivals,
    /// The energies against t/τ (kinetic, elastic, gravitational,
    /// dissipated, and the totals)
    Energy,
}

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Scene files (TOML)
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
    /// Only read and check the files, print what each would make, and
    /// write nothing
    #[arg(long)]
    pub check: bool,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub format: MovieFormat,
    #[command(flatten)]
    pub formats: MixedFormat,
    #[command(flatten)]
    pub limits: SimLimitArgs,
    #[command(flatten)]
    pub pixel_limits: PixelLimitArgs,
    #[command(flatten)]
    pub theory_limits: TheoryLimitArgs,
}

#[derive(Args, Debug)]
pub struct SceneArgs {
    /// Built-in figure or movie ID (see `ladder list`), optionally after
    /// its kind: `3` is figure 3; `movie 3` (or `movie-3`) is movie 3
    #[arg(num_args = 1..=2, value_name = "[KIND] ID", required = true)]
    pub id: Vec<String>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct AllArgs {
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub format: MovieFormat,
    #[command(flatten)]
    pub formats: MixedFormat,
    #[command(flatten)]
    pub limits: SimLimitArgs,
    #[command(flatten)]
    pub pixel_limits: PixelLimitArgs,
    #[command(flatten)]
    pub theory_limits: TheoryLimitArgs,
    /// After the render, print on standard output where the time went: each
    /// figure's and movie's wall time (they render in parallel, so these
    /// overlap), the runs it simulated and their block-steps (steps × blocks),
    /// slowest first, then the whole render's wall time and the process's CPU
    /// time (user + system, every thread). The files written are the same
    /// with or without it (docs/performance.md)
    #[arg(long)]
    pub timings: bool,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct TheoryArgs {
    // The table's `alpha` (|alpha| <= 90: the theory takes 0 and 90)
    #[arg(long, default_value_t = Model::default().alpha, value_name = Param::Alpha.spec().value_name,
          help = theory_help(Param::Alpha, &Param::Alpha.spec().range_text(false)))]
    pub alpha: f64,
    // The table's `b`
    #[arg(long, default_value_t = Model::default().b, value_name = Param::B.spec().value_name,
          help = theory_help(Param::B, &Param::B.spec().range_text(false)))]
    pub b: f64,
    // The table's `n`, up to the theory's largest chain
    #[arg(long, default_value_t = Model::default().n, value_name = Param::N.spec().value_name,
          help = theory_help(Param::N, &format!("from 2 to {}", crate::limits::MAX_THEORY_BLOCKS)))]
    pub n: usize,
    /// Print one JSON object instead of a table
    #[arg(long)]
    pub json: bool,
}

/// A theory flag's help: the table's words and the theory's range
/// (clap adds the default).
fn theory_help(p: Param, range: &str) -> String {
    format!("{}, {range}", p.spec().doc)
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BenchArgs {
    /// work-precision (error against cost), stability (critical time
    /// steps), kernels (the paper's run timed with each `simulate
    /// --kernel`; prints only, writes no file), or cost (each force
    /// path's ns per block-step, the caps' cost model; prints only)
    #[arg(value_name = "STUDY")]
    pub study: String,
    /// Output folder for the chart and its CSV
    #[arg(long, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Print one JSON object instead of a table
    #[arg(long)]
    pub json: bool,
    /// Repeats per work-precision point, or rounds of bench kernels and
    /// bench cost (the median wall time is kept)
    #[arg(long, default_value_t = 3)]
    pub repeats: usize,
    /// The scene of work-precision and stability: paper (the paper's kink
    /// and antikink; stability sweeps alpha) or a built-in movie's ID,
    /// e.g. water-tank (buoyancy, added mass, quadratic drag), whose terms
    /// some integrators refuse
    #[arg(long, default_value = "paper", value_name = "NAME")]
    pub scene: String,
    /// Window of a built-in movie's study, in tau [default: the movie's]
    #[arg(long, value_name = "T")]
    pub t_end: Option<f64>,
    /// The caps on the study's runs, all its runs together
    #[command(flatten)]
    pub limits: SimLimitArgs,
}
