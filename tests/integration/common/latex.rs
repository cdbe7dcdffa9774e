//! Text for the articles the print tests compile with pdflatex.

/// `text` as plain LaTeX of about the same length: each character outside
/// ASCII one letter, LaTeX's special characters escaped.
pub fn latex_text(text: &str) -> String {
    text.trim()
        .chars()
        .map(|c| match c {
            '%' | '&' | '#' | '_' | '$' | '{' | '}' => format!("\\{c}"),
            '\\' | '^' | '~' => "x".into(),
            c if c.is_ascii() => c.to_string(),
            _ => "x".into(),
        })
        .collect()
}
