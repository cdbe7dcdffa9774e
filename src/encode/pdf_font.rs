//! The fonts of a PDF's real text: every face the page draws glyphs from,
//! subset to those glyphs (`subsetter`, TrueType outlines kept as they are)
//! and embedded as a Type 0 font with Identity-H encoding (two-byte codes =
//! the subset's glyph ids), its widths, and a ToUnicode map from the
//! `usvg` layout's text of each glyph, so that readers (pdftotext, search,
//! copy-paste) get the words back: Greek letters, primes and the text of
//! super- and subscripts included.
//!
//! The face data comes from the tree's own font database (`usvg::Tree::
//! fontdb`): this module knows no font by name.

use crate::error::{Error, Result};
use ab_glyph::{Font, FontRef, GlyphId};
use pdf_writer::types::{CidFontType, FontFlags, SystemInfo, UnicodeCmap};
use pdf_writer::{Filter, Finish, Name, Pdf, Rect, Ref, Str};
use resvg::usvg::fontdb;
use std::collections::BTreeMap;
use subsetter::GlyphRemapper;

/// One face used on the page.
struct Face {
    id: fontdb::ID,
    /// PostScript name without spaces (the BaseFont after the subset tag).
    name: String,
    data: Vec<u8>,
    index: u32,
    remapper: GlyphRemapper,
    /// Subset glyph id → (original id, the text it stands for).
    glyphs: BTreeMap<u16, (u16, String)>,
    upem: f32,
}

/// The faces of a page, in the order first used (`/F0`, `/F1`, …).
#[derive(Default)]
pub(super) struct Fonts {
    faces: Vec<Face>,
}

/// A glyph to show: the face's resource name index, its two-byte code,
/// and the face's units per em.
pub(super) struct Shown {
    pub face: usize,
    pub code: [u8; 2],
    pub upem: f32,
}

impl Fonts {
    /// Registers glyph `gid` of face `id` standing for `text`.
    pub fn glyph(
        &mut self,
        db: &fontdb::Database,
        id: fontdb::ID,
        gid: u16,
        text: &str,
    ) -> Result<Shown> {
        let k = match self.faces.iter().position(|f| f.id == id) {
            Some(k) => k,
            None => {
                self.faces.push(Face::load(db, id)?);
                self.faces.len() - 1
            }
        };
        let face = &mut self.faces[k];
        let new = face.remapper.remap(gid);
        face.glyphs
            .entry(new)
            .or_insert_with(|| (gid, text.to_string()));
        Ok(Shown {
            face: k,
            code: new.to_be_bytes(),
            upem: face.upem,
        })
    }

    /// The resource name of face `k`.
    pub fn resource_name(k: usize) -> String {
        format!("F{k}")
    }

    /// Writes every face's objects with ids from `*next` on; returns the
    /// Type 0 font's id of each face, in order.
    pub fn write(&self, pdf: &mut Pdf, next: &mut i32) -> Result<Vec<Ref>> {
        let mut alloc = || {
            *next += 1;
            Ref::new(*next - 1)
        };
        let mut out = Vec::new();
        for face in &self.faces {
            let ids = FaceRefs {
                type0: alloc(),
                cid: alloc(),
                descriptor: alloc(),
                file: alloc(),
                cmap: alloc(),
            };
            face.write(pdf, &ids)?;
            out.push(ids.type0);
        }
        Ok(out)
    }
}

/// The five objects of one embedded face.
struct FaceRefs {
    type0: Ref,
    cid: Ref,
    descriptor: Ref,
    file: Ref,
    cmap: Ref,
}

/// The character collection of every face: Adobe-Identity-0.
fn system_info() -> SystemInfo<'static> {
    SystemInfo {
        registry: Str(b"Adobe"),
        ordering: Str(b"Identity"),
        supplement: 0,
    }
}

impl Face {
    /// Writes this face's objects: the Type 0 font, its CID font, the font
    /// descriptor, the subset font file and the ToUnicode map.
    fn write(&self, pdf: &mut Pdf, ids: &FaceRefs) -> Result<()> {
        let subset = subsetter::subset(&self.data, self.index, &self.remapper).map_err(|e| {
            Error::failed(format!("the font {} could not be subset: {e:?}", self.name))
        })?;
        let font = FontRef::try_from_slice_and_index(&self.data, self.index)
            .map_err(|_| Error::failed(format!("the font {} cannot be read", self.name)))?;
        let base = format!("{}+{}", self.tag(), self.name);
        let base = Name(base.as_bytes());
        pdf.type0_font(ids.type0)
            .base_font(base)
            .encoding_predefined(Name(b"Identity-H"))
            .descendant_font(ids.cid)
            .to_unicode(ids.cmap);
        self.write_cid_font(pdf, &font, ids, base);
        self.write_descriptor(pdf, &font, ids, base);
        let packed = miniz_oxide::deflate::compress_to_vec_zlib(&subset, 6);
        pdf.stream(ids.file, &packed)
            .filter(Filter::FlateDecode)
            .pair(Name(b"Length1"), subset.len() as i32);
        self.write_cmap(pdf, ids.cmap);
        Ok(())
    }

    /// A length in font units as thousandths of the em.
    fn per_mille(&self, v: f32) -> f32 {
        v / self.upem * 1000.0
    }

    /// The CID font with every subset glyph's advance width.
    fn write_cid_font(&self, pdf: &mut Pdf, font: &FontRef, ids: &FaceRefs, base: Name) {
        let count = self.remapper.num_gids();
        let widths: Vec<f32> = (0..count)
            .map(|new| {
                let old = self.glyphs.get(&new).map_or(0, |g| g.0);
                self.per_mille(font.h_advance_unscaled(GlyphId(old)))
            })
            .collect();
        let mut c = pdf.cid_font(ids.cid);
        c.subtype(CidFontType::Type2)
            .base_font(base)
            .system_info(system_info())
            .font_descriptor(ids.descriptor)
            .cid_to_gid_map_predefined(Name(b"Identity"));
        c.widths().consecutive(0, widths);
        c.finish();
    }

    /// The font descriptor: the bounding box of the glyphs used, ascent,
    /// descent, cap height and flags.
    fn write_descriptor(&self, pdf: &mut Pdf, font: &FontRef, ids: &FaceRefs, base: Name) {
        let mut bbox = Rect::new(
            0.0,
            self.per_mille(font.descent_unscaled()),
            1000.0,
            self.per_mille(font.ascent_unscaled()),
        );
        for (old, _) in self.glyphs.values() {
            if let Some(o) = font.outline(GlyphId(*old)) {
                bbox.x1 = bbox.x1.min(self.per_mille(o.bounds.min.x));
                bbox.y1 = bbox.y1.min(self.per_mille(o.bounds.min.y));
                bbox.x2 = bbox.x2.max(self.per_mille(o.bounds.max.x));
                bbox.y2 = bbox.y2.max(self.per_mille(o.bounds.max.y));
            }
        }
        let mut flags = FontFlags::NON_SYMBOLIC;
        if self.name.contains("Serif") {
            flags |= FontFlags::SERIF;
        }
        let cap = font
            .outline(font.glyph_id('H'))
            .map_or(700.0, |o| self.per_mille(o.bounds.max.y));
        pdf.font_descriptor(ids.descriptor)
            .name(base)
            .flags(flags)
            .bbox(bbox)
            .italic_angle(0.0)
            .ascent(self.per_mille(font.ascent_unscaled()))
            .descent(self.per_mille(font.descent_unscaled()))
            .cap_height(cap)
            .stem_v(80.0)
            .font_file2(ids.file);
    }

    /// The ToUnicode map: each subset glyph's text.
    fn write_cmap(&self, pdf: &mut Pdf, cmap: Ref) {
        let mut map = UnicodeCmap::new(Name(b"Custom"), system_info());
        for (new, (_, text)) in &self.glyphs {
            if !text.is_empty() {
                map.pair_with_multiple(*new, text.chars());
            }
        }
        pdf.cmap(cmap, &map.finish())
            .system_info(system_info())
            .name(Name(b"Custom"));
    }
}

impl Face {
    fn load(db: &fontdb::Database, id: fontdb::ID) -> Result<Face> {
        let info = db
            .face(id)
            .ok_or_else(|| Error::failed("a glyph names a font that is not loaded"))?;
        let name: String = info
            .post_script_name
            .chars()
            .filter(|c| c.is_ascii_alphanumeric() || *c == '-')
            .collect();
        let (data, index) = db
            .with_face_data(id, |data, index| (data.to_vec(), index))
            .ok_or_else(|| Error::failed(format!("the font {name} has no data")))?;
        let font = FontRef::try_from_slice_and_index(&data, index)
            .map_err(|_| Error::failed(format!("the font {name} cannot be read")))?;
        let upem = font.units_per_em().unwrap_or(1000.0);
        Ok(Face {
            id,
            name,
            data,
            index,
            remapper: GlyphRemapper::new(),
            glyphs: BTreeMap::new(),
            upem,
        })
    }

    /// Six capital letters naming the subset (PDF 32000-1, 9.6.4), from the
    /// glyphs it holds: the same glyphs give the same tag, so the bytes of
    /// a figure do not depend on anything else.
    fn tag(&self) -> String {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for (new, (old, _)) in &self.glyphs {
            for b in new.to_be_bytes().into_iter().chain(old.to_be_bytes()) {
                h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
            }
        }
        (0..6)
            .map(|i| (b'A' + ((h >> (i * 8)) % 26) as u8) as char)
            .collect()
    }
}
