//! PDF from a parsed SVG tree (`usvg::Tree`): one page the size of the
//! picture times the points per pixel asked for (0.75 at the screen style,
//! i.e. 96 px per inch; a print style's page width over the design width),
//! vector paths, and text as real text in the fonts the tree's layout
//! chose, each subset and embedded (`pdf_font`), or as glyph outlines
//! (`--text outlines`), content compressed with Deflate. PDF 1.5 (the
//! highest version pdflatex includes without a warning), an Info dictionary
//! with the figure's title and the program, version and commit that made
//! it ([`crate::version`]), no dates or IDs, so the bytes depend only on the
//! picture. pdflatex includes it with `\includegraphics`.
//!
//! Written with `pdf-writer` on the tree that the renderer already parses
//! with resvg's own `usvg`: svg2pdf 0.13 and krilla-svg 0.8 would each have
//! compiled a second, older usvg/resvg/fontdb stack (docs/formats.md).
//!
//! Supported: groups with transforms, opacity and path clips; paths with
//! solid fills and strokes (caps, joins, dashes, opacity). Gradients,
//! patterns, masks, filters and raster images are refused: the renderer
//! emits none of them.

use super::pdf_font::Fonts;
use crate::error::{Error, Result};
use pdf_writer::{Content, Finish, Name, Pdf, Rect, Ref, Str};
use resvg::usvg::{self, Node, Paint, tiny_skia_path::PathSegment};

/// How a PDF page is made from a tree.
#[derive(Clone, Debug, PartialEq)]
pub struct PdfOptions {
    /// Points per pixel of the tree. Default: 0.75 (96 px per inch).
    pub pt_per_px: f32,
    /// Text as text with embedded fonts (`true`) or as outlines. Default:
    /// text.
    pub real_text: bool,
    /// The document's title (the Info dictionary's `/Title`). Default:
    /// none.
    pub title: Option<String>,
}

/// What made a figure file: `ladder 0.1.0 (commit 1a2b3c4d5e6f)`, the
/// creator every figure format records (PDF `/Creator`, SVG `<metadata>`,
/// PNG `Software`).
pub fn creator() -> String {
    format!("ladder {}", crate::version::LONG)
}

/// The PDF version written: 1.5, the highest pdflatex's default
/// `\pdfminorversion` accepts without a warning ("found PDF version <1.7>,
/// but at most version <1.5> allowed"). Nothing we write needs more.
pub const PDF_VERSION: (u8, u8) = (1, 5);

impl Default for PdfOptions {
    fn default() -> Self {
        Self {
            pt_per_px: 0.75,
            real_text: true,
            title: None,
        }
    }
}

/// The bytes of a one-page PDF of `tree`.
pub fn pdf_bytes(tree: &usvg::Tree, opts: PdfOptions) -> Result<Vec<u8>> {
    let size = tree.size();
    let k = opts.pt_per_px;
    let (w, h) = (size.width() * k, size.height() * k);
    let mut page = PageWriter {
        real_text: opts.real_text,
        fontdb: Some(tree.fontdb().clone()),
        ..PageWriter::default()
    };
    page.content.transform([k, 0.0, 0.0, -k, 0.0, h]);
    page.group_children(tree.root())?;
    let content = page.content.finish();
    let compressed = miniz_oxide::deflate::compress_to_vec_zlib(content.as_slice(), 6);

    let (catalog, pages, page_id, content_id) =
        (Ref::new(1), Ref::new(2), Ref::new(3), Ref::new(4));
    let mut next = 5;
    let mut pdf = Pdf::new();
    pdf.set_version(PDF_VERSION.0, PDF_VERSION.1);
    let info_id = Ref::new(next);
    next += 1;
    {
        let mut info = pdf.document_info(info_id);
        if let Some(t) = opts.title.as_deref().filter(|t| !t.is_empty()) {
            info.title(pdf_writer::TextStr(t));
        }
        let made_by = creator();
        info.creator(pdf_writer::TextStr(&made_by));
        info.producer(pdf_writer::TextStr(&made_by));
    }
    let font_ids = page.fonts.write(&mut pdf, &mut next)?;
    pdf.catalog(catalog).pages(pages);
    pdf.pages(pages).kids([page_id]).count(1);
    let states: Vec<(Ref, (u8, u8))> = page
        .alphas
        .iter()
        .map(|&a| {
            next += 1;
            (Ref::new(next - 1), a)
        })
        .collect();
    {
        let mut p = pdf.page(page_id);
        p.parent(pages)
            .media_box(Rect::new(0.0, 0.0, w, h))
            .contents(content_id);
        let mut res = p.resources();
        let mut gs = res.ext_g_states();
        for (k, (id, _)) in states.iter().enumerate() {
            gs.pair(Name(alpha_name(k).as_bytes()), *id);
        }
        gs.finish();
        if !font_ids.is_empty() {
            let mut fonts = res.fonts();
            for (k, id) in font_ids.iter().enumerate() {
                fonts.pair(Name(Fonts::resource_name(k).as_bytes()), *id);
            }
        }
        res.finish();
        p.finish();
    }
    pdf.stream(content_id, &compressed)
        .filter(pdf_writer::Filter::FlateDecode);
    for (id, (fill, stroke)) in states {
        pdf.ext_graphics(id)
            .non_stroking_alpha(fill as f32 / 255.0)
            .stroking_alpha(stroke as f32 / 255.0);
    }
    Ok(pdf.finish())
}

fn alpha_name(k: usize) -> String {
    format!("A{k}")
}

/// The page's content stream and the opacity states and fonts it uses.
struct PageWriter {
    content: Content,
    /// (fill, stroke) opacities in 1/255, one graphics state each.
    alphas: Vec<(u8, u8)>,
    /// Text as text (else as outlines).
    real_text: bool,
    fontdb: Option<std::sync::Arc<usvg::fontdb::Database>>,
    fonts: Fonts,
}

impl Default for PageWriter {
    fn default() -> Self {
        Self {
            content: Content::new(),
            alphas: Vec::new(),
            real_text: false,
            fontdb: None,
            fonts: Fonts::default(),
        }
    }
}

impl PageWriter {
    fn group_children(&mut self, g: &usvg::Group) -> Result<()> {
        for node in g.children() {
            match node {
                Node::Group(child) => self.group(child)?,
                Node::Path(path) => self.path(path)?,
                Node::Text(text) if self.real_text => self.text(text)?,
                Node::Text(text) => self.group(text.flattened())?,
                Node::Image(_) => {
                    return Err(Error::failed(
                        "a raster image cannot go into a vector PDF figure",
                    ));
                }
            }
        }
        Ok(())
    }

    fn group(&mut self, g: &usvg::Group) -> Result<()> {
        if g.mask().is_some() || !g.filters().is_empty() {
            return Err(Error::failed(
                "masks and filters cannot go into a vector PDF figure",
            ));
        }
        self.content.save_state();
        let t = g.transform();
        if !t.is_identity() {
            self.content.transform([t.sx, t.ky, t.kx, t.sy, t.tx, t.ty]);
        }
        let opacity = g.opacity().get();
        if opacity < 1.0 {
            let a = (opacity * 255.0).round() as u8;
            self.set_alpha((a, a));
        }
        if let Some(clip) = g.clip_path() {
            self.clip(clip)?;
        }
        self.group_children(g)?;
        self.content.restore_state();
        Ok(())
    }

    /// Intersects the clip with the union of the clip path's paths.
    fn clip(&mut self, clip: &usvg::ClipPath) -> Result<()> {
        if clip.clip_path().is_some() {
            return Err(Error::failed("nested clip paths are not supported in PDF"));
        }
        let t = clip.transform();
        if !t.is_identity() {
            self.content.transform([t.sx, t.ky, t.kx, t.sy, t.tx, t.ty]);
        }
        let mut any = false;
        for node in clip.root().children() {
            if let Node::Path(p) = node {
                self.segments(p.data());
                any = true;
            }
        }
        if any {
            self.content.clip_nonzero();
        } else {
            // An empty clip hides everything.
            self.content.rect(0.0, 0.0, 0.0, 0.0).clip_nonzero();
        }
        self.content.end_path();
        if let Some(inv) = t.invert().filter(|_| !t.is_identity()) {
            self.content
                .transform([inv.sx, inv.ky, inv.kx, inv.sy, inv.tx, inv.ty]);
        }
        Ok(())
    }

    /// Text as text: each glyph shown at the transform of its outline
    /// (font size 1, the matrix scaled by the units per em), filled with
    /// its span's colour. Stroked text keeps its outlines.
    fn text(&mut self, text: &usvg::Text) -> Result<()> {
        let Some(db) = self.fontdb.clone() else {
            return self.group(text.flattened());
        };
        for span in text.layouted() {
            if !span.visible || span.positioned_glyphs.is_empty() {
                continue;
            }
            let Some(fill) = &span.fill else { continue };
            let c = color(fill.paint())?;
            self.content.save_state();
            let a = fill.opacity().get();
            if a < 1.0 {
                let q = (a * 255.0).round() as u8;
                self.set_alpha((q, q));
            }
            self.content.set_fill_rgb(c[0], c[1], c[2]);
            self.content.begin_text();
            let mut current = None;
            for g in &span.positioned_glyphs {
                let gid = u16::try_from(g.id.0).map_err(|_| {
                    Error::failed("a glyph id above 65535 cannot go into a PDF font")
                })?;
                let shown = self.fonts.glyph(&db, g.font, gid, &g.text)?;
                if current != Some(shown.face) {
                    let name = Fonts::resource_name(shown.face);
                    self.content.set_font(Name(name.as_bytes()), 1.0);
                    current = Some(shown.face);
                }
                let t = g.outline_transform().pre_scale(shown.upem, shown.upem);
                self.content
                    .set_text_matrix([t.sx, t.ky, t.kx, t.sy, t.tx, t.ty]);
                self.content.show(Str(&shown.code));
            }
            self.content.end_text();
            self.content.restore_state();
        }
        Ok(())
    }

    fn set_alpha(&mut self, a: (u8, u8)) {
        let k = match self.alphas.iter().position(|&x| x == a) {
            Some(k) => k,
            None => {
                self.alphas.push(a);
                self.alphas.len() - 1
            }
        };
        self.content.set_parameters(Name(alpha_name(k).as_bytes()));
    }

    fn path(&mut self, p: &usvg::Path) -> Result<()> {
        if !p.is_visible() {
            return Ok(());
        }
        let fill = p
            .fill()
            .map(|f| -> Result<_> { Ok((color(f.paint())?, f.opacity().get(), f.rule())) });
        let stroke = p.stroke();
        let fill = fill.transpose()?;
        if fill.is_none() && stroke.is_none() {
            return Ok(());
        }
        let fill_first = p.paint_order() == usvg::PaintOrder::FillAndStroke;
        self.content.save_state();
        let fa = fill.as_ref().map_or(1.0, |f| f.1);
        let sa = stroke.map_or(1.0, |s| s.opacity().get());
        if fa < 1.0 || sa < 1.0 {
            let q = |a: f32| (a * 255.0).round() as u8;
            self.set_alpha((q(fa), q(sa)));
        }
        if let Some((c, _, _)) = &fill {
            self.content.set_fill_rgb(c[0], c[1], c[2]);
        }
        if let Some(s) = stroke {
            self.stroke_style(s)?;
        }
        match (&fill, stroke) {
            (Some((_, _, rule)), Some(_)) if fill_first => {
                self.segments(p.data());
                match rule {
                    usvg::FillRule::NonZero => self.content.fill_nonzero_and_stroke(),
                    usvg::FillRule::EvenOdd => self.content.fill_even_odd_and_stroke(),
                };
            }
            _ => {
                if let Some((_, _, rule)) = &fill {
                    self.segments(p.data());
                    match rule {
                        usvg::FillRule::NonZero => self.content.fill_nonzero(),
                        usvg::FillRule::EvenOdd => self.content.fill_even_odd(),
                    };
                }
                if stroke.is_some() {
                    self.segments(p.data());
                    self.content.stroke();
                }
            }
        }
        self.content.restore_state();
        Ok(())
    }

    fn stroke_style(&mut self, s: &usvg::Stroke) -> Result<()> {
        use pdf_writer::types::{LineCapStyle, LineJoinStyle};
        let c = color(s.paint())?;
        self.content
            .set_stroke_rgb(c[0], c[1], c[2])
            .set_line_width(s.width().get())
            .set_line_cap(match s.linecap() {
                usvg::LineCap::Butt => LineCapStyle::ButtCap,
                usvg::LineCap::Round => LineCapStyle::RoundCap,
                usvg::LineCap::Square => LineCapStyle::ProjectingSquareCap,
            })
            .set_line_join(match s.linejoin() {
                usvg::LineJoin::Miter | usvg::LineJoin::MiterClip => LineJoinStyle::MiterJoin,
                usvg::LineJoin::Round => LineJoinStyle::RoundJoin,
                usvg::LineJoin::Bevel => LineJoinStyle::BevelJoin,
            })
            .set_miter_limit(s.miterlimit().get());
        if let Some(dash) = s.dasharray() {
            self.content
                .set_dash_pattern(dash.iter().copied(), s.dashoffset());
        }
        Ok(())
    }

    fn segments(&mut self, path: &usvg::tiny_skia_path::Path) {
        let mut last = (0.0f32, 0.0f32);
        let mut start = last;
        for seg in path.segments() {
            match seg {
                PathSegment::MoveTo(p) => {
                    self.content.move_to(p.x, p.y);
                    last = (p.x, p.y);
                    start = last;
                }
                PathSegment::LineTo(p) => {
                    self.content.line_to(p.x, p.y);
                    last = (p.x, p.y);
                }
                PathSegment::QuadTo(c, p) => {
                    // The same curve as a cubic: control points 2/3 of the
                    // way from each end to the quadratic's control point.
                    let c1 = (
                        last.0 + 2.0 / 3.0 * (c.x - last.0),
                        last.1 + 2.0 / 3.0 * (c.y - last.1),
                    );
                    let c2 = (p.x + 2.0 / 3.0 * (c.x - p.x), p.y + 2.0 / 3.0 * (c.y - p.y));
                    self.content.cubic_to(c1.0, c1.1, c2.0, c2.1, p.x, p.y);
                    last = (p.x, p.y);
                }
                PathSegment::CubicTo(c1, c2, p) => {
                    self.content.cubic_to(c1.x, c1.y, c2.x, c2.y, p.x, p.y);
                    last = (p.x, p.y);
                }
                PathSegment::Close => {
                    self.content.close_path();
                    last = start;
                }
            }
        }
    }
}

/// A solid colour as PDF RGB components.
fn color(paint: &Paint) -> Result<[f32; 3]> {
    match paint {
        Paint::Color(c) => Ok([c.red, c.green, c.blue].map(|v| v as f32 / 255.0)),
        _ => Err(Error::failed(
            "gradients and patterns cannot go into a vector PDF figure",
        )),
    }
}
