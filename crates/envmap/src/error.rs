//! `MapError`: everything that can go wrong reading, building or writing a map.

use std::path::PathBuf;

use crate::GridError;

/// Why a map could not be loaded, built or written.
///
/// Every variant that comes from a file names the file, and where it can the line or field
/// and the offending value. Underlying io, image and YAML errors are kept as the
/// [`source`](std::error::Error::source), so `{:#}` in `anyhow` prints the whole chain.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MapError {
    /// The file could not be read.
    #[error("cannot read {}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The io error.
        #[source]
        source: std::io::Error,
    },
    /// The file could not be written.
    #[error("cannot write {}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// The io error.
        #[source]
        source: std::io::Error,
    },
    /// The file is not an image the `image` crate can decode (PNG, PGM, PPM, PBM, PAM).
    #[cfg(feature = "image")]
    #[error("{}: not a readable image (PNG, PGM or PPM)", path.display())]
    Decode {
        /// The file.
        path: PathBuf,
        /// The decoder's error.
        #[source]
        source: image::ImageError,
    },
    /// An image could not be encoded.
    #[cfg(feature = "image")]
    #[error("cannot write image {}", path.display())]
    Encode {
        /// The file.
        path: PathBuf,
        /// The encoder's error.
        #[source]
        source: image::ImageError,
    },
    /// Reading or writing images needs the `image` feature of `envmap`.
    #[error("{}: images need the `image` feature of envmap", path.display())]
    NoImageSupport {
        /// The file.
        path: PathBuf,
    },
    /// Reading ROS 2 bags needs the `mcap` feature of `envmap`.
    #[error("{}: ROS 2 bags (MCAP) need the `mcap` feature of envmap", path.display())]
    NoMcapSupport {
        /// The file.
        path: PathBuf,
    },
    /// A ROS 2 bag (MCAP) could not be read as a map; the error names the file, the topic
    /// and the field.
    #[cfg(feature = "mcap")]
    #[error(transparent)]
    Bag(Box<bag::BagError>),
    /// The image has no pixels.
    #[error("{}: image is {width} x {height} pixels, it has no pixels", path.display())]
    EmptyImage {
        /// The file.
        path: PathBuf,
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
    },
    /// A text map file (MovingAI `.map`) is malformed at a line.
    #[error("{}:{line}: {reason}", path.display())]
    Line {
        /// The file.
        path: PathBuf,
        /// 1-based line number in the file.
        line: usize,
        /// What is wrong, with the offending value.
        reason: String,
    },
    /// A YAML file does not parse.
    #[error("{}: invalid YAML", path.display())]
    Yaml {
        /// The file.
        path: PathBuf,
        /// The parser's error (it carries the line and column).
        #[source]
        source: serde_yaml_ng::Error,
    },
    /// A field of a metadata file (ROS map YAML) is missing, of the wrong type or out of range.
    #[error("{}: field `{field}` = {value}: {reason}", path.display())]
    Field {
        /// The file.
        path: PathBuf,
        /// The field name.
        field: &'static str,
        /// The offending value as written, or `missing`.
        value: String,
        /// What is expected.
        reason: String,
    },
    /// A parameter (threshold, radius, ...) is out of range.
    #[error("invalid parameter `{name}` = {value}: {reason}")]
    InvalidParameter {
        /// The parameter name.
        name: &'static str,
        /// The offending value.
        value: String,
        /// What is expected.
        reason: String,
    },
    /// The map has more cells than the memory limit allows; refused before its cells are
    /// read or allocated. Raise the limit with [`LoadOptions::max_cells`](crate::LoadOptions)
    /// (`--max-cells` in `hyplan`).
    #[error(
        "{}: the map is {width} x {height} = {cells} cells, above the memory limit of {limit} cells",
        path.display(),
        cells = (*width as u128) * (*height as u128)
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Columns (pixels or cells) the file declares.
        width: usize,
        /// Rows the file declares.
        height: usize,
        /// The limit, cells.
        limit: usize,
    },
    /// The grid built from a file is invalid (size overflow and the like).
    #[error("{}: invalid map", path.display())]
    Grid {
        /// The file.
        path: PathBuf,
        /// The grid error.
        #[source]
        source: GridError,
    },
}

#[cfg(feature = "mcap")]
impl From<bag::BagError> for MapError {
    fn from(e: bag::BagError) -> Self {
        // Boxed: a bag's errors carry the topic and the schema names, and every result
        // of the workspace's loaders carries a MapError.
        Self::Bag(Box::new(e))
    }
}
