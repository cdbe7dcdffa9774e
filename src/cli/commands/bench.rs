//! `ladder bench`: the work-precision, stability and kernel studies.

use crate::cli::progress::{progress_bar, ticker};
use crate::cli::*;
use crate::error::{Error, Result};
use crate::output;
use crate::sim::IntegratorKind;
use serde::Serialize;

pub(crate) fn bench(args: &BenchArgs) -> Result<()> {
    if !(1..=100).contains(&args.repeats) {
        return Err(Error::bad_input(format!(
            "--repeats must be between 1 and 100, got {}",
            args.repeats
        )));
    }
    if args.scene == "paper" && args.t_end.is_some() {
        return Err(Error::bad_input(
            "--t-end: the paper's scene keeps its 4000 τ; give --scene ID of a built-in movie",
        ));
    }
    if let Some(t) = args.t_end
        && !(t.is_finite() && t > 0.0 && t <= 1e6)
    {
        return Err(Error::bad_input(format!(
            "--t-end must be a number of τ above 0 and at most 1e6, got {}",
            crate::error::num(t)
        )));
    }
    match args.study.as_str() {
        "work-precision" | "stability" => output::check_targets(&[
            args.out.join(format!("{}.csv", args.study)),
            args.out.join(format!("{}.png", args.study)),
        ])?,
        "kernels" => return bench_kernels(args),
        "cost" => return bench_cost(args),
        other => {
            return Err(Error::bad_input(format!(
                "unknown study '{other}'; choose work-precision, stability, kernels or cost"
            )));
        }
    }
    match args.study.as_str() {
        "work-precision" => bench_work_precision(args),
        _ => bench_stability(args),
    }
}

/// The caps of the study's flags (`--max-block-steps`).
fn study_limits(args: &BenchArgs) -> Result<crate::limits::Limits> {
    crate::cli::args::LimitArgs {
        max_block_steps: args.limits.max_block_steps,
        ..Default::default()
    }
    .caps()
}

pub(crate) fn bench_kernels(args: &BenchArgs) -> Result<()> {
    let runs = args.repeats * crate::bench::kernels::kernel_count();
    let bar = progress_bar(runs as u64, "kernels");
    let report = crate::bench::kernels(args.repeats, &ticker(&bar))?;
    bar.finish_and_clear();
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&crate::bench::kernels_table(&report))
    }
}

/// `bench cost`: the cost model's numbers measured (`bench::weights`);
/// prints only.
pub(crate) fn bench_cost(args: &BenchArgs) -> Result<()> {
    let bar = progress_bar(args.repeats as u64 * 11, "cost");
    let report = crate::bench::weights::cost(args.repeats, &ticker(&bar))?;
    bar.finish_and_clear();
    if args.json {
        output::print(&format!("{}\n", to_json(&report)?))
    } else {
        output::print(&crate::bench::weights::cost_table(&report))
    }
}

pub(crate) fn bench_work_precision(args: &BenchArgs) -> Result<()> {
    use crate::bench::{self, BenchScene};
    let scenes = match args.scene.as_str() {
        "paper" => vec![BenchScene::paper(60.0)?, BenchScene::paper(-60.0)?],
        id => vec![BenchScene::movie(id, args.t_end, 200)?],
    };
    bench::check_work_precision_cost(&scenes, args.repeats, &study_limits(args)?)?;
    let total: usize = scenes.len()
        * IntegratorKind::ALL
            .iter()
            .map(|k| bench::default_steps(*k).len())
            .sum::<usize>();
    let bar = progress_bar(total as u64, "work-precision");
    let report = bench::work_precision(&scenes, args.repeats, &ticker(&bar))?;
    bar.finish_and_clear();
    let chart = bench::work_precision_chart(&report)?;
    let csv = bench::work_precision_csv(&report);
    let table = bench::work_precision_table(&report);
    write_study(args, "work-precision", &csv, &chart, &report, &table)
}

/// Writes a study's chart and CSV (`DIR/NAME.png`, `DIR/NAME.csv`; the PNG
/// is encoded before anything is written) and prints its JSON or table.
pub(crate) fn write_study<T: Serialize>(
    args: &BenchArgs,
    name: &str,
    csv_text: &str,
    chart: &tiny_skia::Pixmap,
    report: &T,
    table: &str,
) -> Result<()> {
    let png_bytes = crate::encode::png_bytes(chart)?;
    let (csv, png) = (
        args.out.join(format!("{name}.csv")),
        args.out.join(format!("{name}.png")),
    );
    crate::output::write_atomic(&csv, csv_text.as_bytes())?;
    crate::output::write_atomic(&png, &png_bytes)?;
    if args.json {
        output::print(&format!("{}\n", to_json(report)?))
    } else {
        output::print(&format!(
            "{table}wrote {} and {}\n",
            csv.display(),
            png.display()
        ))
    }
}

pub(crate) fn bench_stability(args: &BenchArgs) -> Result<()> {
    use crate::bench;
    if args.scene != "paper" {
        let scene = bench::BenchScene::movie(&args.scene, args.t_end, 0)?;
        bench::check_stability_cost(&scene, &study_limits(args)?)?;
        let bar = progress_bar(IntegratorKind::ALL.len() as u64, "stability");
        let report = bench::stability_of_scene(&scene, &ticker(&bar))?;
        bar.finish_and_clear();
        let chart = bench::stability_chart(&report)?;
        let csv = bench::stability_csv(&report);
        let table = bench::stability_table(&report);
        return write_study(args, "stability", &csv, &chart, &report, &table);
    }
    let alphas = bench::STABILITY_ALPHAS;
    let bar = progress_bar(alphas.len() as u64, "stability");
    let report = bench::stability(&alphas, &ticker(&bar))?;
    bar.finish_and_clear();
    let chart = bench::stability_chart(&report)?;
    let csv = bench::stability_csv(&report);
    let table = bench::stability_table(&report);
    write_study(args, "stability", &csv, &chart, &report, &table)
}
