//! [`AtomicFile`]: a new version of a file that replaces the old one only when complete;
//! [`write_atomically`] for bytes held in memory.

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// A new version of a file, written to a temporary file in the same directory
/// (`.NAME.PID-N.tmp`) and renamed over the target by [`AtomicFile::commit`].
///
/// Until the commit the target is untouched; dropped without a commit (an error, a panic, an
/// early return), the temporary file is removed and the target left as it was. Readers of the
/// target see the old version or the new one, never a part.
///
/// ```
/// use std::io::Write;
/// # let dir = tempfile::tempdir()?;
/// # let path = dir.path().join("table.csv");
/// let mut file = neutrospline_io::AtomicFile::create(&path)?;
/// writeln!(file, "t,x")?;
/// file.commit()?;
/// # assert_eq!(std::fs::read_to_string(&path)?, "t,x\n");
/// # Ok::<(), std::io::Error>(())
/// ```
#[derive(Debug)]
pub struct AtomicFile {
    /// The file replaced (symbolic links resolved).
    target: PathBuf,
    /// The temporary file.
    temp: PathBuf,
    /// The open temporary file; `None` once closed.
    writer: Option<BufWriter<File>>,
    /// Whether the rename happened (nothing to remove then).
    committed: bool,
}

impl AtomicFile {
    /// Starts a new version of `path`. A symbolic link is followed: its target is replaced and
    /// the link kept.
    ///
    /// # Errors
    /// An empty path, a directory (`it is a directory`), a path without a file name, or the
    /// temporary file cannot be created (the directory does not exist, is not writable, ...).
    pub fn create(path: impl AsRef<Path>) -> io::Result<AtomicFile> {
        let path = path.as_ref();
        if path.as_os_str().is_empty() {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, "an empty path"));
        }
        let target = fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        if fs::metadata(&target).is_ok_and(|meta| meta.is_dir()) {
            return Err(io::Error::new(
                io::ErrorKind::IsADirectory,
                "it is a directory",
            ));
        }
        let file_name = target
            .file_name()
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file name"))?;
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let (temp, file) = create_temp(dir, file_name)?;
        Ok(AtomicFile {
            target,
            temp,
            writer: Some(BufWriter::new(file)),
            committed: false,
        })
    }

    /// The file that [`AtomicFile::commit`] replaces (symbolic links resolved).
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// The temporary file being written.
    pub fn temp_path(&self) -> &Path {
        &self.temp
    }

    fn writer(&mut self) -> io::Result<&mut BufWriter<File>> {
        self.writer
            .as_mut()
            .ok_or_else(|| io::Error::other("the temporary file is closed"))
    }

    /// Flushes what was written and syncs it to disk: after this only the rename of
    /// [`AtomicFile::commit`] remains (a caller can check for an interruption in between).
    ///
    /// # Errors
    /// A write or sync error.
    pub fn sync_all(&mut self) -> io::Result<()> {
        let writer = self.writer()?;
        writer.flush()?;
        writer.get_ref().sync_all()
    }

    /// Syncs the new version to disk, gives it the old file's permissions (best effort) and
    /// renames it over the target.
    ///
    /// # Errors
    /// A write, sync or rename error; the temporary file is then removed and the target left
    /// as it was.
    pub fn commit(mut self) -> io::Result<()> {
        self.sync_all()?;
        drop(self.writer.take());
        if let Ok(old) = fs::metadata(&self.target) {
            // Best effort: a new file keeps the mode of the one it replaces.
            let _ = fs::set_permissions(&self.temp, old.permissions());
        }
        fs::rename(&self.temp, &self.target)?;
        self.committed = true;
        Ok(())
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.writer()?.write(buf)
    }

    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        self.writer()?.write_all(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.writer()?.flush()
    }
}

impl Drop for AtomicFile {
    /// Removes the temporary file unless the rename happened.
    fn drop(&mut self) {
        drop(self.writer.take());
        if !self.committed {
            let _ = fs::remove_file(&self.temp);
        }
    }
}

/// Replaces the file at `path` by `bytes` through an [`AtomicFile`]: readers see the old
/// contents or the new, never a part, and on any error the old file is left as it was and the
/// temporary file removed. A symbolic link is followed: its target is replaced. (A writer that
/// streams what it computes, or must check for an interruption before the rename, uses
/// [`AtomicFile`] itself.)
///
/// # Errors
/// As [`AtomicFile::create`], a write error, and as [`AtomicFile::commit`].
pub fn write_atomically(path: impl AsRef<Path>, bytes: &[u8]) -> io::Result<()> {
    let mut file = AtomicFile::create(path)?;
    file.write_all(bytes)?;
    file.commit()
}

/// Creates `.NAME.PID-N.tmp` in `dir`, a name no other file has.
fn create_temp(dir: &Path, file_name: &std::ffi::OsStr) -> io::Result<(PathBuf, File)> {
    let mut attempt = 0u32;
    loop {
        let mut name = OsString::from(".");
        name.push(file_name);
        name.push(format!(".{}-{attempt}.tmp", std::process::id()));
        let candidate = dir.join(name);
        match OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&candidate)
        {
            Ok(file) => return Ok((candidate, file)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && attempt < 1000 => attempt += 1,
            Err(e) => return Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atomic_file_replaces_or_keeps() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        fs::write(&path, "old\n").unwrap();
        {
            let mut file = AtomicFile::create(&path).unwrap();
            writeln!(file, "partial").unwrap();
            file.sync_all().unwrap();
            assert!(file.temp_path().exists());
            // Dropped without a commit: an error happened.
        }
        assert_eq!(fs::read_to_string(&path).unwrap(), "old\n");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);

        let mut file = AtomicFile::create(&path).unwrap();
        writeln!(file, "new").unwrap();
        file.commit().unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new\n");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn write_atomically_replaces_or_keeps() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.glb");
        fs::write(&path, "old\n").unwrap();
        write_atomically(&path, b"new\0bytes").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new\0bytes");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
        // A directory is refused and left alone; nothing is left behind.
        let sub = dir.path().join("sub");
        fs::create_dir(&sub).unwrap();
        let e = write_atomically(&sub, b"x").unwrap_err();
        assert_eq!(e.to_string(), "it is a directory");
        assert!(sub.is_dir());
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
        assert_eq!(fs::read(&path).unwrap(), b"new\0bytes");
    }

    #[test]
    fn atomic_file_refuses_directories_and_missing_directories() {
        let dir = tempfile::tempdir().unwrap();
        let e = AtomicFile::create(dir.path()).unwrap_err();
        assert_eq!(e.to_string(), "it is a directory");
        assert!(AtomicFile::create(dir.path().join("no/such/out.csv")).is_err());
        assert_eq!(
            AtomicFile::create("").unwrap_err().to_string(),
            "an empty path"
        );
    }

    #[cfg(unix)]
    #[test]
    fn atomic_file_follows_symbolic_links() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.csv");
        let link = dir.path().join("link.csv");
        fs::write(&real, "old\n").unwrap();
        std::os::unix::fs::symlink(&real, &link).unwrap();
        let mut file = AtomicFile::create(&link).unwrap();
        writeln!(file, "new").unwrap();
        file.commit().unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read_to_string(&real).unwrap(), "new\n");
    }
}
