//! Geometry, energy and analytic forces of the ladder (docs/model.md; the
//! supplement's "Details of numerical simulation").
//!
//! Coordinates are stored block after block, `q = [X_1, Y_1, θ_1, X_2, ...]`
//! (index `3 i + k` for block n = i + 1). The x axis points along gravity,
//! down the ladder.

use super::params::{M, Params, R, S};
use nalgebra::DMatrix;

/// Index of X_n, Y_n, θ_n of the block with zero-based index `i` (n = i + 1).
pub const fn ix(i: usize) -> usize {
    3 * i
}
pub const fn iy(i: usize) -> usize {
    3 * i + 1
}
pub const fn itheta(i: usize) -> usize {
    3 * i + 2
}

/// (−1)^n for the block with zero-based index `i` (n = i + 1).
pub const fn parity(i: usize) -> f64 {
    if i.is_multiple_of(2) { -1.0 } else { 1.0 }
}

/// In-plane direction t and normal ν = ∂t/∂θ of block `i` at angle θ.
#[inline]
pub fn frame(i: usize, theta: f64) -> ([f64; 2], [f64; 2]) {
    let (s, c) = theta.sin_cos();
    let p = parity(i);
    ([s, p * c], [c, -p * s])
}

/// The frames (t_n, ν_n) of every block at one q, each block's sine and
/// cosine computed once: [`frame`]'s values bit for bit, for the force
/// loops of the terms (`links`, `media`), which need a block's frame for
/// each of its links and pins. Owns its buffers: [`Frames::at`] allocates
/// only when the number of blocks grows.
#[derive(Debug, Clone, Default)]
pub struct Frames {
    sin: Vec<f64>,
    cos: Vec<f64>,
}

impl Frames {
    /// The frames of the first `n` blocks at `q`.
    pub fn at(&mut self, n: usize, q: &[f64]) {
        self.sin.resize(n, 0.0);
        self.cos.resize(n, 0.0);
        for (i, (s, c)) in self.sin.iter_mut().zip(&mut self.cos).enumerate() {
            (*s, *c) = q[itheta(i)].sin_cos();
        }
    }

    /// The frames of the first `n` blocks at `q`, in new buffers.
    pub fn new(n: usize, q: &[f64]) -> Self {
        let mut f = Self::default();
        f.at(n, q);
        f
    }

    /// (t, ν) of block `i`: `frame(i, θ_i)`.
    #[inline(always)]
    pub fn get(&self, i: usize) -> ([f64; 2], [f64; 2]) {
        let (s, c) = (self.sin[i], self.cos[i]);
        let p = parity(i);
        ([s, p * c], [c, -p * s])
    }
}

/// Orientation t_n = (sin θ_n, (−1)^n cos θ_n) of block `i` at angle `theta`.
pub fn orientation(i: usize, theta: f64) -> [f64; 2] {
    let (s, c) = super::trig::sin_cos(theta);
    [s, parity(i) * c]
}

/// A-node X_n − r t_n and B-node X_n + r t_n of block `i`.
pub fn nodes(q: &[f64], i: usize) -> ([f64; 2], [f64; 2]) {
    let t = orientation(i, q[itheta(i)]);
    let (x, y) = (q[ix(i)], q[iy(i)]);
    ([x - R * t[0], y - R * t[1]], [x + R * t[0], y + R * t[1]])
}

/// The ladder model: parameters plus the derived rest length a, and the
/// terms of docs/experiments.md (`media`; none for the paper's model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ladder {
    pub params: Params,
    /// Rest length of the A springs, a = sqrt(b² + 4 s² cos²α).
    pub a: f64,
    /// Added mass, drag, links and friction; the paper's model has none,
    /// and its force loop ([`Ladder::gradient_with`]) never reads them.
    pub terms: super::terms::Terms,
    /// The toy as built (`built`): blocks with thickness, ribbons and
    /// contact in place of the springs; none for the paper's model.
    pub built: Option<super::built::AsBuilt>,
}

impl Ladder {
    pub fn new(params: Params) -> Self {
        Self {
            a: params.a(),
            params,
            terms: super::terms::Terms::default(),
            built: None,
        }
    }

    /// The same ladder as built: ribbons (and contact) in place of the
    /// springs (`built`).
    pub fn with_built(self, built: super::built::AsBuilt) -> Self {
        Self {
            built: Some(built),
            ..self
        }
    }

    /// The blocks as the toy as built sees them (`contact::Blocks`).
    pub fn blocks(&self) -> super::contact::Blocks {
        super::contact::Blocks {
            n: self.n(),
            inertia: self.params.inertia,
        }
    }

    /// Whether this is the paper's model: no term and not as built.
    pub fn is_paper_model(&self) -> bool {
        self.terms.is_paper() && self.built.is_none()
    }

    /// Whether the accelerations depend on the velocities beyond linear
    /// damping: the terms' (`Terms::velocity_dependent`) or contact.
    pub fn velocity_dependent(&self) -> bool {
        self.terms.velocity_dependent() || self.built.is_some_and(|b| b.velocity_dependent())
    }

    /// The same ladder with the terms of docs/experiments.md.
    pub fn with_terms(self, terms: super::terms::Terms) -> Self {
        Self { terms, ..self }
    }

    pub fn n(&self) -> usize {
        self.params.n
    }

    /// Ground state of sign α (docs/model.md): θ_n = α, X_n = (n − 1) b,
    /// Y_{n+1} − Y_n = (−1)^n s cos|α|, Y_1 = 0. Every A spring has length a
    /// and every B spring length b.
    pub fn ground_state(&self) -> Vec<f64> {
        let p = &self.params;
        let mut q = vec![0.0; p.dof()];
        let dy = S * p.alpha.abs().cos();
        for i in 0..p.n {
            q[ix(i)] = i as f64 * p.b;
            q[itheta(i)] = p.alpha;
            if i > 0 {
                // Y_{n+1} − Y_n with n = i (one-based index of the block above).
                q[iy(i)] = q[iy(i - 1)] + parity(i - 1) * dy;
            }
        }
        q
    }

    /// Spring lengths L_A,n and L_B,n, n = 1..N−1, written into `la`, `lb`.
    pub fn spring_lengths(&self, q: &[f64], la: &mut [f64], lb: &mut [f64]) {
        for (i, (a, b)) in self.spring_length_pairs(q).enumerate() {
            (la[i], lb[i]) = (a, b);
        }
    }

    /// (L_A,n, L_B,n) for n = 1..N−1, each block's nodes computed once.
    fn spring_length_pairs<'q>(&self, q: &'q [f64]) -> impl Iterator<Item = (f64, f64)> + 'q {
        let distance =
            |p: [f64; 2], r: [f64; 2]| ((r[0] - p[0]).powi(2) + (r[1] - p[1]).powi(2)).sqrt();
        let mut upper = nodes(q, 0);
        (1..self.n()).map(move |i| {
            let lower = nodes(q, i);
            let pair = (distance(upper.0, lower.0), distance(upper.1, lower.1));
            upper = lower;
            pair
        })
    }

    /// Elastic energy Σ ½k[(L_A,n − a)² + (L_B,n − b)²].
    pub fn elastic_energy(&self, q: &[f64]) -> f64 {
        self.spring_length_pairs(q)
            .map(|(la, lb)| 0.5 * ((la - self.a).powi(2) + (lb - self.params.b).powi(2)))
            .sum()
    }

    /// Potential energy E = Σ ½k[(L_A,n − a)² + (L_B,n − b)²] − m G Σ X_n
    /// (docs/model.md; the paper's +mgX_n has the wrong sign).
    pub fn energy(&self, q: &[f64]) -> f64 {
        let gravity: f64 = (0..self.n()).map(|i| q[ix(i)]).sum();
        self.elastic_energy(q) - M * self.params.gravity * gravity
    }

    /// Kinetic energy ½ m (Ẋ² + Ẏ²) + ½ I θ̇² summed over blocks.
    pub fn kinetic_energy(&self, v: &[f64]) -> f64 {
        v.chunks_exact(3)
            .map(|b| {
                0.5 * M * (b[0] * b[0] + b[1] * b[1]) + 0.5 * self.params.inertia * b[2] * b[2]
            })
            .sum()
    }

    /// Analytic gradient ∂E/∂q written into `grad` (same layout as `q`).
    /// Allocates its scratch; the integrators use [`Ladder::gradient_with`].
    pub fn gradient(&self, q: &[f64], grad: &mut [f64]) {
        let mut scratch = ForceScratch::new(self.n());
        self.gradient_with(q, grad, &mut scratch);
    }

    /// Analytic gradient using preallocated `scratch` (no allocation).
    ///
    /// For spring σ ∈ {A, B} between blocks n and n+1 with node offset
    /// ∓r t_n, d = p_{n+1} − p_n and L = |d|: ∂E/∂d = k (L − ℓ_σ) d / L; the
    /// node moves with X_n and rotates with ∂p/∂θ_n = ∓ r t'_n, where
    /// t'_n = (cos θ_n, −(−1)^n sin θ_n). The loops run over blocks and
    /// springs as flat arrays so that the compiler vectorises them.
    pub fn gradient_with(&self, q: &[f64], grad: &mut [f64], scratch: &mut ForceScratch) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2, checked just above.
                unsafe { gradient_avx2(self, q, grad, scratch) };
                return;
            }
        }
        gradient_body(self, q, grad, scratch);
    }

    /// The force loop compiled for the baseline CPU, whatever this one
    /// supports: the reference the AVX2 build of the same loop must match
    /// bit for bit (no fused multiply-adds; see tests/sim.rs).
    pub fn gradient_portable(&self, q: &[f64], grad: &mut [f64], scratch: &mut ForceScratch) {
        gradient_body(self, q, grad, scratch);
    }

    /// Jacobian ∂L/∂q of the spring lengths (the compatibility matrix of the
    /// finite chain, linearised about `q`). Rows are ordered
    /// [A_1, B_1, A_2, B_2, ...], 2(N − 1) rows and 3N columns.
    pub fn spring_length_jacobian(&self, q: &[f64]) -> DMatrix<f64> {
        let n = self.n();
        let mut c = DMatrix::zeros(2 * (n - 1), 3 * n);
        for (row, g) in self.spring_length_gradients(q).iter().enumerate() {
            let i = row / 2;
            for (k, x) in g.iter().enumerate() {
                c[(row, 3 * i + k)] = *x;
            }
        }
        c
    }

    /// The non-zero entries of [`Ladder::spring_length_jacobian`], row by
    /// row ([A_1, B_1, A_2, ...]): spring n joins blocks n and n + 1, and
    /// its row holds ∂L/∂(X_n, Y_n, θ_n, X_{n+1}, Y_{n+1}, θ_{n+1}). O(N)
    /// memory, where the dense matrix takes O(N²).
    pub fn spring_length_gradients(&self, q: &[f64]) -> Vec<[f64; 6]> {
        let n = self.n();
        let mut rows = Vec::with_capacity(2 * (n - 1));
        for i in 0..n - 1 {
            let f0 = BlockFrame::new(q, i);
            let f1 = BlockFrame::new(q, i + 1);
            for sign in [-1.0, 1.0] {
                let dx = (f1.x + sign * R * f1.t[0]) - (f0.x + sign * R * f0.t[0]);
                let dy = (f1.y + sign * R * f1.t[1]) - (f0.y + sign * R * f0.t[1]);
                let len = (dx * dx + dy * dy).sqrt();
                let (ux, uy) = (dx / len, dy / len);
                rows.push([
                    -ux,
                    -uy,
                    -sign * R * (ux * f0.dt[0] + uy * f0.dt[1]),
                    ux,
                    uy,
                    sign * R * (ux * f1.dt[0] + uy * f1.dt[1]),
                ]);
            }
        }
        rows
    }
}

/// Scratch arrays of the force loop, one entry per block or per spring.
#[derive(Debug, Clone)]
pub struct ForceScratch {
    parity: Vec<f64>,
    x: Vec<f64>,
    y: Vec<f64>,
    theta: Vec<f64>,
    sin: Vec<f64>,
    cos: Vec<f64>,
    /// Net force of the spring pair n on block n + 1 (x and y).
    fx: Vec<f64>,
    fy: Vec<f64>,
    /// Torque contributions of spring pair n to block n + 1 and to block n.
    torque_lower: Vec<f64>,
    torque_upper: Vec<f64>,
}

impl ForceScratch {
    /// Scratch for N blocks. Arrays are padded to a multiple of four plus
    /// four, so that every loop runs in whole SIMD lanes; the padding blocks
    /// sit far apart at θ = 0 and never enter the result.
    pub fn new(n: usize) -> Self {
        let len = padded(n) + 4;
        let z = vec![0.0; len];
        Self {
            parity: (0..len).map(parity).collect(),
            x: (0..len).map(|i| 10.0 * i as f64).collect(),
            y: z.clone(),
            theta: z.clone(),
            sin: z.clone(),
            cos: z.clone(),
            fx: z.clone(),
            fy: z.clone(),
            torque_lower: z.clone(),
            torque_upper: z,
        }
    }
}

/// `n` rounded up to a multiple of four.
const fn padded(n: usize) -> usize {
    n.div_ceil(4) * 4
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn gradient_avx2(ladder: &Ladder, q: &[f64], grad: &mut [f64], w: &mut ForceScratch) {
    gradient_body(ladder, q, grad, w)
}

/// The force loop (see [`Ladder::gradient_with`]). No fused multiply-adds:
/// the result is bit-identical with and without AVX2.
#[inline(always)]
fn gradient_body(ladder: &Ladder, q: &[f64], grad: &mut [f64], w: &mut ForceScratch) {
    let n = ladder.n();
    let m = n - 1;
    for (((b, x), y), th) in q[..3 * n]
        .chunks_exact(3)
        .zip(&mut w.x)
        .zip(&mut w.y)
        .zip(&mut w.theta)
    {
        (*x, *y, *th) = (b[0], b[1], b[2]);
    }
    // Whole lanes: sin/cos of padded(n) angles, padded(m) spring pairs.
    let (np, mp) = (padded(n), padded(m));
    super::trig::sin_cos_slice(&w.theta[..np], &mut w.sin[..np], &mut w.cos[..np]);
    let (a_rest, b_rest) = (ladder.a, ladder.params.b);
    let (x, y, s, c, p) = (
        &w.x[..=mp],
        &w.y[..=mp],
        &w.sin[..=mp],
        &w.cos[..=mp],
        &w.parity[..=mp],
    );
    let (fx, fy) = (&mut w.fx[..mp], &mut w.fy[..mp]);
    let (tl, tu) = (&mut w.torque_lower[..mp], &mut w.torque_upper[..mp]);
    for j in 0..mp {
        // t = (sin θ, p cos θ), t' = (cos θ, −p sin θ).
        let (tx0, ty0, tx1, ty1) = (s[j], p[j] * c[j], s[j + 1], p[j + 1] * c[j + 1]);
        let (ex, ey) = (x[j + 1] - x[j], y[j + 1] - y[j]);
        let (ux, uy) = (R * (tx1 - tx0), R * (ty1 - ty0));
        let (ax, ay, bx, by) = (ex - ux, ey - uy, ex + ux, ey + uy);
        let ka = 1.0 - a_rest / (ax * ax + ay * ay).sqrt();
        let kb = 1.0 - b_rest / (bx * bx + by * by).sqrt();
        let (fax, fay, fbx, fby) = (ka * ax, ka * ay, kb * bx, kb * by);
        fx[j] = fax + fbx;
        fy[j] = fay + fby;
        // A node rotates with −r t', B node with +r t'.
        let (dx, dy) = (R * (fbx - fax), R * (fby - fay));
        tu[j] = dx * c[j + 1] - dy * p[j + 1] * s[j + 1];
        tl[j] = -(dx * c[j] - dy * p[j] * s[j]);
    }
    let g = M * ladder.params.gravity;
    // Block n feels spring pair n − 1 from above and pair n from below.
    let (first, rest) = grad[..3 * n].split_at_mut(3);
    first.copy_from_slice(&[-g - fx[0], -fy[0], tl[0]]);
    let (middle, last) = rest.split_at_mut(3 * (m - 1));
    for (j, b) in middle.chunks_exact_mut(3).enumerate() {
        // Block j + 2 (zero-based j + 1): pair j above, pair j + 1 below.
        b[0] = -g + fx[j] - fx[j + 1];
        b[1] = fy[j] - fy[j + 1];
        b[2] = tu[j] + tl[j + 1];
    }
    last.copy_from_slice(&[-g + fx[m - 1], fy[m - 1], tu[m - 1]]);
}

/// Centre, orientation t_n and its derivative dt_n/dθ_n of one block.
#[derive(Clone, Copy)]
struct BlockFrame {
    x: f64,
    y: f64,
    t: [f64; 2],
    dt: [f64; 2],
}

impl BlockFrame {
    #[inline(always)]
    fn new(q: &[f64], i: usize) -> Self {
        let (s, c) = super::trig::sin_cos(q[itheta(i)]);
        let p = parity(i);
        Self {
            x: q[ix(i)],
            y: q[iy(i)],
            t: [s, p * c],
            dt: [c, -p * s],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ground_state_lengths_are_rest_lengths() {
        for alpha in [60.0, -60.0, 86.0, -50.0, 10.0] {
            let ladder = Ladder::new(Params::paper(alpha).unwrap());
            let q = ladder.ground_state();
            let (mut la, mut lb) = (vec![0.0; 9], vec![0.0; 9]);
            ladder.spring_lengths(&q, &mut la, &mut lb);
            for k in 0..9 {
                assert!((la[k] - ladder.a).abs() < 1e-14, "A {k}: {}", la[k]);
                assert!((lb[k] - 1.3).abs() < 1e-14, "B {k}: {}", lb[k]);
            }
        }
    }

    #[test]
    fn jacobian_matches_finite_differences() {
        let ladder = Ladder::new(Params::paper(60.0).unwrap());
        let mut q = ladder.ground_state();
        for (k, x) in q.iter_mut().enumerate() {
            *x += 0.05 * ((k as f64) * 1.7).sin();
        }
        let c = ladder.spring_length_jacobian(&q);
        let n = ladder.n();
        let lengths = |q: &[f64]| {
            let (mut la, mut lb) = (vec![0.0; n - 1], vec![0.0; n - 1]);
            ladder.spring_lengths(q, &mut la, &mut lb);
            la.iter()
                .zip(&lb)
                .flat_map(|(a, b)| [*a, *b])
                .collect::<Vec<_>>()
        };
        let h = 1e-6;
        for col in 0..q.len() {
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[col] += h;
            qm[col] -= h;
            let (lp, lm) = (lengths(&qp), lengths(&qm));
            for row in 0..lp.len() {
                let fd = (lp[row] - lm[row]) / (2.0 * h);
                assert!((fd - c[(row, col)]).abs() < 1e-8, "({row},{col})");
            }
        }
    }
}
