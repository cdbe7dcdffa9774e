//! The checks of every `[apparatus]` value: the first bad one is named by
//! its key, which the file loader locates.
//!
//! Two passes: each value on its own ([`Apparatus::check_values`]), then
//! what the values give together in the model's units
//! ([`Apparatus::check_converted`]: the block's mass and the medium's terms
//! per unit mass, τ = √(m/k), G, the motor's T_d, the run's window in τ).
//! A derived quantity out of range is blamed on the key the user wrote
//! that puts it there: the first of its inputs which, put back to its
//! default, brings it into range.

use super::*;
use crate::limits::MAX_STEPS_PER_ULP_SPAN;

/// The largest step (τ) any scheme keeps stable on a ladder: every link is
/// a spring of stiffness k on blocks of mass m, so ω_max ≥ √2/τ, and the
/// widest stability interval of the explicit schemes (RK4: 2√2/ω_max) is
/// at most 2 τ. So a window past [`MAX_STEPS_PER_ULP_SPAN`] × 2 τ has no
/// step that both keeps stable and advances time.
pub const LARGEST_STABLE_STEP: f64 = 2.0;

/// The keys that set the unit of time τ = √(m/k) and G, in the order they
/// are blamed.
const FORCE_KEYS: [&str; 5] = ["g", "stiffness", "mass", "density", "thickness"];

/// |α| (degrees) at which the values are converted for the checks: where
/// the motor's T_d is longest (`a`, where given, sets α instead).
const WIDEST_ALPHA: f64 = 90.0;

/// A number for a message: four significant digits, in exponent form when
/// tiny or huge (so 1e300 is not 301 digits).
fn plain(x: f64) -> String {
    crate::numfmt::plain(format!("{x:.3e}").parse().unwrap_or(x))
}

type Checked = std::result::Result<(), (String, String)>;

fn bad(k: &str, m: String) -> Checked {
    Err((k.to_string(), m))
}

fn positive(k: &str, x: f64, what: &str) -> Checked {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        bad(k, format!("must be {what} > 0, got {}", plain(x)))
    }
}

fn within(k: &str, x: f64, lo: f64, hi: f64, what: &str) -> Checked {
    if x.is_finite() && (lo..=hi).contains(&x) {
        Ok(())
    } else {
        bad(
            k,
            format!(
                "must be {what} in [{}, {}], got {}",
                plain(lo),
                plain(hi),
                plain(x)
            ),
        )
    }
}

impl Apparatus {
    /// Checks every value: `Err((key, message))` names the first bad one
    /// (the file loader locates `apparatus.KEY`).
    pub fn check(&self) -> Checked {
        self.check_values()?;
        self.check_built()?;
        self.check_converted()
    }

    /// Each value on its own, and the geometry.
    fn check_values(&self) -> Checked {
        positive("s", self.s, "a length in cm")?;
        positive("b", self.b, "a length in cm")?;
        positive("thickness", self.thickness, "a length in cm")?;
        if self.thickness >= self.s {
            return bad(
                "thickness",
                format!(
                    "must be less than s = {} cm (a plate), got {}",
                    plain(self.s),
                    plain(self.thickness)
                ),
            );
        }
        let b_over_s = self.b / self.s;
        if !(1e-3..=1e3).contains(&b_over_s) {
            return bad(
                "b",
                format!("b/s must lie in [1e-3, 1e3], got {}", plain(b_over_s)),
            );
        }
        self.check_a()?;
        if let Some(h) = self.span {
            positive("span", h, "a length in cm")?;
        }
        match (self.density, self.mass) {
            (Some(_), Some(_)) => return bad("mass", "give density or mass, not both".into()),
            (None, None) => {
                return bad(
                    "density",
                    "give the blocks' density (g/cm³) or mass (g)".into(),
                );
            }
            (Some(r), None) => positive("density", r, "a density in g/cm³")?,
            (None, Some(m)) => positive("mass", m, "a mass in g")?,
        }
        positive("g", self.g, "an acceleration in cm/s²")?;
        self.check_medium()?;
        if let Stiffness::NewtonPerMetre(k) = self.stiffness {
            positive("stiffness", k, "\"stiff\" or N/m")?;
        }
        if !(self.stiff_gravity.is_finite()
            && self.stiff_gravity > 0.0
            && self.stiff_gravity <= 1e-2)
        {
            return bad(
                "stiff_gravity",
                format!(
                    "must be a number in (0, 0.01], got {}",
                    plain(self.stiff_gravity)
                ),
            );
        }
        self.check_terms()
    }

    /// `a`, where given: an angle 0 < |α| < 90°.
    fn check_a(&self) -> Checked {
        let Some(a) = self.a else { return Ok(()) };
        positive("a", a, "a length in cm")?;
        let c2 = (a * a - self.b * self.b) / (4.0 * self.s * self.s);
        if c2 > 0.0 && c2 < 1.0 {
            return Ok(());
        }
        bad(
            "a",
            format!(
                "needs b < a < sqrt(b² + 4 s²) = {:.4} cm for an angle 0 < |alpha| < 90; \
                 a = b is alpha = 90, where the flip is undefined: leave a out and set \
                 [model] alpha near 90 (the paper simulates 86), got {}",
                (self.b * self.b + 4.0 * self.s * self.s).sqrt(),
                plain(a)
            ),
        )
    }

    /// The medium's density and buoyancy.
    fn check_medium(&self) -> Checked {
        if let Some(r) = self.medium_density
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "medium_density",
                format!("must be a density >= 0 in g/cm³, got {}", plain(r)),
            );
        }
        if self.buoyancy && self.medium_density() >= self.density_g_cm3() {
            return bad(
                "buoyancy",
                format!(
                    "the blocks ({} g/cm³) would float in the medium ({} g/cm³): nothing pulls \
                     the ladder down",
                    plain(self.density_g_cm3()),
                    plain(self.medium_density())
                ),
            );
        }
        Ok(())
    }

    /// The terms' coefficients, the motor and the duration, each alone.
    fn check_terms(&self) -> Checked {
        let amf = self.added_mass_factor;
        within("added_mass_factor", amf, 0.0, 2.0, "a number")?;
        within(
            "drag_coefficient",
            self.drag_coefficient,
            0.0,
            10.0,
            "a number",
        )?;
        if let Some(Damping::PerSecond(r)) = self.damping
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "damping",
                format!("must be \"paper\" or a rate >= 0 in 1/s, got {}", plain(r)),
            );
        }
        within(
            "pin_friction",
            self.pin_friction,
            0.0,
            10.0,
            "a coefficient",
        )?;
        positive("pin_radius", self.pin_radius, "a length in cm")?;
        if self.pin_radius >= 0.5 * self.s {
            return bad(
                "pin_radius",
                format!("must be less than s/2, got {}", plain(self.pin_radius)),
            );
        }
        positive("friction_rate", self.friction_rate, "a rate in rad/s")?;
        if let Some(f) = self.motor {
            positive("motor", f, "a rate in Hz")?;
        }
        if let Some(t) = self.duration {
            positive("duration", t, "a time in s")?;
        }
        Ok(())
    }

    /// What the values give together, in the model's units; each quantity
    /// out of range is blamed on the key that puts it there
    /// ([`Apparatus::blame`]).
    fn check_converted(&self) -> Checked {
        let c = self.convert(WIDEST_ALPHA);
        if !(self.mass_per_term_ok()) {
            let fallback = if self.mass.is_some() {
                "mass"
            } else {
                "thickness"
            };
            let key = self.blame(&["mass", "density", "thickness", "span"], fallback, |a| {
                a.mass_per_term_ok()
            });
            return bad(
                &key,
                format!(
                    "gives a block mass m = {} g, too small for the medium's terms per unit \
                     mass (m_a/m = {}, c s²/m = {}) to be finite numbers",
                    plain(c.mass_g),
                    plain(c.added_mass),
                    plain(c.drag)
                ),
            );
        }
        if !self.gravity_ok() {
            // Blamed for the side it misses: G = 0 (an underflow) on what
            // makes it positive, G > 1 on what brings it under 1.
            let g0 = self.model_gravity();
            let zero = g0.is_nan() || g0 <= 0.0;
            let key = self.blame(&FORCE_KEYS, "stiffness", |a| {
                let g = a.model_gravity();
                if zero { g > 0.0 } else { g <= 1.0 }
            });
            return bad(
                &key,
                format!(
                    "gives G = m g/(k s) = {} (m = {} g, g = {} cm/s², k = {} N/m); links \
                     must hold the weight: 0 < G <= 1",
                    plain(c.gravity),
                    plain(c.mass_g),
                    plain(self.gravity_acting()),
                    plain(c.stiffness_n_per_m)
                ),
            );
        }
        if !self.tau_ok() {
            let key = self.blame(&FORCE_KEYS, "stiffness", |a| a.tau_ok());
            return bad(
                &key,
                format!(
                    "gives the unit of time τ = √(m/k) = {} s, which is no finite time > 0 \
                     (m = {} g, k = {} N/m)",
                    plain(c.tau_s),
                    plain(c.mass_g),
                    plain(c.stiffness_n_per_m)
                ),
            );
        }
        self.check_motor(&c)?;
        self.check_window(&c)
    }

    /// The motor's T_d, a finite time > 0 in τ.
    fn check_motor(&self, c: &Conversion) -> Checked {
        let (Some(f), Some(t_d)) = (self.motor, c.drive_time) else {
            return Ok(());
        };
        if t_d.is_finite() && t_d > 0.0 {
            return Ok(());
        }
        let key = self.blame(&FORCE_KEYS, "motor", |a| {
            a.convert(WIDEST_ALPHA)
                .drive_time
                .is_some_and(|t| t.is_finite() && t > 0.0)
        });
        bad(
            &key,
            format!(
                "{} Hz turns block 1 through its flip in T_d = 2|α|/(2π f) = {} s = {} τ \
                 (τ = {} s): the drive needs a finite time > 0",
                plain(f),
                plain(t_d * c.tau_s),
                plain(t_d),
                plain(c.tau_s)
            ),
        )
    }

    /// The run's window in τ: no step that keeps any scheme stable
    /// ([`LARGEST_STABLE_STEP`]) can reach a window past
    /// [`MAX_STEPS_PER_ULP_SPAN`] of them.
    fn check_window(&self, c: &Conversion) -> Checked {
        if self.window_ok() {
            return Ok(());
        }
        let key = self.blame(&FORCE_KEYS, "duration", |a| a.window_ok());
        let t = self.duration.unwrap_or(f64::NAN);
        let most = MAX_STEPS_PER_ULP_SPAN * LARGEST_STABLE_STEP;
        bad(
            &key,
            format!(
                "the run's duration {} s is {} τ (τ = √(m/k) = {} s, from the block's mass \
                 and the links' stiffness k = {} N/m): no step that any scheme keeps stable \
                 (at most about {LARGEST_STABLE_STEP} τ) reaches it within the {} steps that \
                 still advance time; at this τ the duration can be at most {} s",
                plain(t),
                plain(c.t_end.unwrap_or(f64::NAN)),
                plain(c.tau_s),
                plain(c.stiffness_n_per_m),
                plain(MAX_STEPS_PER_ULP_SPAN),
                plain(most * c.tau_s)
            ),
        )
    }

    fn mass_per_term_ok(&self) -> bool {
        let c = self.convert(WIDEST_ALPHA);
        [c.mass_g, c.added_mass, c.added_inertia, c.drag, c.inertia]
            .iter()
            .all(|x| x.is_finite())
            && c.mass_g > 0.0
    }

    fn gravity_ok(&self) -> bool {
        let g = self.model_gravity();
        g > 0.0 && g <= 1.0
    }

    fn tau_ok(&self) -> bool {
        let c = self.convert(WIDEST_ALPHA);
        c.tau_s.is_finite() && c.tau_s > 0.0 && c.cm_per_s.is_finite() && c.gamma.is_finite()
    }

    fn window_ok(&self) -> bool {
        let c = self.convert(WIDEST_ALPHA);
        c.t_end
            .is_none_or(|t| t.is_finite() && t <= MAX_STEPS_PER_ULP_SPAN * LARGEST_STABLE_STEP)
    }

    /// The key to blame for a quantity that `ok` refuses: the first of
    /// `keys` the user gave which, put back to its default (or to a
    /// typical value where it has none), makes `ok` hold; else `fallback`.
    fn blame(&self, keys: &[&str], fallback: &str, ok: impl Fn(&Apparatus) -> bool) -> String {
        let given = |k: &str| match k {
            "mass" => self.mass.is_some(),
            "density" => self.density.is_some(),
            "span" => self.span.is_some(),
            "stiffness" => matches!(self.stiffness, Stiffness::NewtonPerMetre(_)),
            _ => true,
        };
        let typical = |k: &str| {
            let mut a = self.clone();
            match k {
                "g" => a.g = default_g(),
                "stiffness" => a.stiffness = stiff(),
                "mass" => a.mass = Some(10.0),
                "density" => a.density = Some(1.0),
                "thickness" => a.thickness = 0.1 * a.s,
                "span" => a.span = None,
                _ => {}
            }
            a
        };
        keys.iter()
            .copied()
            .filter(|k| given(k))
            .find(|k| ok(&typical(k)))
            .unwrap_or(fallback)
            .to_string()
    }

    /// The ribbons' and the contact's keys (docs/experiments.md, "The toy
    /// as built").
    fn check_built(&self) -> std::result::Result<(), (String, String)> {
        let bad = |k: &str, m: String| Err((k.to_string(), m));
        if let Some(x) = self.ribbon_anchors
            && !x.iter().all(|x| x.is_finite() && (0.0..=1.0).contains(x))
        {
            return bad(
                "ribbon_anchors",
                format!("must be two fractions of s in [0, 1], got {x:?}"),
            );
        }
        if let Some(k) = self.contact_stiffness
            && !(k.is_finite() && k > 0.0)
        {
            return bad(
                "contact_stiffness",
                format!("must be a number > 0 (the links' k per s), got {k}"),
            );
        }
        let built = self.ribbon_anchors.is_some()
            || self.ribbon_mirror
            || self.contact.is_some()
            || self.contact_stiffness.is_some();
        if built && !self.ribbons {
            return bad(
                "ribbons",
                "ribbon and contact keys need ribbons = true (blocks with thickness held by ribbons)"
                    .into(),
            );
        }
        if self.stiffness == Stiffness::Word(StiffWord::Inextensible) && !self.ribbons {
            return bad(
                "stiffness",
                "\"inextensible\" is for ribbons (ribbons = true): links stretch".into(),
            );
        }
        if self.ribbons && (self.tension_only || self.pin_friction > 0.0) {
            return bad(
                "ribbons",
                "ribbons replace the links: leave tension_only and pin_friction out".into(),
            );
        }
        Ok(())
    }
}
