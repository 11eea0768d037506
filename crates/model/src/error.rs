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
        write!(f, "{}", self.file)?;
        if let Some((line, column)) = self.position {
            write!(f, ":{line}:{column}")?;
        }
        if self.key.is_empty() {
            write!(f, ": {}", self.reason)
        } else {
            write!(f, ": {} — {}", self.key, self.reason)
        }
    }
}

impl std::error::Error for ModelError {}

/// One step of a key path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Segment {
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
    let mut span = None;
    let mut table = Some(root.get_ref());
    let mut array: Option<&[Spanned<DeValue<'_>>]> = None;
    for segment in split_key(key) {
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
