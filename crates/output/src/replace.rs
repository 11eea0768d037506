//! Replacing a file rolldyn writes again and again (a checkpoint, a stored result, a manifest)
//! through a temporary file renamed over it, so that a process killed while writing leaves the
//! previous version intact. Only a regular file (or nothing) is replaced: a symbolic link, a
//! device, a folder or a named pipe at the target is refused, never turned into a regular file.

use std::fs::OpenOptions;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Suffix of the temporary file written beside the target before the rename, after the
/// process id (`run.json.4711.partial`), so that processes sharing a folder (the shards of a
/// sweep, each writing `run.json`) never write one temporary file.
pub const PARTIAL_SUFFIX: &str = ".partial";

/// Why a file could not be replaced.
#[derive(Debug, thiserror::Error)]
pub enum ReplaceError {
    /// The target exists and is not a regular file (`what`: "a symbolic link", "a character
    /// device", …).
    #[error("{} is {what}, not a regular file: rolldyn replaces only regular files", path.display())]
    NotRegularFile { path: PathBuf, what: &'static str },
    #[error("cannot write {}: {source}", path.display())]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// What the file system entry at `path` is, when it is not a regular file: `Ok(None)` for a
/// regular file or a missing path.
fn foreign_kind(path: &Path) -> std::io::Result<Option<&'static str>> {
    let kind = match std::fs::symlink_metadata(path) {
        Ok(metadata) => metadata.file_type(),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e),
    };
    if kind.is_file() {
        return Ok(None);
    }
    if kind.is_symlink() {
        return Ok(Some("a symbolic link"));
    }
    if kind.is_dir() {
        return Ok(Some("a folder"));
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_char_device() {
            return Ok(Some("a character device"));
        }
        if kind.is_block_device() {
            return Ok(Some("a block device"));
        }
        if kind.is_fifo() {
            return Ok(Some("a named pipe"));
        }
        if kind.is_socket() {
            return Ok(Some("a socket"));
        }
    }
    Ok(Some("not a regular file"))
}

/// Checks that [`replace_file_atomically`] may write `path`: it is a regular file or does not
/// exist. Call it before a long run so that a wrong path is refused at the start.
pub fn ensure_replaceable(path: &Path) -> Result<(), ReplaceError> {
    match foreign_kind(path) {
        Ok(None) => Ok(()),
        Ok(Some(what)) => Err(ReplaceError::NotRegularFile {
            path: path.to_path_buf(),
            what,
        }),
        Err(source) => Err(ReplaceError::Io {
            path: path.to_path_buf(),
            source,
        }),
    }
}

/// Writes `bytes` to `path` through `path.<pid>.partial` (created afresh, synced) renamed over
/// `path`: a reader sees the old or the new content, never a part. Refuses a `path` that exists
/// and is not a regular file ([`ReplaceError::NotRegularFile`]).
pub fn replace_file_atomically(path: &Path, bytes: &[u8]) -> Result<(), ReplaceError> {
    ensure_replaceable(path)?;
    let mut partial = path.as_os_str().to_owned();
    partial.push(format!(".{}{PARTIAL_SUFFIX}", std::process::id()));
    let partial = PathBuf::from(partial);
    let io = |source| ReplaceError::Io {
        path: path.to_path_buf(),
        source,
    };
    // a leftover of a killed run (or anything planted there) goes: `create_new` below then
    // never follows a symbolic link
    match std::fs::remove_file(&partial) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(io(e)),
        _ => {}
    }
    let mut file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&partial)
        .map_err(io)?;
    file.write_all(bytes)
        .and_then(|()| file.sync_all())
        .and_then(|()| std::fs::rename(&partial, path))
        .map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rolldyn-replace-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn replaces_a_regular_file_and_creates_a_missing_one() {
        let dir = scratch("regular");
        let path = dir.join("state.bin");
        replace_file_atomically(&path, b"one").unwrap();
        replace_file_atomically(&path, b"two").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        assert_eq!(
            std::fs::read_dir(&dir).unwrap().count(),
            1,
            "no temporary file left"
        );
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn n2_refuses_a_symbolic_link_and_leaves_it_and_its_target() {
        let dir = scratch("symlink");
        let target = dir.join("precious.txt");
        std::fs::write(&target, "keep").unwrap();
        let link = dir.join("checkpoint.bin");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let error = replace_file_atomically(&link, b"new").unwrap_err();
        assert!(error.to_string().contains("a symbolic link"), "{error}");
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn n2_refuses_a_device_and_a_folder() {
        let error = ensure_replaceable(Path::new("/dev/null")).unwrap_err();
        assert!(error.to_string().contains("a character device"), "{error}");
        let dir = scratch("folder");
        let error = replace_file_atomically(&dir, b"x").unwrap_err();
        assert!(error.to_string().contains("a folder"), "{error}");
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_planted_partial_link_is_not_followed() {
        let dir = scratch("partial");
        let target = dir.join("precious.txt");
        std::fs::write(&target, "keep").unwrap();
        let partial = format!("out.json.{}.partial", std::process::id());
        std::os::unix::fs::symlink(&target, dir.join(partial)).unwrap();
        replace_file_atomically(&dir.join("out.json"), b"{}").unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
        assert_eq!(std::fs::read(dir.join("out.json")).unwrap(), b"{}");
        std::fs::remove_dir_all(dir).unwrap();
    }
}
