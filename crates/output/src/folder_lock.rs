//! One writer per output folder: a run that writes a folder holds an advisory lock on
//! `DIR/.rolldyn.lock` until it ends. A second run on the same folder is refused at once with
//! the holder's process id and command line. The operating system releases the lock when the
//! holder ends in any way (also `kill -9`), so a stale lock file never blocks a new run; the
//! file itself stays in the folder. Runs that write disjoint files of one folder at the same
//! time (the shards of a sweep) share it ([`FolderLock::acquire_shared`]); a run that takes it
//! alone waits for none of them: it is refused while any holds it.

use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// File name of the lock in an output folder.
pub const LOCK_FILE: &str = ".rolldyn.lock";

/// Why an output folder could not be taken.
#[derive(Debug, thiserror::Error)]
pub enum FolderLockError {
    /// Another process (or another run of this one) writes the folder.
    #[error("{}: being written by another rolldyn run ({holder}); wait for it to end or choose another output folder", dir.display())]
    Busy { dir: PathBuf, holder: String },
    #[error("cannot create output folder {}: {source}", dir.display())]
    Io {
        dir: PathBuf,
        source: std::io::Error,
    },
}

/// The lock of an output folder, held until dropped.
#[derive(Debug)]
pub struct FolderLock {
    dir: PathBuf,
    _file: File,
}

impl FolderLock {
    /// Creates `dir` (and its parents) when missing and locks it for this run alone; refuses
    /// ([`FolderLockError::Busy`]) a folder another run holds.
    pub fn acquire(dir: &Path) -> Result<Self, FolderLockError> {
        Self::take(dir, false)
    }

    /// [`FolderLock::acquire`] for a run that shares the folder with runs writing other files
    /// of it (the shards of a sweep); refused while a run holds it alone.
    pub fn acquire_shared(dir: &Path) -> Result<Self, FolderLockError> {
        Self::take(dir, true)
    }

    fn take(dir: &Path, shared: bool) -> Result<Self, FolderLockError> {
        let io = |source| FolderLockError::Io {
            dir: dir.to_path_buf(),
            source,
        };
        std::fs::create_dir_all(dir).map_err(io)?;
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(dir.join(LOCK_FILE))
            .map_err(io)?;
        let locked = match shared {
            true => file.try_lock_shared(),
            false => file.try_lock(),
        };
        match locked {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                let mut holder = String::new();
                let _ = file.read_to_string(&mut holder);
                let holder = match holder.trim() {
                    "" => "holder unknown".to_string(),
                    text => text.lines().collect::<Vec<_>>().join("; "),
                };
                return Err(FolderLockError::Busy {
                    dir: dir.to_path_buf(),
                    holder,
                });
            }
            Err(TryLockError::Error(e)) => return Err(io(e)),
        }
        let command: Vec<String> = std::env::args().collect();
        let line = format!("pid {}: {}\n", std::process::id(), command.join(" "));
        // a sole holder replaces the holders' lines, a sharing one adds its own (one write)
        let noted = match shared {
            true => file.seek(std::io::SeekFrom::End(0)).map(|_| ()),
            false => file.set_len(0).and_then(|()| file.rewind()),
        };
        noted
            .and_then(|()| file.write_all(line.as_bytes()))
            .map_err(io)?;
        Ok(Self {
            dir: dir.to_path_buf(),
            _file: file,
        })
    }

    /// The locked folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}

impl std::ops::Deref for FolderLock {
    type Target = Path;

    /// The locked folder.
    fn deref(&self) -> &Path {
        &self.dir
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn n4_a_second_writer_is_refused_until_the_first_ends() {
        let dir = std::env::temp_dir().join(format!("rolldyn-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let first = FolderLock::acquire(&dir.join("out")).unwrap();
        let error = FolderLock::acquire(&dir.join("out")).unwrap_err();
        let text = error.to_string();
        assert!(matches!(error, FolderLockError::Busy { .. }), "{text}");
        assert!(
            text.contains(&format!("pid {}", std::process::id())),
            "{text}"
        );
        drop(first);
        let shard = FolderLock::acquire_shared(&dir.join("out")).unwrap();
        let other_shard = FolderLock::acquire_shared(&dir.join("out")).unwrap();
        FolderLock::acquire(&dir.join("out")).unwrap_err();
        drop((shard, other_shard));
        FolderLock::acquire(&dir.join("out")).unwrap();
        std::fs::remove_dir_all(dir).unwrap();
    }
}
