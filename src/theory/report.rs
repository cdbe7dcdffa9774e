//! The numbers of `ladder theory` (README.md, `theory --json`).

use super::bloch::{BlochChain, Coefficients};
use super::compatibility::{Boundary, IndexCount, index_count};
use super::dispersion::{KineticMetric, gap_closed_form, omega_max_clamped};
use super::edge::{Edge, kappa, surface_zero_mode, zero_mode_ratio};
use super::gravity::{barrier, u_min};
use crate::error::{Error, Result};
use crate::model::Params;
use serde::Serialize;
use std::fmt::Write;

/// Linear theory of one ladder: closed forms and their numerical checks.
/// Energies per pair of blocks in units of m g s, lengths in units of s,
/// frequencies in units of 1/τ = sqrt(k/m). `None` (JSON null) marks a
/// quantity that is infinite or undefined at this α.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TheoryReport {
    pub n: usize,
    pub b: f64,
    pub alpha_deg: f64,
    /// a = sqrt(b² + 4 s² cos²α) (eq:eq_alpha).
    pub a: f64,
    pub inertia: f64,
    /// U_min = −2 m g b (eq:min_values).
    pub u_min: f64,
    /// ΔU(α) (eq:delta_U); null when b < s sin²α.
    pub barrier: Option<f64>,
    /// c_1, c_2 (eq:c_12).
    pub c1: f64,
    pub c2: f64,
    /// c_2/c_1 (eq:2nd_sol); null for a = b.
    pub zero_mode_ratio: Option<f64>,
    /// Ratio δθ_{n+1}/δθ_n of the numerical surface zero mode of the reduced
    /// chain (middle of the chain); null for a = b.
    pub zero_mode_ratio_numerical: Option<f64>,
    /// κ = b^{-1} log|(b + 2s sin α)/(b − 2s sin α)|, signed (> 0: top);
    /// null where infinite (b = 2s|sin α|) or undefined (a = b).
    pub kappa: Option<f64>,
    /// Edge of the numerical surface zero mode: "top", "bottom" or null.
    pub surface_mode_edge: Option<Edge>,
    /// n_C from the phase of det C(q)/(e^{iqb} − 1) of the model; null for
    /// α = 0 and a = b.
    pub winding_number: Option<i32>,
    /// ω_+(q = 0) of the model's constrained chain with the paper's kinetic
    /// metric diag(m, I), in 1/τ.
    pub gap_omega_plus_q0: f64,
    /// The printed 2√2 ω_0 (s/a) sin 2α with ω_0 = 1/τ (eq:gap).
    pub gap_omega_plus_q0_paper: f64,
    /// ω_+(0) with the consistent metric (θ inertia I + m (s/2)² sin²α).
    pub gap_omega_plus_q0_consistent_metric: f64,
    /// Highest branch at q = 0 of the unconstrained three-branch spectrum.
    pub gap_unconstrained: f64,
    /// Largest normal-mode frequency, N blocks, ground state, block 1
    /// clamped, springs only.
    pub omega_max: f64,
    pub zero_modes_clamped: usize,
    pub self_stress_clamped: usize,
    /// Zero modes of the free chain, including the 3 rigid-body motions.
    pub zero_modes_free: usize,
    pub self_stress_free: usize,
    /// ν = 3N − N_b of the free chain (= N_0 − N_s).
    pub maxwell_index_free: i64,
    /// Zero modes and self-stress of the N-block ring (null for odd N).
    pub zero_modes_periodic: Option<usize>,
    pub self_stress_periodic: Option<usize>,
}

/// Largest N for the linear theory: the dense SVDs and eigen-decompositions
/// cost O(N³) (N = 200 takes about 0.5 s, N = 400 about 4 s).
pub const MAX_THEORY_BLOCKS: usize = crate::limits::MAX_THEORY_BLOCKS;

impl TheoryReport {
    /// The JSON fields docs/sweeps.md requires of `ladder theory --json`.
    pub const SPEC_FIELDS: [&'static str; 11] = [
        "a",
        "alpha_deg",
        "u_min",
        "barrier",
        "kappa",
        "winding_number",
        "gap_omega_plus_q0",
        "omega_max",
        "zero_modes_clamped",
        "zero_modes_free",
        "self_stress_free",
    ];

    /// Every quantity for `params` (0 ≤ |α| ≤ 90°, 2 ≤ N ≤ `MAX_THEORY_BLOCKS`).
    pub fn compute(params: &Params) -> Result<Self> {
        let p = params.validated()?;
        if p.n > MAX_THEORY_BLOCKS {
            return Err(Error::bad_input(format!(
                "the linear theory takes N between 2 and {MAX_THEORY_BLOCKS}, got {}",
                p.n
            )));
        }
        let k = Coefficients::of(&p);
        let chain = BlochChain::new(&p)?;
        let (free, clamped) = (
            index_count(&p, Boundary::Free)?,
            index_count(&p, Boundary::Clamped)?,
        );
        let periodic = index_count(&p, Boundary::Periodic).ok();
        let mode = surface_zero_mode(&p).ok();
        Ok(Self {
            n: p.n,
            b: p.b,
            alpha_deg: p.alpha_deg(),
            a: k.a,
            inertia: p.inertia,
            u_min: u_min(p.b),
            barrier: barrier(p.b, p.alpha),
            c1: k.c1,
            c2: k.c2,
            zero_mode_ratio: zero_mode_ratio(p.b, p.alpha),
            zero_mode_ratio_numerical: mode
                .as_ref()
                .and_then(|m| m.ratios.get(m.ratios.len() / 2).copied()),
            kappa: kappa(p.b, p.alpha),
            surface_mode_edge: mode.and_then(|m| m.edge),
            winding_number: chain.winding_number(),
            gap_omega_plus_q0: chain.gap(KineticMetric::Paper),
            gap_omega_plus_q0_paper: gap_closed_form(&k),
            gap_omega_plus_q0_consistent_metric: chain.gap(KineticMetric::Constrained),
            gap_unconstrained: chain.unconstrained_dispersion(0.0)[2],
            omega_max: omega_max_clamped(&p)?,
            zero_modes_clamped: clamped.zero_modes,
            self_stress_clamped: clamped.self_stress,
            zero_modes_free: free.zero_modes,
            self_stress_free: free.self_stress,
            maxwell_index_free: free.maxwell_index,
            zero_modes_periodic: periodic.map(|c: IndexCount| c.zero_modes),
            self_stress_periodic: periodic.map(|c| c.self_stress),
        })
    }

    /// A human-readable table: quantity, value, source.
    pub fn to_table(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "Linear theory, N = {}, b/s = {}, α = {}°",
            self.n,
            self.b,
            crate::numfmt::typeset(self.alpha_deg)
        );
        for (name, value, note) in self.rows() {
            let _ = writeln!(out, "  {name:<34} {value:>14}  {note}");
        }
        out
    }

    /// The printed table's rows: name, value, where the number comes from.
    fn rows(&self) -> Vec<Row> {
        [self.ground_rows(), self.gap_rows(), self.count_rows()].concat()
    }

    /// The ground state, the barrier and the zero mode.
    fn ground_rows(&self) -> Vec<Row> {
        vec![
            ("a/s", num(self.a), "a = √(b² + 4s² cos²α), supplement"),
            (
                "U_min / mgs (per pair)",
                num(self.u_min),
                "U_min = −2mgb, supplement",
            ),
            (
                "barrier ΔU / mgs (per pair)",
                opt(self.barrier),
                "criss-cross barrier, supplement",
            ),
            ("c₁", num(self.c1), "zero-mode coefficient, supplement"),
            ("c₂", num(self.c2), "zero-mode coefficient, supplement"),
            (
                "c₂/c₁",
                opt(self.zero_mode_ratio),
                "zero mode δθₙ₊₁/δθₙ, main text",
            ),
            (
                "δθₙ₊₁/δθₙ (numerical)",
                opt(self.zero_mode_ratio_numerical),
                "reduced chain null vector",
            ),
            (
                "κs",
                opt(self.kappa),
                "κ = ln|(b + 2s sin α)/(b − 2s sin α)|/b, > 0: top",
            ),
            (
                "surface mode edge",
                edge(self.surface_mode_edge),
                "reduced chain null vector",
            ),
            (
                "winding number n_C",
                self.winding_number
                    .map_or("undefined".into(), |w| w.to_string()),
                "phase of det C(q), main text",
            ),
        ]
    }

    /// The band gap, as the model has it and as printed, and ω_max.
    fn gap_rows(&self) -> Vec<Row> {
        vec![
            (
                "gap ω₊(0) τ",
                num(self.gap_omega_plus_q0),
                "model, metric diag(m, I)",
            ),
            (
                "gap ω₊(0) τ, as printed",
                num(self.gap_omega_plus_q0_paper),
                "2√2 ω₀ (s/a) sin 2α, ω₀ = 1/τ",
            ),
            (
                "gap, consistent metric",
                num(self.gap_omega_plus_q0_consistent_metric),
                "θ inertia I + m (s/2)² sin²α",
            ),
            (
                "gap, unconstrained top branch",
                num(self.gap_unconstrained),
                "3 branches at q = 0",
            ),
            (
                "ω_max τ (clamped)",
                num(self.omega_max),
                "Hessian, block 1 clamped",
            ),
        ]
    }

    /// The counts of zero modes and states of self-stress (rank of C).
    fn count_rows(&self) -> Vec<Row> {
        vec![
            (
                "zero modes, clamped",
                self.zero_modes_clamped.to_string(),
                "rank of C",
            ),
            (
                "self-stress, clamped",
                self.self_stress_clamped.to_string(),
                "rank of C",
            ),
            (
                "zero modes, free (incl. 3 rigid)",
                self.zero_modes_free.to_string(),
                "rank of C",
            ),
            (
                "self-stress, free",
                self.self_stress_free.to_string(),
                "rank of C",
            ),
            (
                "Maxwell index 3N − N_b, free",
                self.maxwell_index_free.to_string(),
                "= N₀ − N_s",
            ),
            (
                "zero modes, periodic",
                opt_count(self.zero_modes_periodic),
                "ring of N blocks",
            ),
            (
                "self-stress, periodic",
                opt_count(self.self_stress_periodic),
                "ring of N blocks",
            ),
        ]
    }
}

/// One row of the printed table: name, value, source.
type Row = (&'static str, String, &'static str);

fn num(x: f64) -> String {
    format!("{x:.6}")
}

fn opt(x: Option<f64>) -> String {
    x.map_or_else(|| "undefined".into(), num)
}

fn opt_count(x: Option<usize>) -> String {
    x.map_or_else(|| "n/a (odd N)".into(), |c| c.to_string())
}

fn edge(e: Option<Edge>) -> String {
    match e {
        Some(Edge::Top) => "top".into(),
        Some(Edge::Bottom) => "bottom".into(),
        None => "none".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_serialises_with_the_spec_fields() {
        let r = TheoryReport::compute(&Params::paper(60.0).unwrap()).unwrap();
        let v = serde_json::to_value(&r).unwrap();
        for key in TheoryReport::SPEC_FIELDS {
            assert!(v.get(key).is_some(), "{key}");
        }
        assert!(r.to_table().contains("winding number"));
    }

    #[test]
    fn rejects_huge_chains() {
        let p = Params::paper(60.0)
            .unwrap()
            .with(MAX_THEORY_BLOCKS + 1, 1.3, 60.0)
            .unwrap();
        assert_eq!(TheoryReport::compute(&p).unwrap_err().exit_code(), 2);
    }

    #[test]
    fn limits_give_nulls_not_panics() {
        for alpha in [0.0, 90.0, -90.0] {
            let r = TheoryReport::compute(&Params::paper(alpha).unwrap()).unwrap();
            assert!(r.winding_number.is_none(), "{alpha}");
            let json = serde_json::to_string(&r).unwrap();
            assert!(!json.contains("NaN") && !json.contains("inf"), "{json}");
        }
    }
}
