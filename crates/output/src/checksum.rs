//! Checksums of the files rolldyn writes and reads back (stored sweep results, stored states),
//! and of the files a run leaves in its folder (`run.json`'s `files`): FNV-1a
//! ([`rolldyn_numerics::hash::fnv1a`]) as 16 hex digits. A checksum finds a changed or cut
//! file; it is no signature (anyone can compute it).
//!
//! A JSON document is sealed by a last member `"checksum"`, the hash of the document's pretty
//! text without that member: the file stays plain JSON, and a reader that does not know the
//! member ignores it.

use rolldyn_numerics::hash::fnv1a;

/// The checksum of `bytes`: FNV-1a, 16 lowercase hex digits.
pub fn checksum_hex(bytes: &[u8]) -> String {
    format!("{:016x}", fnv1a(bytes))
}

/// Why a sealed document is not trusted.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ChecksumError {
    /// The document has no checksum (written by an older rolldyn, or cut short).
    #[error("damaged: no checksum")]
    Missing,
    /// The content does not match its checksum (a byte was changed).
    #[error("damaged: checksum mismatch")]
    Mismatch,
}

/// The member that closes a sealed document, up to its value.
const SEAL: &str = ",\n  \"checksum\": \"";

/// `value` (a JSON object) as pretty JSON closed by its checksum member, with a final newline.
pub fn seal_json<T: serde::Serialize>(value: &T) -> Result<String, serde_json::Error> {
    let body = serde_json::to_string_pretty(value)?;
    let Some(open) = body.strip_suffix("\n}") else {
        return Err(serde::ser::Error::custom(
            "only a non-empty JSON object can be sealed",
        ));
    };
    Ok(format!(
        "{open}{SEAL}{}\"\n}}\n",
        checksum_hex(body.as_bytes())
    ))
}

/// Checks the checksum of a document written by [`seal_json`].
pub fn verify_sealed_json(text: &str) -> Result<(), ChecksumError> {
    let text = text.strip_suffix('\n').unwrap_or(text);
    let at = text.rfind(SEAL).ok_or(ChecksumError::Missing)?;
    let sum = text[at + SEAL.len()..]
        .strip_suffix("\"\n}")
        .ok_or(ChecksumError::Missing)?;
    let body = format!("{}\n}}", &text[..at]);
    match sum == checksum_hex(body.as_bytes()) {
        true => Ok(()),
        false => Err(ChecksumError::Mismatch),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sealed_document_verifies_and_stays_json() {
        let text = seal_json(&serde_json::json!({"name": "a", "x": 1.5})).unwrap();
        verify_sealed_json(&text).unwrap();
        let value: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(value["x"], 1.5);
        assert_eq!(value["checksum"].as_str().unwrap().len(), 16);
    }

    #[test]
    fn n11_a_changed_byte_or_a_missing_checksum_is_found() {
        let text = seal_json(&serde_json::json!({"name": "a", "x": 1.5})).unwrap();
        let edited = text.replace("1.5", "2.5");
        assert_eq!(verify_sealed_json(&edited), Err(ChecksumError::Mismatch));
        let unsealed = serde_json::to_string_pretty(&serde_json::json!({"x": 1})).unwrap();
        assert_eq!(verify_sealed_json(&unsealed), Err(ChecksumError::Missing));
    }
}
