//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod fuzz;
pub mod gif;
pub mod golden;
pub mod h264;
pub mod kernels;
pub mod latex;
pub mod lcg;
pub mod pdf;
pub mod pngio;
pub mod require;
pub mod scenes;
pub mod tempdir;

/// The theme of the screen style (the catalogue's default), for tests
/// that draw at it.
pub fn screen() -> jacobs_ladder::render::Theme {
    jacobs_ladder::render::Theme::of(&jacobs_ladder::render::Style::default())
}

/// Runs the `ladder` binary with `args` and waits for it.
pub fn ladder_cli(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("the ladder binary runs")
}

/// `ladder all --frames 20 --size 320x240` and `extra` flags into `dir`
/// (emptied first), small and fast; its standard output. Fails the test
/// unless it exits 0.
pub fn render_catalogue(dir: &std::path::Path, extra: &[&str]) -> String {
    let _ = std::fs::remove_dir_all(dir);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["all", "--frames", "20", "--size", "320x240"])
        .args(extra)
        .arg("--out")
        .arg(dir)
        .output()
        .expect("the ladder binary runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("the output is UTF-8")
}

/// The figure and movie formats of [`catalogue_render`]: every format
/// but PNG (figures then get a PNG preview, which the page shows), so
/// that one render serves the gallery's page checks (links, previews, a
/// real browser loading every image and video) and the timings table.
pub const CATALOGUE_FORMATS: &str = if cfg!(feature = "mp4") {
    "svg,pdf,gif,mp4"
} else {
    "svg,pdf,gif"
};

/// [`render_catalogue`] with `--timings` in [`CATALOGUE_FORMATS`], made
/// once for every test that reads the whole catalogue's render (the
/// gallery's links, previews and browser check, the timings table): its
/// folder and the table it printed. The ring chain alone makes a render
/// of the catalogue cost half a minute of CPU; tests that need other
/// styles render their own. Readers must not change the folder (copy it,
/// as the browser check does, to add pages).
pub fn catalogue_render() -> &'static (std::path::PathBuf, String) {
    static RENDER: std::sync::OnceLock<(std::path::PathBuf, String)> = std::sync::OnceLock::new();
    RENDER.get_or_init(|| {
        // Under target/tmp: replaced by the next run, never left in /tmp.
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("catalogue-render");
        let table = render_catalogue(&dir, &["--timings", "--format", CATALOGUE_FORMATS]);
        (dir, table)
    })
}

/// `ladder all --style STYLE --format pdf --frames 20` (STYLE `paper` or
/// `paper-wide`), made once for every test that reads the catalogue as
/// printed (that it renders at all, the article that prints it): its
/// folder, under target/tmp. Readers must not change it.
pub fn print_render(style: &str) -> &'static std::path::Path {
    static PAPER: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    static WIDE: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    let cell = match style {
        "paper" => &PAPER,
        "paper-wide" => &WIDE,
        _ => panic!("print_render: {style} is not a print style"),
    };
    cell.get_or_init(|| {
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("print-{style}"));
        let _ = std::fs::remove_dir_all(&dir);
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args([
                "all", "--style", style, "--format", "pdf", "--frames", "20", "--out",
            ])
            .arg(&dir)
            .output()
            .expect("the ladder binary runs");
        assert_eq!(
            out.status.code(),
            Some(0),
            "{style}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        dir
    })
}
