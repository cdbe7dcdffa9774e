use super::*;
use crate::model::ribbons::tests::{column, tank_ribbons};

/// A bent, moving state of three blocks round the hanging column.
fn state() -> (Vec<f64>, Vec<f64>) {
    let mut q = column(3, 1.5);
    let bends = [0.0, 0.0, 0.3, 0.05, -0.02, -0.4, -0.03, 0.04, 0.9];
    for (x, d) in q.iter_mut().zip(bends) {
        *x += d;
    }
    let v = vec![0.0, 0.0, 0.01, 0.002, -0.001, -0.02, 0.001, 0.003, 0.015];
    (q, v)
}

fn lengths(q: &[f64]) -> Vec<f64> {
    let r = tank_ribbons(1.5);
    r.spans(q.len() / 3, q)
        .iter()
        .map(|(_, s)| s.length)
        .collect()
}

fn rows_at(q: &[f64], v: &[f64]) -> Vec<(usize, Row)> {
    let r = tank_ribbons(1.5);
    let n = q.len() / 3;
    let mut out = Vec::new();
    r.for_each_span(n, q, |i, pu, pl, s| {
        let k = out.len();
        out.push((i, row(s, r.ribbons[k % 2].rest, (pu, pl), i, v)));
    });
    out
}

#[test]
fn a_rows_gradient_and_rate_are_its_lengths_derivatives() {
    let (q, v) = state();
    let rows = rows_at(&q, &v);
    let h = 1e-7;
    for (k, (i, r)) in rows.iter().enumerate() {
        let g: Vec<f64> = r.upper.iter().chain(&r.lower).copied().collect();
        for (c, gc) in g.iter().enumerate() {
            let at = 3 * i + c;
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[at] += h;
            qm[at] -= h;
            let fd = (lengths(&qp)[k] - lengths(&qm)[k]) / (2.0 * h);
            assert!(
                (fd - gc).abs() < 1e-6,
                "ribbon {k}, coordinate {at}: {fd} against {gc}"
            );
        }
        let rate: f64 = g.iter().zip(&v[3 * i..3 * i + 6]).map(|(a, b)| a * b).sum();
        assert!(
            (rate - r.rate).abs() < 1e-12,
            "ribbon {k}: {rate} against {}",
            r.rate
        );
    }
}

#[test]
fn the_banded_solve_is_the_dense_solution() {
    // A symmetric positive definite band of width 3, n = 7.
    let n = 7;
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        a[i * n + i] = 4.0 + i as f64;
        for d in 1..=3 {
            if i + d < n {
                let x = 0.5 / d as f64;
                a[i * n + i + d] = x;
                a[(i + d) * n + i] = x;
            }
        }
    }
    let x: Vec<f64> = (0..n).map(|i| (i as f64 - 2.5) * 0.7).collect();
    let mut b: Vec<f64> = (0..n)
        .map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum())
        .collect();
    let mut work = a.clone();
    assert!(solve_banded(&mut work, &mut b, n, 3));
    for i in 0..n {
        assert!(
            (b[i] - x[i]).abs() < 1e-12,
            "{i}: {} against {}",
            b[i],
            x[i]
        );
    }
    let mut singular = vec![1.0, 1.0, 1.0, 1.0];
    assert!(!solve_banded(&mut singular, &mut [1.0, 1.0], 2, 3));
}
