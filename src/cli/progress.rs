//! Progress bars on standard error (hidden when it is not a terminal).

/// A progress bar on stderr (hidden when stderr is not a terminal).
/// A progress callback for a study: shows `msg` and counts one item.
pub(crate) fn ticker(bar: &indicatif::ProgressBar) -> impl Fn(&str) + Sync + '_ {
    move |msg| {
        bar.set_message(msg.to_string());
        bar.inc(1);
    }
}

/// A progress bar over simulated time, shown only for a run long enough
/// to wait for (over 10^5 τ of simulated time) and only on a terminal.
pub(crate) fn time_bar(t_end: f64) -> indicatif::ProgressBar {
    if t_end < 1e5 {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(t_end as u64);
    let style = indicatif::ProgressStyle::with_template(
        "simulating [{bar:30}] t/τ = {pos}/{len} {elapsed} (eta {eta})",
    )
    .map(|s| s.progress_chars("=> "));
    if let Ok(style) = style {
        bar.set_style(style);
    }
    bar
}

pub(crate) fn progress_bar(len: u64, what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    let style =
        indicatif::ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} {elapsed} {msg}")
            .map(|s| s.progress_chars("=> "));
    if let Ok(style) = style {
        bar.set_style(style);
    }
    bar.set_prefix(what.to_string());
    bar
}
