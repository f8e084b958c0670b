//! Reading a drawing (DXF, SVG) whole, within the file-size limit.

use std::io::Read;
use std::path::Path;

use neutrospline_io::{InputError, ReadError};

/// Reads the file at `path` whole, at most `limit` bytes (one more byte read at most: a file
/// may grow while it is read); a larger file is refused with its size limit. Returns the path
/// as messages show it and the bytes.
pub(crate) fn read_whole(path: &Path, limit: u64) -> Result<(String, Vec<u8>), ReadError> {
    let shown = path.display().to_string();
    let cannot = |error: std::io::Error| ReadError::Io {
        path: shown.clone(),
        error,
    };
    let file = std::fs::File::open(path).map_err(cannot)?;
    if file.metadata().map_err(cannot)?.is_dir() {
        return Err(ReadError::IsDirectory { path: shown });
    }
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > limit {
        return Err(InputError::new(&shown, None, None, too_large(limit)).into());
    }
    Ok((shown, bytes))
}

/// The message for a DXF or SVG file larger than `limit` bytes.
fn too_large(limit: u64) -> String {
    format!(
        "the file is larger than {limit} bytes, the limit for a file read whole (raise it with \
         --max-file-size or NEUTROSPLINE_MAX_FILE_SIZE)"
    )
}
