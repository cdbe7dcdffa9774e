//! What a scene's apparatus runs: the scene with its conversion made
//! afresh, and the scenario (parameters, terms, drive) of its run.

use super::*;
use crate::error::{Error, Result};
use crate::model::Params;
use crate::sim::{Drive, Scenario};

impl crate::scene::Scene {
    /// This scene with its apparatus' conversion made afresh for its
    /// `[model] alpha` (a conversion the scene carried is never trusted:
    /// a data file's, or one left from before a keyword changed the
    /// apparatus) and its `duration` (s) as the run's window in τ. The one
    /// step a scene file (`scene::file::parse`) and Python's keywords end
    /// with; a scene without an apparatus is returned as it is.
    pub fn with_conversion(mut self) -> Self {
        if let Some(a) = &self.apparatus {
            let a = a.converted(self.model.alpha);
            if let Some(t) = a.conversion.as_ref().and_then(|c| c.t_end) {
                self.run.t_end = t;
            }
            self.apparatus = Some(a);
        }
        self
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
        let model = &scene.model;
        let c = self.convert(model.alpha);
        let alpha = c.alpha.unwrap_or(model.alpha);
        let params = Params::new(model.n, c.b, alpha, c.gamma, c.gravity, c.inertia)?;
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
