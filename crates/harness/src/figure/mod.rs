//! Figures in the papers' conventions: the world figure ([`Scene`]: zones in seed 000's
//! colours, rectangles, trees, raw path, smoothed curve) as PNG or SVG, and charts of
//! metric distributions (box plots, success bars) as SVG.

use std::path::{Path, PathBuf};

mod chart;
mod scene;

pub use chart::{chart_box, chart_metrics, chart_success};
pub use scene::{CURVE_COLOUR, Mark, PATH_COLOUR, START_COLOUR, Scene, TREE_COLOURS, draw_world};

/// A figure that could not be drawn or written.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// The picture is too large to allocate.
    #[error("{}: a {width} x {height} px picture cannot be allocated", path.display())]
    TooLarge {
        /// The file the figure was for.
        path: PathBuf,
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// Drawing or writing the file failed.
    #[error("{}: {message}", path.display())]
    Draw {
        /// The file.
        path: PathBuf,
        /// What the drawing library or the file system said.
        message: String,
    },
}

impl FigureError {
    pub(crate) fn draw(path: &Path, e: &dyn std::fmt::Display) -> Self {
        Self::Draw {
            path: path.to_path_buf(),
            message: e.to_string(),
        }
    }

    /// The same error, naming `path` as the file.
    pub(crate) fn for_file(self, path: &Path) -> Self {
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
        }
    }
}
