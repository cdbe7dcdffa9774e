//! The double ring chain (paper Fig. 4b and SI Movie 12): key rings in two
//! interlocked strands, where turning the top ring over sends a helical
//! solitary wave down one strand, clearest when the partner strand is
//! held by tapes. A system of its own beside the ladder's `sim`: rigid
//! tori in 3D ([`body`]), their topology and the hand as input
//! ([`chain`], [`hand`], [`alternate`]), contact between tubes of our own ([`contact`];
//! docs/rings.md says why not an engine, and [`warm`], its search
//! warm-started from the previous step), the linking guard ([`guard`]),
//! the step ([`system`]), the observables ([`observe`]) and the chain's
//! normal modes at rest ([`modes`]).
//!
//! Floors: `rings` knows only `error` below it; `render` draws its
//! states from plain poses, and `scenes` brings them together.

pub mod alternate;
pub mod body;
pub mod build;
pub mod chain;
pub mod contact;
pub mod guard;
pub mod hand;
pub mod math;
pub mod modes;
pub mod observe;
pub mod run;
pub mod settle;
pub mod start;
pub mod system;
pub mod warm;

pub use chain::{RingChain, TapeKind, Topology, Turn};
pub use run::{RingRun, Sample, run};
