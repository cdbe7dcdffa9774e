//! Domain walls of a state (where the polarisation sin θₙ changes sign)
//! and the marks a filmstrip draws at them.

use crate::render::compose::*;
use crate::render::palette::Role;
use crate::render::style;
use crate::sim::{self};

/// A domain wall of the chain: where the polarisation sin θₙ changes sign
/// between two neighbouring blocks, at `at` blocks (linear between their
/// centres). A kink has sin θ < 0 above and > 0 below (the flip of
/// α > 0 → −α at the top); an antikink the reverse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wall {
    pub at: f64,
    pub kink: bool,
}

/// The domain walls of state `q`, top to bottom.
pub fn walls(q: &[f64]) -> Vec<Wall> {
    let p = sim::observables::polarisation(q);
    p.windows(2)
        .enumerate()
        .filter(|(_, w)| w[0] * w[1] < 0.0)
        .map(|(i, w)| Wall {
            at: (i + 1) as f64 + w[0] / (w[0] - w[1]),
            kink: w[0] < 0.0,
        })
        .collect()
}

/// Walls of opposite kinds closer than this, in blocks, are colliding.
const COLLISION_BLOCKS: f64 = 1.0;

/// The marks of a snapshot: "kink" on the left of the chain, "antikink" on
/// the right, and "collision" where a kink and an antikink are less than
/// [`COLLISION_BLOCKS`] apart (paper Fig. 4a).
pub(crate) fn wall_marks(q: &[f64]) -> Vec<ChainMark> {
    let w = walls(q);
    let mut marks = Vec::new();
    let mut k = 0;
    while k < w.len() {
        if let Some(next) = w.get(k + 1)
            && next.kink != w[k].kink
            && next.at - w[k].at < COLLISION_BLOCKS
        {
            marks.push(ChainMark {
                at: 0.5 * (w[k].at + next.at),
                label: "collision".into(),
                role: Role::Ink,
                side: style::HAlign::Right,
            });
            k += 2;
            continue;
        }
        // The waves' roles, as in figure 3 and every chart: a kink
        // vermillion, an antikink blue (the words in a shade of each that
        // reads on white).
        let (label, role, side) = if w[k].kink {
            ("kink", Role::Kink, style::HAlign::Left)
        } else {
            ("antikink", Role::Antikink, style::HAlign::Right)
        };
        marks.push(ChainMark {
            at: w[k].at,
            label: label.into(),
            role,
            side,
        });
        k += 1;
    }
    marks
}

#[cfg(test)]
mod wall_tests {
    use super::*;

    /// A state with these block angles (degrees); centres unused.
    fn state(theta_deg: &[f64]) -> Vec<f64> {
        theta_deg
            .iter()
            .flat_map(|t| [0.0, 0.0, t.to_radians()])
            .collect()
    }

    #[test]
    fn walls_are_sign_changes_of_the_polarisation() {
        // −α above +α: a kink between blocks 2 and 3; back to −α: an
        // antikink between blocks 5 and 6, nearer block 6.
        let q = state(&[-60.0, -60.0, 60.0, 60.0, 60.0, -10.0, -60.0]);
        let w = walls(&q);
        assert_eq!(w.len(), 2);
        assert!(w[0].kink && (w[0].at - 2.5).abs() < 1e-12, "{w:?}");
        assert!(!w[1].kink && w[1].at > 5.5 && w[1].at < 6.0, "{w:?}");
        let marks = wall_marks(&q);
        assert_eq!(marks.len(), 2);
        assert!(marks[0].label == "kink" && marks[0].side == style::HAlign::Left);
        assert!(marks[1].label == "antikink" && marks[1].side == style::HAlign::Right);
        // Figure 3's roles: a kink vermillion, an antikink blue.
        assert_eq!((marks[0].role, marks[1].role), (Role::Kink, Role::Antikink));
        assert!(
            walls(&state(&[60.0; 5])).is_empty(),
            "a ground state has none"
        );
    }

    #[test]
    fn walls_less_than_a_block_apart_are_a_collision() {
        let q = state(&[-60.0, -60.0, -20.0, 5.0, -20.0, -60.0]);
        let marks = wall_marks(&q);
        assert_eq!(marks.len(), 1, "{marks:?}");
        assert_eq!(marks[0].label, "collision");
        assert!((marks[0].at - 4.0).abs() < 1e-9);
    }
}
