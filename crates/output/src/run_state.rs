//! The stored state of a resumable run (`wear`, `startup`, `fatigue`, tapered `simulate`):
//! after each completed unit of work (a wear period, a startup sample, a fatigue step) the
//! run stores what it needs to go on — its state and the rows of its tables
//! ([`crate::KeptRows`]) — in one file, replaced atomically; a run killed at any moment
//! leaves the last complete state, and `--resume` continues from it with nothing lost or
//! duplicated (the tables are cut back to the stored rows and their Parquet files rebuilt by
//! [`crate::TableWriter::resume`]).
//!
//! The file is sealed ([`rolldyn_numerics::sealed`]): the tag `RDYNRS` and the format version,
//! the [`fingerprint`] of the run's inputs, the state (CBOR, so that every `f64` reads back
//! bit for bit), and the FNV-1a checksum of everything before it. A damaged file, one of
//! another rolldyn format or one of a run with other inputs is refused, naming the file.

use crate::replace::replace_file_atomically;
use rolldyn_numerics::hash::fnv1a;
use rolldyn_numerics::sealed::{Kind, Unsealed};
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::path::{Path, PathBuf};

const KIND: Kind = Kind {
    tag: b"RDYNRS",
    version: b"01",
};

/// The fingerprint of a run's `inputs` (their exact text, e.g. the `Debug` text of the model
/// and settings, whose floats print as round-trip values) and of the rolldyn version.
pub fn fingerprint(inputs: &str) -> u64 {
    fnv1a(format!("rolldyn {}\n{inputs}", env!("CARGO_PKG_VERSION")).as_bytes())
}

/// A state file that could not be read or written; the message names the file.
#[derive(Debug, Clone, thiserror::Error)]
#[error("{0}")]
pub struct StateError(pub String);

/// The state file of one run: where it is and the fingerprint of the run's inputs.
#[derive(Debug, Clone)]
pub struct StateFile {
    path: PathBuf,
    fingerprint: u64,
}

impl StateFile {
    pub fn new(path: PathBuf, fingerprint: u64) -> Self {
        Self { path, fingerprint }
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The stored state; `None` when there is no file. Refuses a damaged file, one of another
    /// kind or format, and one of a run with other inputs.
    pub fn load<T: DeserializeOwned>(&self) -> Result<Option<T>, StateError> {
        let refuse = |reason: String| StateError(format!("{}: {reason}", self.path.display()));
        let bytes = match std::fs::read(&self.path) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            read => read.map_err(|e| refuse(e.to_string()))?,
        };
        let body = KIND.open(&bytes).map_err(|e| match e {
            Unsealed::Foreign => refuse("not the stored state of a rolldyn run".into()),
            Unsealed::Version(found) => refuse(format!(
                "format version {found}, this rolldyn reads version {} (written by another rolldyn: run again without --resume)",
                String::from_utf8_lossy(KIND.version)
            )),
            Unsealed::Damaged => refuse(e.to_string()),
        })?;
        let body = &body[KIND.header().len()..];
        let (stored, state) = body
            .split_first_chunk::<8>()
            .ok_or_else(|| refuse(Unsealed::Damaged.to_string()))?;
        if u64::from_le_bytes(*stored) != self.fingerprint {
            return Err(refuse(
                "the stored run had other inputs (model, operating point, settings or rolldyn version): resume with the inputs of that run, or run again without --resume".into(),
            ));
        }
        ciborium::from_reader(state)
            .map(Some)
            .map_err(|e| refuse(format!("the stored state cannot be read ({e})")))
    }

    /// Stores `state`, replacing the previous state atomically ([`replace_file_atomically`]):
    /// a run killed while storing leaves the previous one.
    pub fn store<T: Serialize>(&self, state: &T) -> Result<(), StateError> {
        let fail = |e: String| StateError(format!("cannot write {}: {e}", self.path.display()));
        let mut buf = KIND.header();
        buf.extend_from_slice(&self.fingerprint.to_le_bytes());
        ciborium::into_writer(state, &mut buf).map_err(|e| fail(e.to_string()))?;
        replace_file_atomically(&self.path, &KIND.seal(buf)).map_err(|e| StateError(e.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, PartialEq, serde::Serialize, serde::Deserialize)]
    struct Progress {
        done: Vec<f64>,
        count: u64,
    }

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rolldyn-state-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join("state")
    }

    #[test]
    fn a_state_reads_back_bit_for_bit_and_a_foreign_or_damaged_one_is_refused() {
        let path = scratch("round-trip");
        let file = StateFile::new(path.clone(), fingerprint("inputs"));
        assert!(file.load::<Progress>().unwrap().is_none());
        let state = Progress {
            done: vec![
                0.1 + 0.2,
                f64::NAN.copysign(1.0),
                5e-324,
                -0.0,
                f64::INFINITY,
            ],
            count: u64::MAX,
        };
        file.store(&state).unwrap();
        let back: Progress = file.load().unwrap().unwrap();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back.done), bits(&state.done));
        assert_eq!(back.count, state.count);
        let other = StateFile::new(path.clone(), fingerprint("other inputs"));
        let err = other.load::<Progress>().unwrap_err().to_string();
        assert!(err.contains("other inputs"), "{err}");
        let mut bytes = std::fs::read(&path).unwrap();
        bytes[20] ^= 1;
        std::fs::write(&path, &bytes).unwrap();
        let err = file.load::<Progress>().unwrap_err().to_string();
        assert!(err.contains("checksum") && err.contains("state"), "{err}");
        std::fs::remove_dir_all(path.parent().unwrap()).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_state_never_replaces_what_is_not_a_regular_file() {
        let path = scratch("symlink");
        let target = path.with_file_name("target");
        std::fs::write(&target, b"keep").unwrap();
        std::os::unix::fs::symlink(&target, &path).unwrap();
        let err = StateFile::new(path.clone(), 1).store(&1u8).unwrap_err();
        assert!(err.to_string().contains("not a regular file"), "{err}");
        assert_eq!(std::fs::read(&target).unwrap(), b"keep");
        std::fs::remove_dir_all(path.parent().unwrap()).unwrap();
    }
}
