//! The gallery page `index.html` as a reader meets it: every file it names
//! exists, every picture has one caption and words for its alt text, the
//! model level is said once per section, a figure asked only as PDF still
//! shows a PNG preview, and, in a real browser (Debian's `chromium`,
//! headless), every image and video loads, the grid has no holes and the
//! page is under 7,000 px tall at 1400 px wide. The browser test saves screenshots under
//! `target/tmp/gallery/` to look at. Without chromium it fails under CI
//! and is reported as skipped elsewhere (`common::require`; `.ci/run`
//! installs chromium).
//!
//! All three read one render of the catalogue (`common::catalogue_render`,
//! every format but PNG, shared with the timings test): a render costs
//! half a minute of CPU, whatever its formats.

use crate::common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A copy of the catalogue's shared render (`common::catalogue_render`,
/// every format but PNG) in a fresh folder of its own, for a test that
/// adds pages to it.
fn copy_of_render(tag: &str) -> PathBuf {
    let from = &crate::common::catalogue_render().0;
    let dir = std::env::temp_dir().join(format!("ladder-gallery-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        std::fs::copy(e.path(), dir.join(e.file_name())).unwrap();
    }
    dir
}

/// The values of attribute `attr` (`src="..."`) in `html`, unescaped.
fn attributes(html: &str, attr: &str) -> Vec<String> {
    let key = format!(" {attr}=\"");
    html.split(&key)
        .skip(1)
        .filter_map(|s| s.split_once('"').map(|(v, _)| v.replace("&amp;", "&")))
        .collect()
}

/// Every file the page names was written, and every file written is named.
fn check_links(dir: &Path, html: &str) -> BTreeSet<String> {
    let written: BTreeSet<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f != "index.html")
        .collect();
    let linked: BTreeSet<String> = attributes(html, "href")
        .into_iter()
        .chain(attributes(html, "src"))
        .filter(|h| !h.starts_with('#'))
        .collect();
    for f in &linked {
        assert!(
            written.contains(f),
            "the page names {f}, which is not written"
        );
    }
    for f in &written {
        assert!(
            linked.contains(f),
            "{f} was written but the page does not link it"
        );
    }
    written
}

/// The cards of the page, each from its `<figure` to its `</figure>`.
fn cards(html: &str) -> Vec<&str> {
    html.split("<figure class=\"card")
        .skip(1)
        .map(|c| c.split("</figure>").next().unwrap())
        .collect()
}

/// The paragraphs `<p class="level" ...>` of the page, without their tags.
fn level_sentences(html: &str) -> Vec<&str> {
    html.split("<p class=\"level\"")
        .skip(1)
        .map(|p| {
            let p = p.split_once('>').unwrap().1;
            let p = p.split("</p>").next().unwrap();
            // "<b>Fig. 1c, Fig. 3:</b> Simulated: …" → the sentence.
            p.rsplit_once("</b> ").map_or(p, |(_, s)| s)
        })
        .collect()
}

#[test]
fn every_link_and_picture_of_the_page_is_a_file_the_run_wrote() {
    // The catalogue's default render, shared with the timings test.
    let dir = &crate::common::catalogue_render().0;
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let written = check_links(dir, &html);
    // One card per scene, each with exactly one caption, and alt text in words.
    // One data file per scene: as many cards, the paper's 13 figures and 9
    // movies at least.
    let n_cards = html.matches("<figure class=\"card").count();
    let scenes = written.iter().filter(|f| f.ends_with(".json")).count();
    assert!(
        n_cards == scenes && n_cards >= 22,
        "{n_cards} cards, {scenes} scenes"
    );
    assert_eq!(html.matches("<figcaption>").count(), n_cards);
    for alt in attributes(&html, "alt") {
        assert!(
            alt.len() > 40 && !alt.contains(".png") && !alt.contains(".gif"),
            "alt text should describe the picture: {alt}"
        );
    }
    // The model level is a sentence, never a bare word, said once per
    // section (not on each of the 20-odd simulated cards); each card names
    // its level in a word, linked to the sentence.
    let levels = level_sentences(&html);
    assert!(!levels.is_empty());
    for sentence in &levels {
        assert!(
            sentence.split_whitespace().count() > 6 && sentence.ends_with('.'),
            "{sentence}"
        );
    }
    let simulated = "Simulated: the full nonlinear equations";
    let said = html.matches(simulated).count();
    let sections = html.matches("<section id=\"figures\"").count()
        + html.matches("<section id=\"movies\"").count();
    let distinct: BTreeSet<&&str> = levels.iter().filter(|s| s.starts_with(simulated)).collect();
    assert!(
        said == levels.iter().filter(|s| s.starts_with(simulated)).count()
            && said <= sections * distinct.len(),
        "the simulation sentence is said {said} times ({} kinds, {sections} sections)",
        distinct.len()
    );
    for card in cards(&html) {
        assert!(
            !card.contains(simulated),
            "a card repeats the level: {card}"
        );
        assert!(
            card.contains("<span class=\"key\">Model:</span> <a href=\"#"),
            "a card without its level: {card}"
        );
    }
    // A movie's title is drawn in its picture and listed in the contents,
    // not repeated in its caption.
    let movie4 = html.split("id=\"movie-4\"").nth(1).unwrap();
    let caption = movie4
        .split("<figcaption>")
        .nth(1)
        .and_then(|c| c.split("</figcaption>").next())
        .unwrap();
    assert!(!caption.contains("kink, α = 60°"), "{caption}");
    assert!(html.contains("Not made here: figures 1a, 1b, 2a, S1 and S2"));
}

#[test]
fn figures_asked_without_png_still_show_a_png_preview() {
    // `ladder all` in every format but PNG (the shared render, with
    // `--format svg,pdf,gif,mp4`): every figure card shows a PNG
    // preview, the PDF is linked, and no full PNG is written.
    let dir = &crate::common::catalogue_render().0;
    assert!(!crate::common::CATALOGUE_FORMATS.contains("png"));
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let written = check_links(dir, &html);
    assert!(!written.contains("figure-3.png"), "a PNG nobody asked for");
    let cards = cards(&html);
    assert!(cards.len() >= 22, "{} cards", cards.len());
    for card in cards {
        let pictures = card.matches("<img ").count() + card.matches("<video ").count();
        assert!(pictures >= 1, "a card without a picture: {card}");
        for src in attributes(card, "src") {
            if src.ends_with(".png") {
                assert!(src.ends_with("-preview.png"), "{src}");
                let bytes = std::fs::read(dir.join(&src)).unwrap();
                assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{src} is no PNG");
            }
        }
    }
    let figure3 = html.split("id=\"figure-3\"").nth(1).unwrap();
    let figure3 = figure3.split("</figure>").next().unwrap();
    assert!(
        figure3.contains("<img src=\"figure-3-preview.png\""),
        "{figure3}"
    );
    assert!(figure3.contains("href=\"figure-3.pdf\">PDF<"), "{figure3}");
    // A movie's kymograph is a figure too: PDF, and its PNG preview.
    assert!(written.contains("movie-4-kymograph.pdf"), "{written:?}");
    assert!(html.contains("<img src=\"movie-4-kymograph-preview.png\""));
}

/// The browser: `LADDER_CHROMIUM`, else the first of chromium,
/// chromium-browser, google-chrome on the PATH.
fn browser() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("LADDER_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .flat_map(|name| std::env::split_paths(&path).map(move |d| d.join(name)))
        .find(|p| p.is_file())
}

/// Runs headless chromium on `page` with `extra` flags; returns stdout.
/// Killed after two minutes: a hung browser fails the test, never hangs it.
fn chromium(browser: &Path, profile: &Path, extra: &[String], page: &Path) -> String {
    let _ = std::fs::remove_dir_all(profile);
    let mut child = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(format!("file://{}", page.display()))
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("chromium starts");
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut stdout, &mut s).ok();
        s
    });
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        if start.elapsed() > Duration::from_secs(120) {
            child.kill().ok();
            child.wait().ok();
            panic!("chromium did not finish within two minutes");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    reader.join().unwrap()
}

/// A page script that waits for every image and video of the page to load
/// or fail (lazy images made eager), then writes the outcome, the page's
/// height and its largest hole into the DOM as JSON in `<pre
/// id="check">`. A hole is the space between two cards one above the
/// other in a column of a grid, beyond the grid's gap.
const CHECK_SCRIPT: &str = r#"<script>
window.addEventListener('load', () => {
  const media = [...document.querySelectorAll('img, video')];
  const report = { height: 0, hole: 0, media: [] };
  let pending = media.length;
  const finish = () => {
    report.height = document.documentElement.scrollHeight;
    for (const grid of document.querySelectorAll('.grid')) {
      const gap = parseFloat(getComputedStyle(grid).rowGap) || 0;
      const gapX = parseFloat(getComputedStyle(grid).columnGap) || 0;
      const boxes = [...grid.children].map(c => c.getBoundingClientRect());
      for (const x of new Set(boxes.map(b => b.left + 1))) {
        const column = boxes.filter(b => b.left <= x && b.right > x)
          .sort((a, b) => a.top - b.top);
        for (let i = 1; i < column.length; i++) {
          const space = column[i].top - column[i - 1].bottom - Math.max(gap, gapX);
          report.hole = Math.max(report.hole, space);
        }
      }
    }
    const pre = document.createElement('pre');
    pre.id = 'check';
    pre.textContent = JSON.stringify(report);
    document.body.appendChild(pre);
  };
  const done = (el, ok) => {
    report.media.push({ src: el.getAttribute('src'), ok });
    if (--pending === 0) finish();
  };
  if (pending === 0) finish();
  for (const el of media) {
    if (el.tagName === 'IMG') {
      el.loading = 'eager';
      if (el.complete) { done(el, el.naturalWidth > 0); continue; }
      el.addEventListener('load', () => done(el, el.naturalWidth > 0), { once: true });
      el.addEventListener('error', () => done(el, false), { once: true });
    } else {
      if (el.readyState >= 1) { done(el, true); continue; }
      el.addEventListener('loadedmetadata', () => done(el, el.videoWidth > 0), { once: true });
      el.addEventListener('error', () => done(el, false), { once: true });
      el.load();
    }
  }
});
</script>"#;

/// What the check script found in a window `width` pixels wide.
struct Checked {
    /// (src, loaded) per image and video.
    media: Vec<(String, bool)>,
    /// The page's height, pixels.
    height: u32,
    /// The largest hole of a grid, pixels.
    hole: f64,
}

fn check_in_browser(
    browser: &Path,
    dir: &Path,
    page_html: &str,
    name: &str,
    width: u32,
) -> Checked {
    let page = dir.join(name);
    std::fs::write(
        &page,
        page_html.replace("</body>", &format!("{CHECK_SCRIPT}</body>")),
    )
    .unwrap();
    let dom = chromium(
        browser,
        &dir.join("profile-check"),
        &[
            "--virtual-time-budget=20000".into(),
            format!("--window-size={width},1000"),
            "--dump-dom".into(),
        ],
        &page,
    );
    let json = dom
        .split("<pre id=\"check\">")
        .nth(1)
        .and_then(|s| s.split("</pre>").next())
        .unwrap_or_else(|| panic!("the page's check did not finish; DOM tail: {}", tail(&dom)))
        .replace("&quot;", "\"")
        .replace("&amp;", "&");
    let v: serde_json::Value = serde_json::from_str(&json).expect("the check writes JSON");
    let media = v["media"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            (
                m["src"].as_str().unwrap_or("").to_string(),
                m["ok"].as_bool().unwrap(),
            )
        })
        .collect();
    Checked {
        media,
        height: v["height"].as_u64().unwrap_or(0) as u32,
        hole: v["hole"].as_f64().unwrap_or(f64::INFINITY),
    }
}

fn tail(s: &str) -> &str {
    let start = s.len().saturating_sub(400);
    let start = (start..s.len())
        .find(|&i| s.is_char_boundary(i))
        .unwrap_or(0);
    &s[start..]
}

#[test]
fn every_image_and_video_loads_in_a_real_browser() {
    let browser = browser();
    if !common::require::require(
        "every_image_and_video_loads_in_a_real_browser",
        browser.is_some(),
        "no chromium found",
        "set LADDER_CHROMIUM or install Debian's chromium; .ci/run installs it",
    ) {
        return;
    }
    let browser = browser.expect("checked above");
    // The shared render in every format but PNG, so that the page shows
    // MP4 videos (with the GIF as poster) and the figures' PNG previews,
    // and links SVG and PDF files; copied, as the check adds pages.
    let dir = copy_of_render("browser");
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let videos = html.matches("<video ").count();
    let movies = jacobs_ladder::catalog::entries(jacobs_ladder::scene::Kind::Movie)
        .unwrap()
        .len();
    assert_eq!(videos, if cfg!(feature = "mp4") { movies } else { 0 });
    let expected = html.matches("<img ").count() + videos;
    assert!(expected >= 22, "one picture per scene at least");
    for f in ["figure-3.svg", "figure-3.pdf"] {
        assert!(html.contains(&format!("href=\"{f}\"")), "{f} not linked");
    }

    let Checked {
        media,
        height,
        hole,
    } = check_in_browser(&browser, &dir, &html, "check.html", 1400);
    assert_eq!(media.len(), expected, "every picture reported: {media:?}");
    let broken: Vec<&String> = media.iter().filter(|(_, ok)| !ok).map(|(s, _)| s).collect();
    assert!(broken.is_empty(), "broken in the browser: {broken:?}");

    // The check can fail: a page with a missing and a corrupt picture.
    std::fs::write(dir.join("corrupt.png"), b"not a png").unwrap();
    let bad = html.replacen("<img src=\"", "<img src=\"missing.png\" data-x=\"", 1);
    let bad = bad.replacen(
        "<img src=\"figure-2b-preview.png\"",
        "<img src=\"corrupt.png\"",
        1,
    );
    let bad = bad.replacen(
        "<video src=\"movie-3.mp4\"",
        "<video src=\"missing.mp4\"",
        1,
    );
    let media = check_in_browser(&browser, &dir, &bad, "check-bad.html", 1400).media;
    let failed: BTreeSet<&str> = media
        .iter()
        .filter(|(_, ok)| !ok)
        .map(|(s, _)| s.as_str())
        .collect();
    let mut broken = BTreeSet::from(["missing.png", "corrupt.png"]);
    if videos > 0 {
        broken.insert("missing.mp4");
    }
    assert_eq!(failed, broken, "{media:?}");

    // Screenshots to look at: the whole page on a wide screen, the top of
    // it on a phone-sized one.
    let shots = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gallery");
    std::fs::create_dir_all(&shots).unwrap();
    let index = dir.join("index.html");
    let phone = check_in_browser(&browser, &dir, &html, "check-phone.html", 420);
    eprintln!(
        "gallery: {height} px tall at 1400 px wide (largest hole {hole:.0} px), {} px at 420 px \
         (largest hole {:.0} px)",
        phone.height, phone.hole
    );
    for (file, width, h) in [
        ("index-1400.png", 1400, height.clamp(600, 16_000)),
        ("index-420.png", 420, 2400),
    ] {
        let shot = shots.join(file);
        let _ = std::fs::remove_file(&shot);
        chromium(
            &browser,
            &dir.join("profile-shot"),
            &[
                format!("--window-size={width},{h}"),
                "--virtual-time-budget=20000".into(),
                format!("--screenshot={}", shot.display()),
            ],
            &index,
        );
        let meta = std::fs::metadata(&shot).expect("chromium saved the screenshot");
        assert!(meta.len() > 10_000, "{} is nearly empty", shot.display());
        eprintln!("screenshot: {}", shot.display());
    }
    // A wide screen shows three cards a row, packed: the page was 9,100 px
    // tall at 1400 px with holes of 700 px under short cards; packed, it
    // was 6,9xx px, and 7,126 px with the two experiment movies added
    // (one more row of movie cards), 7,922 px with the three experiment
    // figures (one more row of figure cards; looked at: no holes), 8,403
    // px with figure 4b and movie 12 of the ring chain (looked at: the
    // ring chain's cards end their columns, no holes), 9,515 px with the
    // toy as built (figure toy's wide card, movie toy and the ribbon
    // tank's movie: one more row of each kind; looked at: the toy's
    // filmstrip card first, two columns wide, with 2b beside it; no
    // holes).
    assert!(height < 10_300, "page height {height} px at 1400 px wide");
    // A hole: more than about five lines of caption text left empty (the
    // packing leaves at most a few lines where a wide card needs two
    // columns; the grid before left up to 700 px).
    assert!(
        hole < 100.0,
        "a hole of {hole:.0} px in the grid at 1400 px"
    );
    assert!(
        phone.hole < 100.0,
        "a hole of {:.0} px at 420 px",
        phone.hole
    );
    let _ = std::fs::remove_dir_all(&dir);
}
