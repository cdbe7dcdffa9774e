//! The commands, one file each: each turns its checked arguments into
//! library calls and says what it did.

pub mod bench;
pub mod docs;
pub mod render;
pub mod simulate;
pub mod sweep;
pub mod theory;

use crate::limits::Limits;
use crate::scene::Scene;

/// What every command that makes files is handed beside its arguments.
pub struct Call<'a> {
    /// The program's arguments, word by word, recorded in the data files.
    pub command_line: &'a [String],
    /// The caps of the `--max-*` flags (the defaults where none is given).
    pub limits: Limits,
}

impl Call<'_> {
    /// `scenes`, each carrying this command's caps (`Scene::limits`).
    pub fn capped(&self, scenes: Vec<Scene>) -> Vec<Scene> {
        scenes.into_iter().map(|s| self.capped_one(s)).collect()
    }

    /// `scene` carrying this command's caps.
    pub fn capped_one(&self, scene: Scene) -> Scene {
        Scene {
            limits: self.limits,
            ..scene
        }
    }
}
