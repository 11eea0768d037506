//! The frame of the state files rolldyn writes and reads back whole (dynamics checkpoints,
//! the stored state of resumable runs): a six-byte tag and a two-digit format version first,
//! the body, and the [`fnv1a`] checksum of everything before it last, so that a file of
//! another kind, of another format version, or damaged (a changed or cut byte) is recognised.

use crate::hash::fnv1a;

/// Bytes of the checksum that closes a sealed file.
const CHECKSUM_BYTES: usize = 8;

/// The kind of a sealed file: its tag and format version.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Kind {
    pub tag: &'static [u8; 6],
    pub version: &'static [u8; 2],
}

/// Why a file could not be opened as a sealed file of a kind.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Unsealed {
    /// It does not start with the kind's tag.
    Foreign,
    /// It is of the kind but of another format version (this one).
    Version(String),
    /// Its checksum does not match.
    Damaged,
}

impl std::fmt::Display for Unsealed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unsealed::Foreign => write!(f, "not a file of this kind"),
            Unsealed::Version(v) => write!(f, "format version {v}"),
            Unsealed::Damaged => write!(
                f,
                "damaged: its checksum does not match (a byte was changed or the file cut short)"
            ),
        }
    }
}

impl Kind {
    /// The opening bytes of a file of this kind: the tag and the version; the body follows.
    pub fn header(&self) -> Vec<u8> {
        [self.tag.as_slice(), self.version].concat()
    }

    /// A buffer that starts with [`Kind::header`], closed by its checksum.
    pub fn seal(&self, mut buf: Vec<u8>) -> Vec<u8> {
        debug_assert!(buf.starts_with(&self.header()));
        let sum = fnv1a(&buf);
        buf.extend_from_slice(&sum.to_le_bytes());
        buf
    }

    /// The bytes of a file written by [`Kind::seal`] without the checksum (the header
    /// included: the body starts at `header().len()`).
    pub fn open<'a>(&self, bytes: &'a [u8]) -> Result<&'a [u8], Unsealed> {
        let header = self.tag.len() + self.version.len();
        if bytes.len() < header || &bytes[..self.tag.len()] != self.tag {
            return Err(Unsealed::Foreign);
        }
        let version = &bytes[self.tag.len()..header];
        if version != self.version {
            return Err(Unsealed::Version(
                String::from_utf8_lossy(version).into_owned(),
            ));
        }
        let body_len = bytes
            .len()
            .checked_sub(CHECKSUM_BYTES)
            .filter(|&n| n >= header)
            .ok_or(Unsealed::Damaged)?;
        let (body, sum) = bytes.split_at(body_len);
        match sum == fnv1a(body).to_le_bytes() {
            true => Ok(body),
            false => Err(Unsealed::Damaged),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const KIND: Kind = Kind {
        tag: b"RDYNTS",
        version: b"01",
    };

    #[test]
    fn a_sealed_file_opens_and_a_changed_byte_or_other_kind_is_refused() {
        let mut buf = KIND.header();
        buf.extend_from_slice(b"body");
        let sealed = KIND.seal(buf);
        assert_eq!(KIND.open(&sealed).unwrap(), b"RDYNTS01body");
        let mut changed = sealed.clone();
        changed[9] ^= 1;
        assert_eq!(KIND.open(&changed), Err(Unsealed::Damaged));
        assert_eq!(
            KIND.open(&sealed[..sealed.len() - 1]),
            Err(Unsealed::Damaged)
        );
        let other = Kind {
            version: b"02",
            ..KIND
        };
        assert_eq!(other.open(&sealed), Err(Unsealed::Version("01".into())));
        assert_eq!(KIND.open(b"PK\x03\x04"), Err(Unsealed::Foreign));
    }
}
