//! Redraws `work-precision.png` and `stability.png` from the JSON that
//! `ladder bench work-precision --json` and `ladder bench stability --json`
//! printed, without running the studies again:
//!
//! `cargo run --release --example bench_charts -- wp.json st.json OUT_DIR`

use jacobs_ladder::bench::{self, StabilityReport, WorkPrecisionReport};
use jacobs_ladder::{encode, output};
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [wp, st, out] = args.as_slice() else {
        return Err("usage: bench_charts WORK_PRECISION.json STABILITY.json OUT_DIR".into());
    };
    let out = PathBuf::from(out);
    output::ensure_dir(&out)?;
    let wp: WorkPrecisionReport = serde_json::from_str(&std::fs::read_to_string(wp)?)?;
    let image = bench::work_precision_chart(&wp)?;
    output::write_atomic(&out.join("work-precision.png"), &encode::png_bytes(&image)?)?;
    let st: StabilityReport = serde_json::from_str(&std::fs::read_to_string(st)?)?;
    let image = bench::stability_chart(&st)?;
    output::write_atomic(&out.join("stability.png"), &encode::png_bytes(&image)?)?;
    println!("{}", bench::stability_caption(&st));
    Ok(())
}
