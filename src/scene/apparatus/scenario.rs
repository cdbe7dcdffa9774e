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
