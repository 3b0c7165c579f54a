//! The one error type of the crate: a figure or table that could not be made or written.

use std::path::{Path, PathBuf};

/// A figure that could not be drawn, encoded or written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FigureError {
    /// The picture is too large to allocate.
    #[error("{}: a {width} x {height} px picture cannot be allocated", path.display())]
    TooLarge {
        /// The file the figure was for (`<memory>` when none was named yet).
        path: PathBuf,
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// The chart library or the PNG encoder failed.
    #[error("{}: {message}", path.display())]
    Draw {
        /// The file the figure was for (`<memory>` when none was named yet).
        path: PathBuf,
        /// What the drawing library or the encoder said.
        message: String,
    },
    /// Writing the file failed.
    #[error("writing {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the file system said.
        source: std::io::Error,
    },
    /// An animation was asked for with no frame.
    #[error("an animation needs at least one frame")]
    NoFrames,
    /// Frames of one animation differ in size.
    #[error("frame {index} is {got:?} px, the first frame {expected:?} px")]
    FrameSize {
        /// The frame, from 0.
        index: usize,
        /// Its size, pixels.
        got: (u32, u32),
        /// The first frame's size, pixels.
        expected: (u32, u32),
    },
    /// A grid image given a cell count other than width x height.
    #[error("a grid image of {width} x {height} cells given {cells} cells")]
    GridSize {
        /// Cells per row.
        width: usize,
        /// Rows.
        height: usize,
        /// Cells given.
        cells: usize,
    },
    /// A palette with no colour or more than 256, or a cell naming a colour beyond it.
    #[error("a palette of {len} colours (1 to 256) with cells up to index {max_index}")]
    Palette {
        /// Colours in the palette.
        len: usize,
        /// The largest index a cell names.
        max_index: u8,
    },
}

/// Where an in-memory figure is said to be before a file is named.
#[cfg_attr(not(feature = "draw"), allow(dead_code))]
pub(crate) const MEMORY: &str = "<memory>";

impl FigureError {
    /// A drawing or encoding error for an in-memory figure.
    #[cfg_attr(not(feature = "draw"), allow(dead_code))]
    pub(crate) fn draw(e: &dyn std::fmt::Display) -> Self {
        Self::Draw {
            path: PathBuf::from(MEMORY),
            message: e.to_string(),
        }
    }

    /// The same error, naming `path` as the file.
    #[must_use]
    pub fn for_file(self, path: &Path) -> Self {
        match self {
            Self::TooLarge { width, height, .. } => Self::TooLarge {
                path: path.to_path_buf(),
                width,
                height,
            },
            Self::Draw { message, .. } => Self::Draw {
                path: path.to_path_buf(),
                message,
            },
            other => other,
        }
    }
}

/// Writes `bytes` to `path`, naming the file on failure.
#[cfg_attr(not(feature = "draw"), allow(dead_code))]
pub(crate) fn write_file(path: &Path, bytes: impl AsRef<[u8]>) -> Result<(), FigureError> {
    std::fs::write(path, bytes).map_err(|source| FigureError::Io {
        path: path.to_path_buf(),
        source,
    })
}
