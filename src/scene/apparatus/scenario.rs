//! What a scene's apparatus runs: the scene with its conversion made
//! afresh (its model, drive and window the ones the run uses), and the
//! scenario (parameters, terms, drive) of its run.

use super::*;
use crate::error::{Error, Result};
use crate::model::Params;
use crate::scene::{DriveSpec, Model};
use crate::sim::{Drive, Scenario};

impl crate::scene::Scene {
    /// This scene with its apparatus' conversion made afresh for its
    /// `[model] alpha` (a conversion the scene carried is never trusted:
    /// a data file's, or one left from before a keyword changed the
    /// apparatus), and the values the run uses written where the scene
    /// keeps them, so that the scene recorded is the one run: `[model]`'s
    /// b, γ, G, I (and α where `a` sets it) from the conversion
    /// ([`Conversion::model`]), the motor's flip as `[drive]`
    /// ([`Conversion::drive`]) and `duration` (s) as the run's window in
    /// τ. The one step a scene file (`scene::file::parse`), the command
    /// line's `--apparatus` and Python's keywords end with; a scene
    /// without an apparatus is returned as it is.
    pub fn with_conversion(mut self) -> Self {
        if let Some(a) = &self.apparatus {
            let a = a.converted(self.model.alpha);
            if let Some(c) = &a.conversion {
                if let Some(t) = c.t_end {
                    self.run.t_end = t;
                }
                self.model = c.model(&self.model);
                self.drive = c.drive(&self.drive);
            }
            self.apparatus = Some(a);
        }
        self
    }

    /// This scene with its run's window set to `t_end` (τ) where the scene
    /// is made (the command line's `--t-end`, Python's `t_end`, a figure
    /// panel's `t_end`), its apparatus' conversion made afresh: an
    /// apparatus' `duration` yields to the window given, and is dropped,
    /// so that the run goes to `t_end` and the scene recorded says only
    /// that. (Without this the duration, converted again, replaced the
    /// window given.)
    pub fn with_t_end(mut self, t_end: f64) -> Self {
        self.run.t_end = t_end;
        if let Some(a) = self.apparatus.as_mut() {
            a.duration = None;
        }
        self.with_conversion()
    }

    /// This scene with block 1's drive given where the scene is made
    /// (`--drive-time`, `--flips`, `--second-flip`, Python's drive
    /// keywords), its apparatus' conversion made afresh: an apparatus'
    /// `motor` yields to the drive given, and is dropped, as `duration`
    /// yields to `t_end` ([`Self::with_t_end`]).
    pub fn with_drive(mut self, drive: DriveSpec) -> Self {
        self.drive = drive;
        if let Some(a) = self.apparatus.as_mut() {
            a.motor = None;
        }
        self.with_conversion()
    }
}

impl Conversion {
    /// The model the run uses: `model` (its N, start and the sign of α)
    /// with the conversion's b, γ, G and I, and α where `a` sets it.
    pub fn model(&self, model: &Model) -> Model {
        Model {
            alpha: self.alpha.unwrap_or(model.alpha),
            b: self.b,
            gamma: self.gamma,
            gravity: self.gravity,
            inertia: self.inertia,
            ..*model
        }
    }

    /// The drive the run uses: the motor's one flip from t = 0 over its
    /// drive time where there is a motor, else `drive`.
    pub fn drive(&self, drive: &DriveSpec) -> DriveSpec {
        match self.drive_time {
            Some(t_d) => DriveSpec::flips_at(&[0.0], t_d),
            None => drive.clone(),
        }
    }
}

impl Apparatus {
    /// The simulation of `scene` with this apparatus: the model from the
    /// conversion (N, the sign of α and α itself unless `a` sets it from
    /// `[model]`), the motor's drive or the scene's, `duration` or
    /// `[run] t_end`.
    pub fn scenario(&self, scene: &crate::scene::Scene) -> Result<Scenario> {
        self.check()
            .map_err(|(k, m)| Error::bad_input(format!("apparatus.{k}: {m}")))?;
        let c = self.convert(scene.model.alpha);
        let model = c.model(&scene.model);
        let params = model.params()?;
        if let Some(built) = self.built(&c) {
            return self.built_scenario(scene, params, built, &c);
        }
        crate::sim::check_simulable(&params)?;
        let drive = match c.drive_time {
            Some(t_d) => Drive::single_flip(params.alpha, t_d)?,
            None => scene.drive.drive(params.alpha)?,
        };
        let t_end = match c.t_end {
            Some(t) => t,
            None if scene.run.t_end.is_finite() => scene.run.t_end,
            None => {
                return Err(Error::bad_input(
                    "apparatus: give duration (s) or [run] t_end for a scene with an apparatus",
                ));
            }
        };
        let mut sc = Scenario::with_drive(params, drive, t_end)?.started(model.start)?;
        let terms = self.terms(&c).validated()?;
        sc.ladder = sc.ladder.with_terms(terms);
        Ok(sc)
    }

    /// The run of a ladder as built: the hanging column at rest, the
    /// motor's or the scene's drive (the hanging start is the column).
    fn built_scenario(
        &self,
        scene: &crate::scene::Scene,
        params: Params,
        built: crate::model::built::AsBuilt,
        c: &Conversion,
    ) -> Result<Scenario> {
        let drive = match c.drive_time {
            Some(t_d) => Drive::single_flip(params.alpha, t_d)?,
            None => scene.drive.drive(params.alpha)?,
        };
        let t_end = c.t_end.unwrap_or(scene.run.t_end);
        let terms = self.terms(c).validated()?;
        Scenario::as_built(params, drive, t_end, terms, built)
    }
}

impl Apparatus {
    /// Why a value given for `p` beside this apparatus (a flag, a Python
    /// keyword, a sweep's axis) would not be the value run, or `None`
    /// where it would: the apparatus sets b, γ, G and I from its own keys
    /// ([`Conversion::model`]), so a value given for one of them would be
    /// replaced without a word. (Block 1's drive time is the motor's
    /// only until a drive is given: [`crate::scene::Scene::with_drive`].)
    pub fn replaces(&self, p: crate::scene::params::Param) -> Option<String> {
        use crate::scene::params::Param;
        let from = match p {
            Param::B => "b from its own b and s (cm)",
            Param::Gamma => "gamma from its `damping`",
            Param::Gravity => "G from its links' stiffness, its mass and g",
            Param::Inertia => "I from its s and thickness",
            _ => return None,
        };
        Some(format!(
            "the apparatus sets {from} (docs/experiments.md, \"The apparatus in the model's \
             units\"); change its [apparatus] keys, or leave the apparatus out"
        ))
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::params::Param;
    use crate::scene::{Panel, Scene, file};

    /// The toy scene (an apparatus with a 2 s `duration`), or its text with
    /// `extra` appended.
    fn toy(extra: &str) -> crate::error::Result<Scene> {
        let text = include_str!("../../../assets/scenes/toy.toml");
        file::parse(&format!("{text}{extra}"), "toy.toml", "toy")
    }

    #[test]
    fn a_window_given_replaces_the_duration_and_a_drive_the_motor() {
        let scene = toy("").unwrap();
        let tau = scene.apparatus.as_ref().unwrap().convert(86.0).tau_s;
        assert!((scene.run.t_end - 2.0 / tau).abs() < 1e-9);
        let given = scene.clone().with_t_end(500.0);
        assert_eq!(given.run.t_end, 500.0);
        assert_eq!(given.apparatus.as_ref().unwrap().duration, None);
        // The scenario runs to it (before: the duration, converted again).
        let sc = given.apparatus.as_ref().unwrap().scenario(&given).unwrap();
        assert_eq!(sc.t_end, 500.0);
        // A panel's t_end the same way.
        let panel = Panel {
            t_end: Some(300.0),
            ..Panel::default()
        };
        let v = scene.variant(&panel);
        assert_eq!(v.run.t_end, 300.0);
        assert_eq!(v.apparatus.as_ref().unwrap().duration, None);
        // A motor yields to a drive given.
        let mut motor = scene.clone();
        motor.apparatus.as_mut().unwrap().motor = Some(0.5);
        let motor = motor.with_conversion();
        assert!(motor.drive.flips[0].duration > 300.0);
        let d = crate::scene::DriveSpec::flips_at(&[0.0], 100.0);
        let given = motor.with_drive(d.clone());
        assert_eq!(given.drive, d);
        assert_eq!(given.apparatus.as_ref().unwrap().motor, None);
    }

    #[test]
    fn the_apparatus_names_the_model_values_it_sets() {
        let a = toy("").unwrap().apparatus.unwrap();
        for p in Param::ALL {
            let set = matches!(p, Param::B | Param::Gamma | Param::Gravity | Param::Inertia);
            assert_eq!(a.replaces(p).is_some(), set, "{}", p.name());
        }
        // A filmstrip panel that sets one is refused, naming it.
        let e = toy("").map(|mut s| {
            s.output = crate::scene::OutputSpec::Filmstrip {
                times: vec![0.0, 100.0],
                panels: vec![Panel {
                    model: crate::scene::ModelPatch {
                        gamma: Some(0.1),
                        ..Default::default()
                    },
                    ..Panel::default()
                }],
            };
            s.check()
        });
        let (key, msg) = e.unwrap().unwrap_err();
        assert_eq!(key, "output.panels.0.model.gamma");
        assert!(msg.starts_with("the apparatus sets gamma"), "{msg}");
    }
}
