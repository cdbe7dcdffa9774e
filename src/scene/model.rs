//! `[model]`: the ladder's parameters (docs/model.md) and a panel's
//! patch of them, both made from the parameter table
//! ([`crate::model::table`]): one field per parameter of the model, its
//! key the parameter's name, its default the table's.

use crate::error::Result;
use crate::model::Params;
use crate::model::table::{Param, ParamValue, Place};
use crate::sim::Start;
use serde::{Deserialize, Serialize};

/// `Model` and `ModelPatch` from the table's model parameters.
macro_rules! declare_model {
    (
        model { $($m:ident : $mt:ty = $mv:ident { $($rest:tt)* }),* $(,)? }
        drive { $($drive:tt)* }
    ) => {
        /// The model's parameters (docs/model.md, `[model]` in a scene
        /// file): one field per parameter of the table
        /// ([`crate::model::table`], which gives each one's symbol,
        /// unit, range, default and meaning), and how the run starts.
        #[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields, default)]
        pub struct Model {
            $(
                #[doc = concat!("`", stringify!($m), "`: see [`Param::", stringify!($mv), "`].")]
                pub $m: $mt,
            )*
            /// How the run starts: `ground` (at rest in the ground state, springs
            /// at rest length) or `relaxed` (at rest hanging under gravity with
            /// block 1 clamped, `sim::relax`). Default `ground` (docs/model.md,
            /// "The hanging start", gives the measurement behind it).
            pub start: Start,
        }

        impl Default for Model {
            /// The paper's simulation values (supplement, "Details of
            /// numerical simulation"): the table's defaults.
            fn default() -> Self {
                Self {
                    $($m: <$mt as ParamValue>::from_f64(Param::$mv.default_value()),)*
                    start: Start::default(),
                }
            }
        }

        impl Model {
            /// Parameter `p`'s value (`None` for the drive's).
            pub fn get(&self, p: Param) -> Option<f64> {
                match p {
                    $(Param::$mv => Some(self.$m.to_f64()),)*
                    _ => None,
                }
            }

            /// Sets parameter `p` to `x` (a whole number for N, as the
            /// checks ask); the drive's leave the model as it is.
            pub fn set(&mut self, p: Param, x: f64) {
                match p {
                    $(Param::$mv => self.$m = <$mt as ParamValue>::from_f64(x),)*
                    _ => {}
                }
            }
        }

        /// Overrides of some model fields (a filmstrip panel, a chart curve, a
        /// sweep point). Missing fields keep the scene's value.
        #[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct ModelPatch {
            $(
                #[serde(skip_serializing_if = "Option::is_none")]
                pub $m: Option<$mt>,
            )*
        }

        impl ModelPatch {
            /// Parameter `p`'s value, where the patch sets it.
            pub fn get(&self, p: Param) -> Option<f64> {
                match p {
                    $(Param::$mv => self.$m.map(ParamValue::to_f64),)*
                    _ => None,
                }
            }

            /// `m` with the patch's values over it.
            pub fn apply(&self, m: &Model) -> Model {
                Model {
                    $($m: self.$m.unwrap_or(m.$m),)*
                    start: m.start,
                }
            }
        }
    };
}

crate::parameter_table!(declare_model);

impl Model {
    /// Validated model parameters (each value checked against the
    /// table's range as given, [`Params::from_values`]).
    pub fn params(&self) -> Result<Params> {
        Ok(Params::from_values(|p| {
            self.get(p).expect("a model parameter")
        })?)
    }

    /// "kink" for α > 0, "antikink" for α < 0.
    pub fn wave(&self) -> &'static str {
        crate::sim::waves::WaveKind::launched(self.alpha).name()
    }

    /// The model's parameters and their values, in the table's order.
    pub fn values(&self) -> impl Iterator<Item = (Param, f64)> + '_ {
        Param::ALL
            .into_iter()
            .filter(|p| p.spec().place == Place::Model)
            .map(|p| (p, self.get(p).expect("a model parameter")))
    }
}

/// Whether a panel leaves the model as it is (its patch is empty).
pub(crate) fn is_default_patch(p: &ModelPatch) -> bool {
    *p == ModelPatch::default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_is_the_tables() {
        let m = Model::default();
        let keys = serde_json::to_value(m).unwrap();
        let keys = keys.as_object().unwrap();
        for p in Param::MODEL {
            assert_eq!(m.get(p), Some(p.default_value()), "{p}");
            assert_eq!(keys[p.name()].as_f64(), Some(p.default_value()), "{p}");
            let mut changed = m;
            changed.set(p, 3.0);
            assert_eq!(changed.get(p), Some(3.0), "{p}");
        }
        // The parameters and `start`, nothing else.
        assert_eq!(keys.len(), Param::MODEL.len() + 1);
        let patch = ModelPatch {
            n: Some(20),
            ..ModelPatch::default()
        };
        assert_eq!(patch.get(Param::N), Some(20.0));
        assert_eq!(patch.apply(&m).n, 20);
    }
}
