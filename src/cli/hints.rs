//! Hints in the user's words: a diverged run's message says the step
//! that would hold, naming the flags or the scene file's keys.

use crate::error::Error;
use crate::scene::{self, Scene};
use crate::scenes;
use crate::sim::IntegratorKind;

/// How a hint names the settings: as command-line flags, or as the keys
/// of a scene file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Words {
    Flags,
    Keys,
}

impl Words {
    fn dt(self) -> &'static str {
        match self {
            Self::Flags => "--dt",
            Self::Keys => "[run] dt",
        }
    }

    fn rtol(self) -> &'static str {
        match self {
            Self::Flags => "--rtol",
            Self::Keys => "[run] rtol",
        }
    }

    fn auto(self) -> &'static str {
        match self {
            Self::Flags => "--integrator auto",
            Self::Keys => "[run] integrator = \"auto\"",
        }
    }
}

/// A diverged run's message with a hint in the user's terms: the largest
/// step at which this scene stays bounded with the integrator that failed
/// (measured by bisection, or the linear prediction where measuring would
/// take long), or the auto integrator. Other errors pass unchanged.
pub(crate) fn with_divergence_hint(e: Error, scene: &Scene, words: Words) -> Error {
    let Error::Diverged(d) = &e else {
        return e;
    };
    let scene::Method::Fixed(kind) = scene.run.integrator else {
        return e;
    };
    let auto = words.auto();
    let hint = if kind == IntegratorKind::Dopri5 && scene.run.rtol.is_some() {
        format!("use a smaller {}, or {auto}", words.rtol())
    } else if kind == IntegratorKind::Moreau {
        // Inextensible ribbons: no linear bound (the ribbons act by
        // impulses), and `auto` refuses them.
        format!(
            "use a smaller {}: 0.05 τ holds the tank's speeds within 2 % \
             (docs/experiments.md, \"Inextensible ribbons\")",
            words.dt()
        )
    } else {
        let dt = words.dt();
        match scenes::run::critical_step(scene, kind) {
            Ok(scenes::run::CriticalStep {
                measured: Some(c),
                predicted,
            }) => format!(
                "on this scene {kind} stays bounded up to dt ≈ {} τ (measured; the linear theory \
                 predicts {}): use {dt} below that, or {auto}, which picks a step and checks it",
                short(c),
                short(predicted)
            ),
            Ok(scenes::run::CriticalStep { predicted, .. }) if predicted.is_finite() => format!(
                "the linear theory puts the stable step of {kind} on this scene near dt ≈ {} τ: \
                 use {dt} well below that, or {auto}, which picks a step and checks it",
                short(predicted)
            ),
            _ => format!("use a smaller {dt}, or {auto}, which picks a step and checks it"),
        }
    };
    Error::failed(format!("{}; hint: {hint}", d.facts()))
}

/// `x` to two significant digits, as a reader writes it.
pub(crate) fn short(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return format!("{x}");
    }
    let scale = 10f64.powf(x.log10().floor() - 1.0);
    crate::numfmt::typeset((x / scale).floor() * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_numbers_round_down_to_two_digits() {
        assert_eq!(short(0.7512), "0.75");
        assert_eq!(short(0.0056789), "0.0056");
        assert_eq!(short(12.9), "12");
    }
}
