//! The ring chain as input: the rings (torus radii, steel), the contact
//! coefficients, the topology (which rings interlock, the two strands,
//! the tapes), the hand that holds and turns the top ring, and the run.
//! Every field has a default, stated and reasoned in docs/rings.md (the
//! paper, Fig. 4b and SI Movie 12, gives no dimensions and no topology).
//! [`RingChain::validated`] refuses bad input with one line (exit 2).

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Standard gravity, m/s².
pub const G: f64 = 9.81;

/// The ring chain of a scene (`[rings]` in a scene file), in SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RingChain {
    /// Number of rings. Default 30.
    pub n: usize,
    /// Centre-line radius R of each ring, m. Default 0.0125 (a 25 mm key ring).
    pub major_radius: f64,
    /// Tube (wire) radius r, m. Default 0.001.
    pub tube_radius: f64,
    /// Density of the wire, kg/m³. Default 7850 (steel).
    pub density: f64,
    /// Coefficient of restitution of a ring on a ring. Default 0.6.
    pub restitution: f64,
    /// Coefficient of (kinetic) friction, steel on steel. Default 0.57.
    pub friction: f64,
    /// Sliding speed, m/s, below which friction is regularised (grows
    /// linearly from 0): a numerical choice, docs/rings.md. Default 0.05.
    pub slip_speed: f64,
    /// Penalty stiffness, as the overlap (a fraction of r) that the weight
    /// of the whole chain makes at one contact. Default 0.05.
    pub overlap: f64,
    /// Linked pairs (ring indices from 0, the top ring). Default: those
    /// of `topology`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub links: Option<Vec<[usize; 2]>>,
    /// The links by name, when `links` is not given: "double" (ring k
    /// with k + 1 and k + 2) or "tumbling" (k with k + 2, and 2j with
    /// 2j + 1: Gardner's tumbling rings, docs/rings.md). Default "double".
    #[serde(skip_serializing_if = "Option::is_none")]
    pub topology: Option<Topology>,
    /// Taped pairs. Default: none.
    pub tapes: Vec<[usize; 2]>,
    /// What a tape is: "weld" (the two rings move as one body) or "link"
    /// (joined at one point, free to turn about it). Default "weld".
    pub tape: TapeKind,
    /// The ring the hand holds (fixed in space, turned by `turn`). Default 0.
    pub held: usize,
    /// How the hand turns the held ring. Default: half a turn about the
    /// horizontal axis at azimuth 90°, from 0.3 s over 0.2 s.
    pub turn: Turn,
    /// Whether the hand, instead of turning the held ring, lets it go at
    /// `turn.start` and holds the other strand's top ring (ring held + 1)
    /// where it is then (the paper's "releasing the top ring", and its
    /// "retrieving a top ring of one of two strands"; docs/rings.md).
    /// Default false.
    pub release: bool,
    /// Whether the chain is built as the mirror image (x → −x) of the
    /// default one. Default false.
    pub mirror: bool,
    /// End of the run, s. Default 3.
    pub t_end: f64,
    /// Time step, s; 0 takes it from the contact frequency (docs/rings.md).
    /// Default 0.
    pub dt: f64,
    /// Check every linked pair every this many steps. Default 20.
    pub guard_every: usize,
    /// The leaning start: the chain built leaning and let settle before
    /// the run (`leaning = { angle = 30.0, squeeze = 0.7 }`, its keys in
    /// [`super::start`]). Default none: the chain as built.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leaning: Option<super::start::Leaning>,
    /// The alternating hand: instead of turning the held ring, the hand
    /// passes the chain from one strand's top ring to the other's, again
    /// and again (`alternate = { start = 0.3, period = 0.6, count = 4 }`,
    /// its keys in [`super::alternate`]; the paper's "retrieving a top
    /// ring of one of two strands alternately"). Default none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alternate: Option<super::alternate::Alternate>,
}

/// The chain's links by name (`topology` in `[rings]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Topology {
    /// Ring k linked with k + 1 and k + 2: every ring threaded by its two
    /// neighbours of the other strand.
    Double,
    /// Ring k linked with k + 2 (each strand a simple chain) and ring 2j
    /// with 2j + 1 (a rung every other ring): the tumbling rings of
    /// magicians (Gardner's "Afghan rings"), the key-ring chain the paper
    /// cites for Fig. 4b.
    Tumbling,
}

impl<'de> Deserialize<'de> for Topology {
    /// One of the names; anything else one line naming what the key
    /// takes (serde says "wanted string or table" of a number).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            Word(String),
            Other(serde::de::IgnoredAny),
        }
        let bad = |got: &str| {
            <D::Error as serde::de::Error>::custom(format!(
                "must be \"double\" or \"tumbling\", got {got}"
            ))
        };
        match Raw::deserialize(d)? {
            Raw::Word(w) if w == "double" => Ok(Self::Double),
            Raw::Word(w) if w == "tumbling" => Ok(Self::Tumbling),
            Raw::Word(w) => Err(bad(&format!("\"{w}\""))),
            Raw::Other(_) => Err(bad("another kind of value")),
        }
    }
}

/// What a tape does to the two rings it joins.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TapeKind {
    /// A stiff joint at three points: the two rings turn as one body.
    Weld,
    /// A stiff joint at one point (their crossing): the rings turn freely
    /// about it.
    Link,
}

/// The hand's turn of the held ring: half a turn (or `angle`) about a
/// horizontal axis, smoothly (the ladder's drive profile, docs/model.md).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Turn {
    /// When it starts, s.
    pub start: f64,
    /// How long it takes, s; 0 holds the ring still.
    pub duration: f64,
    /// Angle turned, degrees.
    pub angle: f64,
    /// Azimuth of the horizontal axis, degrees from +x.
    pub azimuth: f64,
}

impl Default for Turn {
    fn default() -> Self {
        Turn {
            start: 0.3,
            duration: 0.2,
            angle: 180.0,
            azimuth: 90.0,
        }
    }
}

impl Default for RingChain {
    fn default() -> Self {
        RingChain {
            n: 30,
            major_radius: 0.0125,
            tube_radius: 0.001,
            density: 7850.0,
            restitution: 0.6,
            friction: 0.57,
            slip_speed: 0.05,
            overlap: 0.05,
            links: None,
            topology: None,
            tapes: Vec::new(),
            tape: TapeKind::Weld,
            held: 0,
            turn: Turn::default(),
            release: false,
            mirror: false,
            t_end: 3.0,
            dt: 0.0,
            guard_every: 20,
            leaning: None,
            alternate: None,
        }
    }
}

/// Largest number of rings.
pub const MAX_RINGS: usize = 400;

impl RingChain {
    /// The linked pairs, `i < j`, sorted: as given, or the default.
    pub fn linked_pairs(&self) -> Vec<[usize; 2]> {
        let mut pairs: Vec<[usize; 2]> = match (&self.links, self.topology) {
            (Some(l), _) => l.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect(),
            (None, Some(Topology::Tumbling)) => Self::tumbling_links(self.n),
            (None, _) => Self::double_links(self.n),
        };
        pairs.sort();
        pairs.dedup();
        pairs
    }

    /// The tumbling rings' links (Gardner's "Afghan rings", the chain of
    /// key rings the paper cites): ring k with k + 2 (each strand a simple
    /// chain) and ring 2j with 2j + 1 (a rung every other ring).
    pub fn tumbling_links(n: usize) -> Vec<[usize; 2]> {
        let mut pairs = Self::double_links(n);
        pairs.retain(|p| p[1] == p[0] + 2 || p[0].is_multiple_of(2));
        pairs
    }

    /// The double chain's links, sorted: ring k with k + 1 and k + 2.
    pub fn double_links(n: usize) -> Vec<[usize; 2]> {
        let mut pairs: Vec<[usize; 2]> = (0..n)
            .flat_map(|k| [[k, k + 1], [k, k + 2]])
            .filter(|p| p[1] < n)
            .collect();
        pairs.sort();
        pairs
    }

    /// Whether the chain's links are the tumbling rings'.
    /// (At least 4 rings: below that the links are no two strands.)
    pub fn is_tumbling(&self) -> bool {
        self.n >= 4 && self.linked_pairs() == Self::tumbling_links(self.n)
    }

    /// The strand of ring k (0 or 1): rings of one parity.
    pub fn strand(k: usize) -> usize {
        k % 2
    }

    /// Mass of one ring, kg: ρ · 2π²Rr² (a torus).
    pub fn mass(&self) -> f64 {
        self.density
            * 2.0
            * std::f64::consts::PI.powi(2)
            * self.major_radius
            * self.tube_radius.powi(2)
    }

    /// Moments of inertia of a torus, (about a diameter, about the axis):
    /// m(½R² + ⅝r²) and m(R² + ¾r²).
    pub fn inertia(&self) -> (f64, f64) {
        let (m, r_c, r_t) = (self.mass(), self.major_radius, self.tube_radius);
        (
            m * (0.5 * r_c * r_c + 0.625 * r_t * r_t),
            m * (r_c * r_c + 0.75 * r_t * r_t),
        )
    }

    /// Refuses what cannot be a ring chain, with one line.
    pub fn validated(&self) -> Result<&Self> {
        let bad = |m: String| Err(Error::bad_input(format!("rings: {m}")));
        let positive = [
            ("major_radius", self.major_radius),
            ("tube_radius", self.tube_radius),
            ("density", self.density),
            ("slip_speed", self.slip_speed),
            ("overlap", self.overlap),
            ("t_end", self.t_end),
        ];
        for (name, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return bad(format!("{name} must be a number above 0, got {v}"));
            }
        }
        if !(2..=MAX_RINGS).contains(&self.n) {
            return bad(format!(
                "n must be between 2 and {MAX_RINGS}, got {}",
                self.n
            ));
        }
        if self.tube_radius >= 0.5 * self.major_radius {
            return bad(format!(
                "the tube radius r = {} m must be below half the ring radius R = {} m (R ≤ 2r \
                 leaves no hole for another ring to pass through)",
                self.tube_radius, self.major_radius
            ));
        }
        if !(0.0..=1.0).contains(&self.restitution) {
            return bad(format!(
                "restitution must be between 0 and 1, got {}",
                self.restitution
            ));
        }
        if !(self.friction.is_finite() && (0.0..=2.0).contains(&self.friction)) {
            return bad(format!(
                "friction must be between 0 and 2, got {}",
                self.friction
            ));
        }
        if self.overlap > 0.5 {
            return bad(format!(
                "overlap must be at most 0.5 (of r), got {}",
                self.overlap
            ));
        }
        if !(self.dt.is_finite() && self.dt >= 0.0) {
            return bad(format!(
                "dt must be 0 (automatic) or a step in s, got {}",
                self.dt
            ));
        }
        if self.guard_every == 0 {
            return bad("guard_every must be at least 1".into());
        }
        if self.t_end > 600.0 {
            return bad(format!("t_end must be at most 600 s, got {}", self.t_end));
        }
        self.check_turn()?;
        self.check_tumbling()?;
        self.check_pairs()?;
        if let Some(l) = &self.leaning {
            l.validated()?;
        }
        self.check_alternate()?;
        Ok(self)
    }

    fn check_turn(&self) -> Result<()> {
        let t = &self.turn;
        for (name, v) in [("start", t.start), ("duration", t.duration)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::bad_input(format!(
                    "rings: turn.{name} must be 0 or more seconds, got {v}"
                )));
            }
        }
        if !(t.angle.is_finite() && t.angle.abs() <= 720.0 && t.azimuth.is_finite()) {
            return Err(Error::bad_input(format!(
                "rings: turn.angle must be within ±720° and turn.azimuth a number, got {} and {}",
                t.angle, t.azimuth
            )));
        }
        Ok(())
    }

    /// Refuses `links` beside `topology` (two answers to one question),
    /// and the leaning start on the tumbling rings (its guess leans the
    /// double chain as built).
    fn check_tumbling(&self) -> Result<()> {
        if self.links.is_some() && self.topology.is_some() {
            return Err(Error::bad_input(
                "rings: links and topology both say which rings interlock: give one".to_string(),
            ));
        }
        if self.topology == Some(Topology::Tumbling) && self.n < 4 {
            return Err(Error::bad_input(format!(
                "rings: the tumbling rings need at least 4 rings (two strands), got n = {}",
                self.n
            )));
        }
        if self.is_tumbling() && self.leaning.is_some() {
            return Err(Error::bad_input(
                "rings: the tumbling rings always settle from their own guess, and leaning leans \
                 the double chain: leave leaning out"
                    .to_string(),
            ));
        }
        Ok(())
    }

    /// Refuses what the alternating hand cannot do: a value out of its
    /// keys' ranges, a second hand (`release`), or a chain that is not the
    /// double chain (ring k linked with k + 1 and k + 2) or the tumbling
    /// rings, whose two strands are the even and the odd rings.
    fn check_alternate(&self) -> Result<()> {
        let Some(a) = &self.alternate else {
            return Ok(());
        };
        a.validated()?;
        if self.release {
            return Err(Error::bad_input(
                "rings: alternate and release = true are two hands: give one".to_string(),
            ));
        }
        if self.linked_pairs() != Self::double_links(self.n) && !self.is_tumbling() {
            return Err(Error::bad_input(
                "rings: alternate passes the hand between the two strands of the double chain \
                 (ring k linked with k + 1 and k + 2) or of the tumbling rings, and these links \
                 are neither"
                    .to_string(),
            ));
        }
        Ok(())
    }

    fn check_pairs(&self) -> Result<()> {
        if self.held >= self.n {
            return Err(Error::bad_input(format!(
                "rings: held ring {} is not one of the {} rings (0 to {})",
                self.held,
                self.n,
                self.n - 1
            )));
        }
        let links = self.linked_pairs();
        if self.release && !links.contains(&[self.held, self.held + 1]) {
            return Err(Error::bad_input(format!(
                "rings: release = true passes the chain from ring {} to ring {}, which must be \
                 a ring linked with it",
                self.held,
                self.held + 1
            )));
        }
        for (what, list) in [("link", &links), ("tape", &self.tapes)] {
            for &[a, b] in list.iter() {
                if a >= self.n || b >= self.n || a == b {
                    return Err(Error::bad_input(format!(
                        "rings: a {what} between rings {a} and {b}: rings are numbered 0 to {} \
                         and a {what} joins two different rings",
                        self.n - 1
                    )));
                }
            }
        }
        // Every ring hangs from the held one through the links.
        let mut reached = vec![false; self.n];
        reached[self.held] = true;
        let mut grew = true;
        while grew {
            grew = false;
            for &[a, b] in &links {
                if reached[a] != reached[b] {
                    reached[a] = true;
                    reached[b] = true;
                    grew = true;
                }
            }
        }
        if let Some(k) = reached.iter().position(|r| !r) {
            return Err(Error::bad_input(format!(
                "rings: ring {k} is linked to no chain that reaches the held ring {}: the links \
                 must connect every ring",
                self.held
            )));
        }
        Ok(())
    }
}

/// Words for captions and the gallery (docs/rings.md).
impl RingChain {
    /// The partner (odd) strand taped, ring k to ring k + 2 for every odd
    /// k with k + 2 in the chain: the tapes of figure 4b and movie 12
    /// (docs/rings.md).
    pub fn odd_strand_tapes(&self) -> Vec<[usize; 2]> {
        (1..self.n)
            .step_by(2)
            .filter(|k| k + 2 < self.n)
            .map(|k| [k, k + 2])
            .collect()
    }
}

impl RingChain {
    /// "30 rings, R = 12.5 mm, r = 1 mm, e = 0.6, μ = 0.57, 14 tapes".
    pub fn parameters(&self) -> String {
        format!(
            "{} {}rings, R = {} mm, r = {} mm, e = {}, μ = {}{}{}",
            self.n,
            if self.is_tumbling() { "tumbling " } else { "" },
            self.major_radius * 1e3,
            self.tube_radius * 1e3,
            self.restitution,
            self.friction,
            if self.tapes.is_empty() {
                String::new()
            } else {
                format!(", {} tapes", self.tapes.len())
            },
            if self.mirror { ", mirrored" } else { "" }
        )
    }

    /// How the pictures are computed.
    pub fn model_level() -> &'static str {
        "Simulated in 3D: rigid steel rings with contact between their tubes (Hertz with \
         Hunt–Crossley damping, regularised Coulomb friction), every linked pair checked still \
         linked as it runs (docs/rings.md)."
    }

    /// What the kymograph shows.
    pub fn kymograph_words() -> &'static str {
        "Kymograph: the azimuth of each ring's normal (across: the even strand, then the odd) \
         against time (down), on a colour wheel, paler where the ring lies flat; dots mark flips"
    }
}
