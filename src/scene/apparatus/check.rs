//! The checks of every `[apparatus]` value: the first bad one is named by
//! its key, which the file loader locates.

use super::*;

impl Apparatus {
    /// Checks every value: `Err((key, message))` names the first bad one
    /// (the file loader locates `apparatus.KEY`).
    pub fn check(&self) -> std::result::Result<(), (String, String)> {
        let bad = |k: &str, m: String| Err((k.to_string(), m));
        let positive = |k: &str, x: f64, what: &str| {
            if x.is_finite() && x > 0.0 {
                Ok(())
            } else {
                bad(k, format!("must be {what} > 0, got {x}"))
            }
        };
        positive("s", self.s, "a length in cm")?;
        positive("b", self.b, "a length in cm")?;
        positive("thickness", self.thickness, "a length in cm")?;
        if self.thickness >= self.s {
            return bad(
                "thickness",
                format!(
                    "must be less than s = {} cm (a plate), got {}",
                    self.s, self.thickness
                ),
            );
        }
        let b_over_s = self.b / self.s;
        if !(1e-3..=1e3).contains(&b_over_s) {
            return bad("b", format!("b/s must lie in [1e-3, 1e3], got {b_over_s}"));
        }
        if let Some(a) = self.a {
            positive("a", a, "a length in cm")?;
            let c2 = (a * a - self.b * self.b) / (4.0 * self.s * self.s);
            if !(c2 > 0.0 && c2 < 1.0) {
                return bad(
                    "a",
                    format!(
                        "needs b < a < sqrt(b² + 4 s²) = {:.4} cm for an angle 0 < |alpha| < 90; \
                         a = b is alpha = 90, where the flip is undefined: leave a out and set \
                         [model] alpha near 90 (the paper simulates 86), got {a}",
                        (self.b * self.b + 4.0 * self.s * self.s).sqrt()
                    ),
                );
            }
        }
        if let Some(h) = self.span {
            positive("span", h, "a length in cm")?;
        }
        match (self.density, self.mass) {
            (Some(_), Some(_)) => {
                return bad("mass", "give density or mass, not both".into());
            }
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
        if let Some(r) = self.medium_density
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "medium_density",
                format!("must be a density >= 0 in g/cm³, got {r}"),
            );
        }
        if self.buoyancy && self.medium_density() >= self.density_g_cm3() {
            return bad(
                "buoyancy",
                format!(
                    "the blocks ({} g/cm³) would float in the medium ({} g/cm³): nothing pulls \
                     the ladder down",
                    self.density_g_cm3(),
                    self.medium_density()
                ),
            );
        }
        match self.stiffness {
            Stiffness::NewtonPerMetre(k) => positive("stiffness", k, "\"stiff\" or N/m")?,
            Stiffness::Word(_) => {}
        }
        if !(self.stiff_gravity.is_finite()
            && self.stiff_gravity > 0.0
            && self.stiff_gravity <= 1e-2)
        {
            return bad(
                "stiff_gravity",
                format!("must be a number in (0, 0.01], got {}", self.stiff_gravity),
            );
        }
        let g = self.model_gravity();
        if !(g > 0.0 && g <= 1.0) {
            return bad(
                "stiffness",
                format!("gives G = m g/(k s) = {g}; links must hold the weight: 0 < G <= 1"),
            );
        }
        self.check_built()?;
        if !(self.added_mass_factor.is_finite() && (0.0..=2.0).contains(&self.added_mass_factor)) {
            return bad(
                "added_mass_factor",
                format!("must be a number in [0, 2], got {}", self.added_mass_factor),
            );
        }
        if !(self.drag_coefficient.is_finite() && (0.0..=10.0).contains(&self.drag_coefficient)) {
            return bad(
                "drag_coefficient",
                format!("must be a number in [0, 10], got {}", self.drag_coefficient),
            );
        }
        if let Some(Damping::PerSecond(r)) = self.damping
            && !(r.is_finite() && r >= 0.0)
        {
            return bad(
                "damping",
                format!("must be \"paper\" or a rate >= 0 in 1/s, got {r}"),
            );
        }
        if !(self.pin_friction.is_finite() && (0.0..=10.0).contains(&self.pin_friction)) {
            return bad(
                "pin_friction",
                format!(
                    "must be a coefficient in [0, 10], got {}",
                    self.pin_friction
                ),
            );
        }
        positive("pin_radius", self.pin_radius, "a length in cm")?;
        if self.pin_radius >= 0.5 * self.s {
            return bad(
                "pin_radius",
                format!("must be less than s/2, got {}", self.pin_radius),
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
        if self.ribbons && (self.tension_only || self.pin_friction > 0.0) {
            return bad(
                "ribbons",
                "ribbons replace the links: leave tension_only and pin_friction out".into(),
            );
        }
        Ok(())
    }
}
