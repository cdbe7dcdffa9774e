//! SVG from a parsed SVG tree (`usvg::Tree`): a self-contained file whose
//! text is converted to glyph outlines, so it looks the same wherever it is
//! opened, whether or not the viewer has the font.

use resvg::usvg;

/// The bytes of a standalone SVG of `tree`, text as outlines.
pub fn svg_bytes(tree: &usvg::Tree) -> Vec<u8> {
    let opt = usvg::WriteOptions {
        coordinates_precision: 3,
        transforms_precision: 6,
        ..usvg::WriteOptions::default()
    };
    tree.to_string(&opt).into_bytes()
}
