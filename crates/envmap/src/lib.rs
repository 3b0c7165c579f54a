//! The world model of hyplan: three-zone grid maps.
//!
//! A [`GridMap`] holds one [`Zone`](hyplan_core::Zone) per cell (safe, high-risk,
//! forbidden, seed `000_9b224721fe327833.txt` section 4.1) and implements
//! [`Workspace`](hyplan_core::Workspace) with an exact, cell-level `segment_free`.
//!
//! # Contents
//!
//! - [`GridMap`]: the grid, its frame (origin at the lower-left corner, y up) and zones.
//! - [`GridMap::segment_cells`], [`GridMap::segment_free_cells`]: every cell a segment
//!   touches, corners included.
//!
//! # Example
//!
//! ```
//! use envmap::GridMap;
//! use hyplan_core::{Point2, Workspace};
//! let map = GridMap::from_ascii("
//!     ....
//!     .##.
//!     ....
//! ")?;
//! assert!(map.segment_free(Point2::new(0.5, 0.5), Point2::new(3.5, 0.5)));
//! assert!(!map.segment_free(Point2::new(0.5, 1.5), Point2::new(3.5, 1.5)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! - `image` (default): PNG / PGM / PPM decoding and encoding.
//! - `serde`: derives for the plain data types.

mod grid_map;
mod workspace;

pub use grid_map::{GridError, GridMap};
