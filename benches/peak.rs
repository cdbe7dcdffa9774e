//! This CPU's limits, beside the kernels that should approach them
//! (docs/performance.md, "The machine's limit"):
//!
//! - the clock: a chain of dependent integer additions (one cycle each);
//! - floating-point throughput: fused multiply-adds on ten independent
//!   accumulators (enough to hide the FMA latency on two ports), scalar,
//!   4 lanes (AVX2) and 8 lanes (AVX-512), in FMAs per cycle and GFLOP/s;
//! - read bandwidth from each level of the memory (8 KB, 512 KB, 64 MB);
//! - the latency of an 8-lane division, square root, multiplication and
//!   addition (dependent chains): what bounds a chain of dependent steps;
//! - the chain kernel (symplectic Euler, N = 1000, the paper's dt) and the
//!   batch kernel (a sweep of N = 10 kinks, symplectic Euler at the
//!   paper's dt and Verlet at the scenes' 0.25) in ns and cycles per
//!   block-step, on one core.
//!
//! `cargo bench --bench peak` prints one table; each number is the median
//! of 7 rounds of CPU time (the process's, so that other jobs' turns on a
//! shared core do not count).

use jacobs_ladder::bench::kernels::sweep_scenarios;
use jacobs_ladder::model::Params;
use jacobs_ladder::sim::{self, IntegratorConfig, RunOptions, Scenario, Stepping, batch};
use std::hint::black_box;

const ROUNDS: usize = 7;

/// This process's CPU time in seconds (every thread): on a shared machine
/// it counts the cycles this work got, where the wall clock also counts
/// other jobs' turns.
fn cpu_seconds() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec for the call to fill.
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// Median of `ROUNDS` CPU timings of `f`, in seconds.
fn median(mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..ROUNDS)
        .map(|_| {
            let start = cpu_seconds();
            f();
            cpu_seconds() - start
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[ROUNDS / 2]
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::asm;

    /// `n` iterations of 8 dependent one-cycle register additions (not
    /// additions of an immediate, which some cores fold at rename).
    pub fn add_chain(n: u64) {
        let mut x = 0u64;
        unsafe {
            asm!(
                "2:",
                "add {x}, {y}", "add {x}, {y}", "add {x}, {y}", "add {x}, {y}",
                "add {x}, {y}", "add {x}, {y}", "add {x}, {y}", "add {x}, {y}",
                "dec {n}",
                "jnz 2b",
                x = inout(reg) x,
                y = in(reg) 3u64,
                n = inout(reg) n => _,
                options(nomem, nostack),
            );
        }
        std::hint::black_box(x);
    }

    /// Ten independent FMA chains of `n` steps on `$reg` registers.
    macro_rules! fma_loop {
        ($name:ident, $feature:literal, $op:literal, $r:literal) => {
            #[target_feature(enable = $feature)]
            pub unsafe fn $name(n: u64) {
                unsafe {
                    asm!(
                        concat!("vxorpd ", $r, "0, ", $r, "0, ", $r, "0"),
                        concat!("vxorpd ", $r, "1, ", $r, "1, ", $r, "1"),
                        concat!("vxorpd ", $r, "2, ", $r, "2, ", $r, "2"),
                        "2:",
                        concat!($op, " ", $r, "3, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "4, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "5, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "6, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "7, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "8, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "9, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "10, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "11, ", $r, "1, ", $r, "2"),
                        concat!($op, " ", $r, "12, ", $r, "1, ", $r, "2"),
                        "dec {n}",
                        "jnz 2b",
                        n = inout(reg) n => _,
                        out("xmm0") _, out("xmm1") _, out("xmm2") _, out("xmm3") _,
                        out("xmm4") _, out("xmm5") _, out("xmm6") _, out("xmm7") _,
                        out("xmm8") _, out("xmm9") _, out("xmm10") _, out("xmm11") _,
                        out("xmm12") _,
                        options(nomem, nostack),
                    );
                }
            }
        };
    }
    fma_loop!(fma_scalar, "fma", "vfmadd231sd", "xmm");
    fma_loop!(fma_ymm, "fma", "vfmadd231pd", "ymm");
    fma_loop!(fma_zmm, "avx512f", "vfmadd231pd", "zmm");

    /// Ten independent divisions (or square roots) of 8 lanes a step, of
    /// `n` steps: the divider's throughput.
    macro_rules! divider_loop {
        ($name:ident, $insn:literal) => {
            #[target_feature(enable = "avx512f")]
            pub unsafe fn $name(n: u64) {
                unsafe {
                    asm!(
                        "vbroadcastsd zmm1, xmm13",
                        "vbroadcastsd zmm2, xmm14",
                        "2:",
                        concat!($insn, " zmm3, zmm1, zmm2"),
                        concat!($insn, " zmm4, zmm1, zmm2"),
                        concat!($insn, " zmm5, zmm1, zmm2"),
                        concat!($insn, " zmm6, zmm1, zmm2"),
                        concat!($insn, " zmm7, zmm1, zmm2"),
                        concat!($insn, " zmm8, zmm1, zmm2"),
                        concat!($insn, " zmm9, zmm1, zmm2"),
                        concat!($insn, " zmm10, zmm1, zmm2"),
                        concat!($insn, " zmm11, zmm1, zmm2"),
                        concat!($insn, " zmm12, zmm1, zmm2"),
                        "dec {n}",
                        "jnz 2b",
                        n = inout(reg) n => _,
                        in("xmm13") 1.5f64, in("xmm14") 1.25f64,
                        out("xmm1") _, out("xmm2") _, out("xmm3") _,
                        out("xmm4") _, out("xmm5") _, out("xmm6") _, out("xmm7") _,
                        out("xmm8") _, out("xmm9") _, out("xmm10") _, out("xmm11") _,
                        out("xmm12") _,
                        options(nomem, nostack),
                    );
                }
            }
        };
    }
    divider_loop!(div_zmm, "vdivpd");

    /// A chain of `n` × 8 dependent 8-lane `$insn`s (each takes the last
    /// one's result): the instruction's latency.
    macro_rules! latency_loop {
        ($name:ident, $a:literal, $b:literal, $c:literal, $d:literal) => {
            #[target_feature(enable = "avx512f")]
            pub unsafe fn $name(n: u64) {
                unsafe {
                    asm!(
                        "vbroadcastsd zmm1, xmm13",
                        "vbroadcastsd zmm2, xmm14",
                        "2:",
                        $a, $b, $c, $d, $a, $b, $c, $d,
                        "dec {n}",
                        "jnz 2b",
                        n = inout(reg) n => _,
                        in("xmm13") 1.0f64, in("xmm14") 1.0f64,
                        out("xmm1") _, out("xmm2") _,
                        options(nomem, nostack),
                    );
                }
            }
        };
    }
    // x ← x / 1 and x ← √x keep 1.0 (no denormals, no early exit).
    latency_loop!(
        div_chain,
        "vdivpd zmm1, zmm1, zmm2",
        "vdivpd zmm1, zmm1, zmm2",
        "vdivpd zmm1, zmm1, zmm2",
        "vdivpd zmm1, zmm1, zmm2"
    );
    latency_loop!(
        sqrt_chain,
        "vsqrtpd zmm1, zmm1",
        "vsqrtpd zmm1, zmm1",
        "vsqrtpd zmm1, zmm1",
        "vsqrtpd zmm1, zmm1"
    );
    latency_loop!(
        mul_chain,
        "vmulpd zmm1, zmm1, zmm2",
        "vmulpd zmm1, zmm1, zmm2",
        "vmulpd zmm1, zmm1, zmm2",
        "vmulpd zmm1, zmm1, zmm2"
    );
    latency_loop!(
        add_chain_pd,
        "vaddpd zmm1, zmm1, zmm2",
        "vsubpd zmm1, zmm1, zmm2",
        "vaddpd zmm1, zmm1, zmm2",
        "vsubpd zmm1, zmm1, zmm2"
    );
    /// Ten independent 8-lane square roots a step, of `n` steps.
    #[target_feature(enable = "avx512f")]
    pub unsafe fn sqrt_zmm(n: u64) {
        unsafe {
            asm!(
                "vbroadcastsd zmm2, xmm14",
                "2:",
                "vsqrtpd zmm3, zmm2", "vsqrtpd zmm4, zmm2", "vsqrtpd zmm5, zmm2",
                "vsqrtpd zmm6, zmm2", "vsqrtpd zmm7, zmm2", "vsqrtpd zmm8, zmm2",
                "vsqrtpd zmm9, zmm2", "vsqrtpd zmm10, zmm2", "vsqrtpd zmm11, zmm2",
                "vsqrtpd zmm12, zmm2",
                "dec {n}",
                "jnz 2b",
                n = inout(reg) n => _,
                in("xmm14") 1.25f64,
                out("xmm2") _, out("xmm3") _,
                out("xmm4") _, out("xmm5") _, out("xmm6") _, out("xmm7") _,
                out("xmm8") _, out("xmm9") _, out("xmm10") _, out("xmm11") _,
                out("xmm12") _,
                options(nomem, nostack),
            );
        }
    }
}

/// GHz from the dependent addition chain.
#[cfg(target_arch = "x86_64")]
fn clock_ghz() -> f64 {
    let n = 50_000_000u64;
    let s = median(|| x86::add_chain(black_box(n)));
    8.0 * n as f64 / s / 1e9
}

/// FMAs per cycle for each width this CPU has: (name, lanes, FMAs/cycle).
#[cfg(target_arch = "x86_64")]
fn fma_rates(ghz: f64) -> Vec<(&'static str, usize, f64)> {
    let n = 20_000_000u64;
    let per_cycle = |s: f64| 10.0 * n as f64 / s / (ghz * 1e9);
    let mut out = Vec::new();
    if is_x86_feature_detected!("fma") {
        // SAFETY: the feature was detected at run time.
        let s = median(|| unsafe { x86::fma_scalar(black_box(n)) });
        out.push(("scalar", 1, per_cycle(s)));
        let s = median(|| unsafe { x86::fma_ymm(black_box(n)) });
        out.push(("AVX2", 4, per_cycle(s)));
    }
    if is_x86_feature_detected!("avx512f") {
        let s = median(|| unsafe { x86::fma_zmm(black_box(n)) });
        out.push(("AVX-512", 8, per_cycle(s)));
    }
    out
}

/// Cycles per 8-lane division and per 8-lane square root (throughput), if
/// this CPU has AVX-512.
#[cfg(target_arch = "x86_64")]
fn divider_cycles(ghz: f64) -> Option<(f64, f64)> {
    if !is_x86_feature_detected!("avx512f") {
        return None;
    }
    let n = 2_000_000u64;
    let cycles = |s: f64| s * ghz * 1e9 / (10.0 * n as f64);
    // SAFETY: the feature was detected at run time.
    let div = median(|| unsafe { x86::div_zmm(black_box(n)) });
    let sqrt = median(|| unsafe { x86::sqrt_zmm(black_box(n)) });
    Some((cycles(div), cycles(sqrt)))
}

/// Latency in cycles of an 8-lane division, square root, multiplication
/// and addition (dependent chains), if this CPU has AVX-512.
#[cfg(target_arch = "x86_64")]
fn latencies(ghz: f64) -> Option<[(&'static str, f64); 4]> {
    if !is_x86_feature_detected!("avx512f") {
        return None;
    }
    let cycles = |n: u64, s: f64| s * ghz * 1e9 / (8.0 * n as f64);
    let (slow, fast) = (2_000_000u64, 20_000_000u64);
    // SAFETY: the feature was detected at run time.
    unsafe {
        Some([
            (
                "vdivpd",
                cycles(slow, median(|| x86::div_chain(black_box(slow)))),
            ),
            (
                "vsqrtpd",
                cycles(slow, median(|| x86::sqrt_chain(black_box(slow)))),
            ),
            (
                "vmulpd",
                cycles(fast, median(|| x86::mul_chain(black_box(fast)))),
            ),
            (
                "vaddpd",
                cycles(fast, median(|| x86::add_chain_pd(black_box(fast)))),
            ),
        ])
    }
}

/// Read bandwidth in GB/s from an array of `bytes` (summed in 32
/// independent lanes, so that the additions' latency does not bound it).
fn read_bandwidth(bytes: usize) -> f64 {
    let v = vec![1.0f64; bytes / 8];
    let passes = (1usize << 30) / bytes;
    let s = median(|| {
        for _ in 0..passes {
            let mut acc = [0.0f64; 32];
            for c in black_box(&v).chunks_exact(32) {
                for (a, x) in acc.iter_mut().zip(c) {
                    *a += x;
                }
            }
            black_box(acc);
        }
    });
    (passes * bytes) as f64 / s / 1e9
}

/// ns per block-step of one run of N blocks on the fastest kernel (the
/// chain kernel for N > 32), one core.
fn chain_ns(n: usize) -> f64 {
    let config = IntegratorConfig::paper();
    let steps = (2e7 / n as f64).ceil();
    let params = Params::paper(60.0).unwrap().with(n, 1.3, 60.0).unwrap();
    let scenario = Scenario::single_flip(params, 1000.0, steps * config.dt).unwrap();
    let options = RunOptions::default()
        .stepping(Stepping::Fastest)
        .every_step(false);
    let ran = sim::run(&scenario, &[], &config, &options).unwrap().steps;
    let s = median(|| {
        black_box(sim::run(black_box(&scenario), &[], &config, &options).ok());
    });
    s * 1e9 / (ran as f64 * n as f64)
}

/// ns per block-step of a 64-run sweep of N = 10 kinks in the batch
/// kernel, on one core, by `config`'s scheme and step.
fn batch_ns(config: &IntegratorConfig) -> f64 {
    let config = *config;
    let scenarios = sweep_scenarios(64, 10, 100.0).unwrap();
    let alone = RunOptions::default()
        .stepping(Stepping::Fastest)
        .every_step(false);
    let steps: u64 = scenarios
        .iter()
        .map(|sc| sim::run(sc, &[], &config, &alone).unwrap().steps)
        .sum();
    let one_core = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let s = median(|| {
        one_core.install(|| {
            black_box(batch::simulate_many(
                black_box(&scenarios),
                &config,
                &RunOptions::default(),
            ))
        });
    });
    s * 1e9 / (steps as f64 * 10.0)
}

fn main() {
    #[cfg(target_arch = "x86_64")]
    {
        let ghz = clock_ghz();
        println!("clock (dependent additions): {ghz:.2} GHz");
        for (name, lanes, rate) in fma_rates(ghz) {
            let gflops = rate * lanes as f64 * 2.0 * ghz;
            println!(
                "FMA {name:8} {rate:.2} FMAs/cycle = {:.1} flops/cycle, {gflops:.1} GFLOP/s per core",
                rate * lanes as f64 * 2.0
            );
        }
        if let Some((div, sqrt)) = divider_cycles(ghz) {
            println!(
                "divider (AVX-512, 8 lanes): vdivpd {div:.1} cycles, vsqrtpd {sqrt:.1} cycles each"
            );
        }
        if let Some(l) = latencies(ghz) {
            let l: Vec<String> = l.iter().map(|(n, c)| format!("{n} {c:.1}")).collect();
            println!("latency (AVX-512, cycles): {}", l.join(", "));
        }
        for (name, bytes) in [
            ("L1 (8 KB)", 8 << 10),
            ("L2 (512 KB)", 512 << 10),
            ("memory (64 MB)", 64 << 20),
        ] {
            println!("read {name:15} {:.1} GB/s", read_bandwidth(bytes));
        }
        for n in [1000, 100_000] {
            let ns = chain_ns(n);
            println!(
                "chain kernel N = {n}: {ns:.2} ns = {:.1} cycles per block-step",
                ns * ghz
            );
        }
        for (name, config) in [
            ("symplectic Euler, dt = 0.01", IntegratorConfig::paper()),
            (
                "Verlet, dt = 0.25",
                IntegratorConfig::fixed(sim::IntegratorKind::Verlet, 0.25),
            ),
        ] {
            let ns = batch_ns(&config);
            println!(
                "batch kernel, 64 runs of N = 10, {name}, one core: {ns:.2} ns = {:.1} cycles \
                 per block-step",
                ns * ghz
            );
        }
    }
}
