//! Model-file errors that point at the file, line, key and reason.

use std::fmt;
use std::ops::Range;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// A model file could not be used. Displayed as `file:line:column: key — reason`.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelError {
    pub file: String,
    /// 1-based line and column of the offending key or value, when known.
    pub position: Option<(usize, usize)>,
    /// Dotted key path, e.g. `roller.profile.drop` (empty for whole-file errors).
    pub key: String,
    pub reason: String,
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut line = self.file.clone();
        if let Some((row, column)) = self.position {
            line.push_str(&format!(":{row}:{column}"));
        }
        if self.key.is_empty() {
            line.push_str(&format!(": {}", self.reason));
        } else {
            line.push_str(&format!(": {} — {}", self.key, self.reason));
        }
        f.write_str(&shorten_long_words(&line))
    }
}

/// Longest word (run without whitespace) an error message quotes in full.
pub const MAX_QUOTED_CHARS: usize = 80;

/// `text` with every word longer than [`MAX_QUOTED_CHARS`] cut to its start and its length,
/// so that an error quoting a huge bad value stays one readable line.
pub fn shorten_long_words(text: &str) -> String {
    let mut out = String::with_capacity(text.len().min(4 * MAX_QUOTED_CHARS));
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let word = &rest[..end];
        let chars = word.chars().count();
        if chars > MAX_QUOTED_CHARS {
            let head: String = word.chars().take(MAX_QUOTED_CHARS / 2).collect();
            out.push_str(&format!("{head}… ({chars} characters)"));
        } else {
            out.push_str(word);
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

impl std::error::Error for ModelError {}

/// A TOML input file parsed with its spans, to name the line and column of a key in errors:
/// the locator of the model, sweep, journal and oil files.
pub struct LocatedToml<'a> {
    text: &'a str,
    file: &'a str,
    pub(crate) tree: Spanned<DeTable<'a>>,
}

impl<'a> LocatedToml<'a> {
    /// Parses `text` (named `file` in errors); a syntax error names its line and column.
    pub fn parse(text: &'a str, file: &'a str) -> Result<Self, ModelError> {
        let tree = DeTable::parse(text).map_err(|e| ModelError {
            file: file.to_string(),
            position: e.span().map(|s| line_column(text, s.start)),
            key: String::new(),
            reason: format!("TOML syntax error: {}", e.message().trim()),
        })?;
        Ok(Self { text, file, tree })
    }

    /// The error `reason` at dotted `key` (at its line when the key is in the file).
    pub fn error(&self, key: &str, reason: impl Into<String>) -> ModelError {
        self.error_at(&split_key(key), key, reason)
    }

    /// The error `reason` at `path`, named `key` (at the line of the deepest item of `path`
    /// in the file).
    pub fn error_at(&self, path: &[Segment], key: &str, reason: impl Into<String>) -> ModelError {
        ModelError {
            file: self.file.to_string(),
            position: span_of_path(&self.tree, path).map(|s| line_column(self.text, s.start)),
            key: key.to_string(),
            reason: reason.into(),
        }
    }
}

/// One step of a key path: a table key (which may itself contain dots, like a sweep file's
/// quoted override keys) or an array index.
#[derive(Debug, Clone, PartialEq)]
pub enum Segment {
    Key(String),
    Index(usize),
}

/// Splits `a.b[0].c` into segments.
pub(crate) fn split_key(key: &str) -> Vec<Segment> {
    let mut segments = Vec::new();
    for part in key.split('.').filter(|p| !p.is_empty()) {
        let mut rest = part;
        if let Some(open) = rest.find('[') {
            segments.push(Segment::Key(rest[..open].to_string()));
            rest = &rest[open..];
            while let Some(close) = rest.find(']') {
                if let Ok(i) = rest[1..close].parse() {
                    segments.push(Segment::Index(i));
                }
                rest = &rest[close + 1..];
            }
        } else {
            segments.push(Segment::Key(rest.to_string()));
        }
    }
    segments
}

/// Byte span of the deepest existing item along `key` in the parsed document.
pub(crate) fn span_of(root: &Spanned<DeTable<'_>>, key: &str) -> Option<Range<usize>> {
    span_of_path(root, &split_key(key))
}

/// Byte span of the deepest existing item along `path` in the parsed document.
fn span_of_path(root: &Spanned<DeTable<'_>>, path: &[Segment]) -> Option<Range<usize>> {
    let mut span = None;
    let mut table = Some(root.get_ref());
    let mut array: Option<&[Spanned<DeValue<'_>>]> = None;
    for segment in path.iter().cloned() {
        let value = match (segment, table, array) {
            (Segment::Key(k), Some(t), _) => {
                match t.iter().find(|(name, _)| name.get_ref() == &k) {
                    Some((name, value)) => {
                        span = Some(name.span());
                        value
                    }
                    None => break,
                }
            }
            (Segment::Index(i), _, Some(items)) => match items.get(i) {
                Some(value) => {
                    span = Some(value.span());
                    value
                }
                None => break,
            },
            _ => break,
        };
        table = value.get_ref().as_table();
        array = value.get_ref().as_array().map(|a| &a[..]);
    }
    span
}

/// 1-based (line, column) of byte `offset` in `text`.
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_words_are_cut() {
        let long = "9".repeat(1000);
        let short = shorten_long_words(&format!("a '{long} mm' b"));
        assert!(short.len() < 2 * MAX_QUOTED_CHARS, "{short}");
        assert!(short.starts_with("a '999") && short.ends_with("(1001 characters) mm' b"));
        assert_eq!(
            shorten_long_words(" keep  these words "),
            " keep  these words "
        );
    }

    #[test]
    fn keys_split_with_indices() {
        assert_eq!(
            split_key("inner_ring.ribs[1].diameter"),
            vec![
                Segment::Key("inner_ring".into()),
                Segment::Key("ribs".into()),
                Segment::Index(1),
                Segment::Key("diameter".into())
            ]
        );
    }

    #[test]
    fn spans_find_nested_keys() {
        let text = "[a]\nb = 1\n[[a.c]]\nd = 2\n[[a.c]]\nd = 3\n";
        let root = DeTable::parse(text).unwrap();
        let span = span_of(&root, "a.c[1].d").unwrap();
        assert_eq!(line_column(text, span.start), (6, 1));
        let span = span_of(&root, "a.b").unwrap();
        assert_eq!(line_column(text, span.start), (2, 1));
    }
}
