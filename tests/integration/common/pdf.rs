//! Reading a PDF's content stream back (with lopdf, not the program's own
//! picture model).

/// The bytes a text-showing operator (`Tj`, or `TJ` with its kerning
/// numbers left out) shows: two-byte glyph codes in our PDFs.
pub fn shown_bytes(operand: &lopdf::Object) -> Vec<u8> {
    match operand {
        lopdf::Object::String(b, _) => b.clone(),
        lopdf::Object::Array(parts) => parts
            .iter()
            .filter_map(|p| p.as_str().ok().map(|s| s.to_vec()))
            .flatten()
            .collect(),
        _ => Vec::new(),
    }
}
